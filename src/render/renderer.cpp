#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/gl_api.h"
#include "render/gpu.h"
#include "render/shader.h"
#include "render/tube_cache.h"

namespace coilsim::render {

std::optional<ViewMode> parseViewMode(std::string_view name) {
  if (name == "3d") return ViewMode::Shaded;
  if (name == "xray") return ViewMode::XRay;
  if (name == "biplane") return ViewMode::Biplane;
  return std::nullopt;
}

const char* viewModeName(ViewMode mode) {
  switch (mode) {
    case ViewMode::Shaded: return "3d";
    case ViewMode::XRay: return "xray";
    case ViewMode::Biplane: return "biplane";
  }
  return "3d";
}

namespace {

// Gap between the two biplane images, pixels.
constexpr int kBiplaneGap = 2;

void biplaneHalves(int width, int& left, int& right) {
  left = std::max((width - kBiplaneGap) / 2, 1);
  right = std::max(width - kBiplaneGap - left, 1);
}

void setMatrices(const Program& p, const Camera& camera, double aspect) {
  const Mat4f view = camera.view(), projection = camera.projection(aspect);
  glUniformMatrix4fv(p.uniform("uView"), 1, GL_FALSE, view.data());
  glUniformMatrix4fv(p.uniform("uProjection"), 1, GL_FALSE, projection.data());
}

// The X-ray image's pixels per frame pixel (XRaySettings::resolutionScale).
double xrayScale(const XRaySettings& x, int viewHeight) {
  return x.resolutionScale > 0 ? std::min(double(x.resolutionScale), 1.0) : (viewHeight > 480 ? 0.5 : 1.0);
}

// Pixels per metre at a tube where it is nearest the eye, in the views of
// `mode` (biplane: the nearer of the two projections), `height` pixels tall.
TubeCache::PixelScale pixelScale(const Camera& camera, const RenderSettings& s, int height) {
  std::vector<Camera> eyes{camera};
  if (s.mode == ViewMode::Biplane) eyes.push_back(lateralView(camera));
  // An X-ray pixel is a line integral across the wire, which a polygon's
  // flat sides change more than they move a shaded edge: its detail is
  // chosen as for an image of twice the pixels.
  const double pixels = s.mode == ViewMode::Shaded ? double(height) : 2.0 * height * xrayScale(s.xray, height);
  const double perDepth = pixels / (2.0 * std::tan(0.5 * camera.fovY));
  return [eyes, perDepth](const DrawTube& t) {
    double nearest = 1e300;
    for (const Camera& c : eyes) {
      const Vec3 eye = c.eye(), f = c.forward();
      for (const Vec3& p : t.centre)
        if (p.allFinite()) nearest = std::min(nearest, (p - eye).dot(f) - t.radius);
    }
    // Behind or at the eye: no size to go by, full detail.
    return nearest > 1e-9 && nearest < 1e300 ? perDepth / nearest : 0.0;
  };
}

}  // namespace

void fitCamera(Camera& camera, const Bounds& bounds, ViewMode mode, int width, int height) {
  if (mode != ViewMode::Biplane) {
    camera.fit(bounds, double(width) / std::max(height, 1));
    return;
  }
  int left = 0, right = 0;
  biplaneHalves(width, left, right);
  const double aspect = double(std::min(left, right)) / std::max(height, 1);
  Camera lateral = lateralView(camera);
  camera.fit(bounds, aspect);
  lateral.fit(bounds, aspect);
  camera.distance = std::max(camera.distance, lateral.distance);
  camera.updateClipPlanes();
}

struct Renderer::Impl {
  Program shaded, accumulate, background, composite;
  GpuMesh tubes[3];  // by role: coil, catheter, wire
  GpuMesh points;
  GpuMesh meshes;
  GLuint emptyVao = 0;
  RenderTarget scene;   // multisampled colour + depth for the 3D view
  RenderTarget frame;   // RGBA8: the finished image, overlays go on top
  RenderTarget xray;    // RGBA32F line integrals
  RenderTarget xrayImage;  // RGBA8: the X-ray image at reduced resolution, scaled up into the frame
  int samples = -1;     // of `scene` as created
  bool samplesFailed = false;
  std::vector<ViewportInfo> viewports;

  TriangleMesh scratch;
  TubeCache tubeCache;
  // The vessels' draw order is kept while the camera and the meshes stay.
  bool sortedValid = false;
  Vec3 sortedEye = Vec3::Zero(), sortedForward = Vec3::Zero();
  // The vessel meshes change rarely: rebuild only when their data does.
  std::vector<DrawMesh> meshSource;
  bool meshesBuilt = false;
  TriangleMesh meshGeometry;
  std::vector<Eigen::Vector3f> centroids;  // (ntriangle)
  std::vector<std::pair<float, std::uint32_t>> order;
  std::vector<std::uint32_t> sorted;

  bool ensureTargets(int w, int h, int wantSamples, std::string& error);
  void uploadGeometry(const DrawData& data, const RenderSettings& s, const TubeCache::PixelScale& scale);
  void uploadMeshes(const DrawData& data);
  void sortMeshes(const Camera& camera, bool keep);
  void drawShaded(const ViewportInfo& vp, const RenderSettings& s);
  void drawXRay(const ViewportInfo& vp, const RenderSettings& s);
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}

Renderer::~Renderer() {
  if (impl_ && impl_->emptyVao && gl.DeleteVertexArrays) glDeleteVertexArrays(1, &impl_->emptyVao);
}

bool Renderer::init(std::string& error) {
  if (!gl.CreateProgram) {
    error = "the renderer needs a current OpenGL context (create a backend first)";
    return false;
  }
  Impl& r = *impl_;
  if (!r.shaded.build("mesh.vert.glsl", "shaded.frag.glsl", error)) return false;
  if (!r.accumulate.build("mesh.vert.glsl", "xray_accum.frag.glsl", error)) return false;
  if (!r.background.build("fullscreen.vert.glsl", "background.frag.glsl", error)) return false;
  if (!r.composite.build("fullscreen.vert.glsl", "xray_composite.frag.glsl", error)) return false;
  glGenVertexArrays(1, &r.emptyVao);
  return true;
}

bool Renderer::Impl::ensureTargets(int w, int h, int wantSamples, std::string& error) {
  if (samplesFailed) wantSamples = 0;
  if (frame.width() != w || frame.height() != h || !frame.framebuffer()) {
    if (!frame.create(w, h, GL_RGBA8, 0, false, error)) return false;
    if (!xray.create(w, h, GL_RGBA32F, 0, false, error)) {
      error = "X-ray view: " + error + " (32-bit float render targets are needed)";
      return false;
    }
    if (!xrayImage.create(w, h, GL_RGBA8, 0, false, error)) return false;
    samples = -1;
  }
  if (samples != wantSamples || scene.width() != w || scene.height() != h) {
    if (!scene.create(w, h, GL_RGBA8, wantSamples, true, error)) {
      if (wantSamples == 0) return false;
      // Some drivers lack multisampled targets: draw without anti-aliasing.
      samplesFailed = true;
      wantSamples = 0;
      if (!scene.create(w, h, GL_RGBA8, 0, true, error)) return false;
    }
    samples = wantSamples;
  }
  return true;
}

void Renderer::Impl::uploadGeometry(const DrawData& data, const RenderSettings& s, const TubeCache::PixelScale& scale) {
  tubeCache.update(data.tubes, s.tube, s.tubeDetailBySize ? scale : TubeCache::PixelScale(), s.keepGeometry);
  for (int role = 0; role < kTubeRoles; ++role)
    if (tubeCache.changed(role)) tubes[role].upload(tubeCache.mesh(role));
  scratch.clear();
  if (s.drawPoints && s.mode == ViewMode::Shaded && !data.points.empty()) {
    double radius = s.pointRadius;
    if (!(radius > 0)) {
      for (const DrawTube& t : data.tubes) radius = std::max(radius, 1.6 * t.radius);
      if (!(radius > 0)) radius = 0.01 * std::max(boundsOf(data).radius(), 1e-6);
    }
    // Markers as fine as their size on screen needs (a dense packing has
    // hundreds): the sides tubeDetail gives a tube of their radius.
    int slices = 10, arrowSides = 10;
    if (s.tubeDetailBySize && scale) {
      DrawTube at;
      at.radius = radius;
      for (const DrawPoint& p : data.points) at.centre.push_back(p.position);
      const double perMetre = scale(at);
      if (perMetre > 0) {
        slices = tubeDetail(TubeOptions{10, 1, 1.0, 0}, perMetre * radius, 0).sides;
        arrowSides = tubeDetail(TubeOptions{10, 1, 1.0, 0}, perMetre * 0.35 * radius, 0).sides;
      }
    }
    for (const DrawPoint& p : data.points) {
      appendSphere(p.position, radius, p.colour, scratch, slices, std::max(3, (slices + 1) / 2));
      appendArrow(p.position, p.vector, 0.35 * radius, p.colour, scratch, arrowSides);
    }
  }
  points.upload(scratch);
  uploadMeshes(data);
}

void Renderer::Impl::uploadMeshes(const DrawData& data) {
  bool same = meshSource.size() == data.meshes.size();
  for (size_t k = 0; same && k < meshSource.size(); ++k) {
    const DrawMesh &a = meshSource[k], &b = data.meshes[k];
    same = a.colour == b.colour && a.vertices == b.vertices && a.triangles == b.triangles;
  }
  if (same && meshesBuilt) return;
  meshesBuilt = true;
  sortedValid = false;
  meshSource = data.meshes;
  meshGeometry.clear();
  for (const DrawMesh& m : data.meshes) appendMesh(m, meshGeometry);
  const size_t nt = meshGeometry.indices.size() / 3;
  centroids.resize(nt);
  for (size_t t = 0; t < nt; ++t) {
    Eigen::Vector3f c = Eigen::Vector3f::Zero();
    for (int k = 0; k < 3; ++k) c += Eigen::Map<const Eigen::Vector3f>(meshGeometry.vertices[meshGeometry.indices[3 * t + k]].position);
    centroids[t] = c / 3.0f;
  }
  meshes.upload(meshGeometry);
}

void Renderer::Impl::sortMeshes(const Camera& camera, bool keep) {
  // Back to front by centroid distance along the view direction, so that
  // alpha blending composites the far side of a vessel before the near side.
  const size_t nt = centroids.size();
  if (!nt) return;
  if (keep && sortedValid && sortedEye == camera.eye() && sortedForward == camera.forward()) return;
  sortedValid = true;
  sortedEye = camera.eye();
  sortedForward = camera.forward();
  const Eigen::Vector3f eye = camera.eye().cast<float>(), f = camera.forward().cast<float>();
  order.resize(nt);
  for (size_t t = 0; t < nt; ++t) order[t] = {(centroids[t] - eye).dot(f), std::uint32_t(t)};
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  sorted.resize(3 * nt);
  for (size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) sorted[3 * t + k] = meshGeometry.indices[3 * order[t].second + k];
  meshes.uploadIndices(sorted);
}

void Renderer::Impl::drawShaded(const ViewportInfo& vp, const RenderSettings& s) {
  const Camera& camera = vp.camera;
  glBindFramebuffer(GL_FRAMEBUFFER, scene.framebuffer());
  glViewport(vp.x, vp.y, vp.width, vp.height);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  glDisable(GL_DEPTH_TEST);
  background.use();
  glUniform3f(background.uniform("uTop"), s.backgroundTop[0], s.backgroundTop[1], s.backgroundTop[2]);
  glUniform3f(background.uniform("uBottom"), s.backgroundBottom[0], s.backgroundBottom[1], s.backgroundBottom[2]);
  glBindVertexArray(emptyVao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  shaded.use();
  setMatrices(shaded, camera, double(vp.width) / vp.height);
  glUniform1f(shaded.uniform("uOpacity"), 1.0f);
  glUniform1i(shaded.uniform("uSilhouetteAlpha"), 0);
  // Platinum is bright and tight, the polymer catheter soft, the wire between.
  const float specular[3] = {0.85f, 0.3f, 0.6f}, shininess[3] = {70.0f, 24.0f, 50.0f};
  for (int role = 0; role < 3; ++role) {
    glUniform1f(shaded.uniform("uSpecular"), specular[role]);
    glUniform1f(shaded.uniform("uShininess"), shininess[role]);
    tubes[role].draw();
  }
  glUniform1f(shaded.uniform("uSpecular"), 0.4f);
  glUniform1f(shaded.uniform("uShininess"), 30.0f);
  points.draw();

  if (s.drawMeshes && !meshes.empty()) {
    sortMeshes(camera, s.keepGeometry);
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glUniform1f(shaded.uniform("uSpecular"), 0.25f);
    glUniform1f(shaded.uniform("uShininess"), 40.0f);
    glUniform1i(shaded.uniform("uSilhouetteAlpha"), 1);
    meshes.draw();
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
  }
  glDisable(GL_CULL_FACE);
  glDisable(GL_DEPTH_TEST);

  // Resolve the samples into the frame.
  glBindFramebuffer(GL_READ_FRAMEBUFFER, scene.framebuffer());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.framebuffer());
  const int x1 = vp.x + vp.width, y1 = vp.y + vp.height;
  glBlitFramebuffer(vp.x, vp.y, x1, y1, vp.x, vp.y, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::Impl::drawXRay(const ViewportInfo& view, const RenderSettings& s) {
  const XRaySettings& x = s.xray;
  // The X-ray image may have fewer pixels than its place in the frame.
  const double k = xrayScale(x, view.height);
  ViewportInfo vp = view;
  if (k < 1) {
    vp.x = int(view.x * k);
    vp.y = int(view.y * k);
    vp.width = std::max(int(view.width * k), 1);
    vp.height = std::max(int(view.height * k), 1);
  }
  // Pass 1: signed distances of every surface into the float target.
  glBindFramebuffer(GL_FRAMEBUFFER, xray.framebuffer());
  glViewport(vp.x, vp.y, vp.width, vp.height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(vp.x, vp.y, vp.width, vp.height);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendEquation(GL_FUNC_ADD);
  glBlendFunc(GL_ONE, GL_ONE);
  accumulate.use();
  setMatrices(accumulate, vp.camera, double(vp.width) / vp.height);
  glUniform1f(accumulate.uniform("uReference"), float(vp.camera.distance));
  const GLint mu = accumulate.uniform("uMu");
  glUniform4f(mu, x.muMetal, 0, 0, 0);
  tubes[0].draw();
  glUniform4f(mu, 0, x.muCatheter, 0, 0);
  tubes[1].draw();
  glUniform4f(mu, x.muWire, 0, 0, 0);
  tubes[2].draw();
  if (s.drawMeshes) {
    glUniform4f(mu, 0, 0, x.muContrast, 0);
    meshes.draw();
  }
  glDisable(GL_BLEND);

  // Pass 2: Beer-Lambert into the frame (or the reduced image).
  glBindFramebuffer(GL_FRAMEBUFFER, k < 1 ? xrayImage.framebuffer() : frame.framebuffer());
  composite.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, xray.texture());
  // Bilinear taps do the blur (see xray_composite.frag.glsl).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glUniform1i(composite.uniform("uAccum"), 0);
  glUniform4f(composite.uniform("uViewport"), float(vp.x), float(vp.y), float(vp.width), float(vp.height));
  glUniform3f(composite.uniform("uWeight"), 1.0f, 1.0f, 1.0f);
  glUniform1f(composite.uniform("uOutline"), x.outline);
  glUniform1f(composite.uniform("uBrightness"), x.brightness);
  glUniform1f(composite.uniform("uNoise"), x.noise);
  glUniform1f(composite.uniform("uVignette"), x.vignette);
  glBindVertexArray(emptyVao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindTexture(GL_TEXTURE_2D, 0);
  glDisable(GL_SCISSOR_TEST);
  if (k < 1) {
    // Scaling up with bilinear filtering; a blit is cheap even in software.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, xrayImage.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.framebuffer());
    glBlitFramebuffer(vp.x, vp.y, vp.x + vp.width, vp.y + vp.height, view.x, view.y, view.x + view.width,
                      view.y + view.height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool Renderer::render(const DrawData& data, const Camera& camera, const RenderSettings& settings, int width,
                      int height, std::string& error) {
  return render(data, camera, settings, width, height, Rect{0, 0, width, height}, error);
}

bool Renderer::render(const DrawData& data, const Camera& camera, const RenderSettings& settings, int width,
                      int height, const Rect& area, std::string& error) {
  Impl& r = *impl_;
  if (!r.emptyVao) {
    error = "the renderer was not initialised";
    return false;
  }
  if (width <= 0 || height <= 0) {
    error = "frame size " + std::to_string(width) + "x" + std::to_string(height) + " is empty";
    return false;
  }
  // The scene area, clipped to the frame; at least a pixel.
  Rect a = area;
  a.x = std::clamp(a.x, 0, width - 1);
  a.y = std::clamp(a.y, 0, height - 1);
  a.width = std::clamp(a.width, 1, width - a.x);
  a.height = std::clamp(a.height, 1, height - a.y);
  if (!r.ensureTargets(width, height, std::max(settings.samples, 0), error)) return false;
  r.uploadGeometry(data, settings, pixelScale(camera, settings, a.height));

  // Outside the scene area (under a side panel) the frame is plain.
  glBindFramebuffer(GL_FRAMEBUFFER, r.frame.framebuffer());
  glViewport(0, 0, width, height);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(settings.sideColour[0], settings.sideColour[1], settings.sideColour[2], 1);
  glClear(GL_COLOR_BUFFER_BIT);

  r.viewports.clear();
  switch (settings.mode) {
    case ViewMode::Shaded:
      r.viewports.push_back({a.x, a.y, a.width, a.height, "3D", camera});
      r.drawShaded(r.viewports.back(), settings);
      break;
    case ViewMode::XRay:
      r.viewports.push_back({a.x, a.y, a.width, a.height, "AP", camera});
      r.drawXRay(r.viewports.back(), settings);
      break;
    case ViewMode::Biplane: {
      int left = 0, right = 0;
      biplaneHalves(a.width, left, right);
      // The gap between the two images stays black.
      glBindFramebuffer(GL_FRAMEBUFFER, r.frame.framebuffer());
      glEnable(GL_SCISSOR_TEST);
      glScissor(a.x, a.y, a.width, a.height);
      glClearColor(0, 0, 0, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      glDisable(GL_SCISSOR_TEST);
      r.viewports.push_back({a.x, a.y, left, a.height, "AP", camera});
      r.viewports.push_back({a.x + a.width - right, a.y, right, a.height, "LAT", lateralView(camera)});
      for (const ViewportInfo& vp : r.viewports) r.drawXRay(vp, settings);
      break;
    }
  }
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "OpenGL error 0x%x while drawing", unsigned(e));
    error = buf;
    return false;
  }
  return true;
}

const std::vector<ViewportInfo>& Renderer::viewports() const { return impl_->viewports; }
int Renderer::width() const { return impl_->frame.width(); }
int Renderer::height() const { return impl_->frame.height(); }

void Renderer::bindFrame() {
  glBindFramebuffer(GL_FRAMEBUFFER, impl_->frame.framebuffer());
  glViewport(0, 0, impl_->frame.width(), impl_->frame.height());
}

namespace {

// Reads the bound read framebuffer into `out`, flipping rows (GL counts from the bottom).
bool readPixels(int width, int height, Image& out) {
  out.width = width;
  out.height = height;
  out.pixels.resize(size_t(width) * height * 4);
  std::vector<std::uint8_t> raw(out.pixels.size());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
  const size_t row = size_t(width) * 4;
  for (int y = 0; y < height; ++y)
    std::copy_n(raw.data() + size_t(height - 1 - y) * row, row, out.pixels.data() + size_t(y) * row);
  for (size_t i = 3; i < out.pixels.size(); i += 4) out.pixels[i] = 255;  // screenshots are opaque
  return glGetError() == GL_NO_ERROR;
}

}  // namespace

bool Renderer::readFrame(Image& out) {
  const RenderTarget& f = impl_->frame;
  if (!f.framebuffer()) return false;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, f.framebuffer());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  const bool ok = readPixels(f.width(), f.height(), out);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return ok;
}

bool Renderer::readWindowPixels(int width, int height, Image& out) {
  if (width <= 0 || height <= 0) return false;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  return readPixels(width, height, out);
}

void Renderer::present(int framebufferWidth, int framebufferHeight) {
  const RenderTarget& f = impl_->frame;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, f.framebuffer());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  const bool same = f.width() == framebufferWidth && f.height() == framebufferHeight;
  glBlitFramebuffer(0, 0, f.width(), f.height(), 0, 0, framebufferWidth, framebufferHeight, GL_COLOR_BUFFER_BIT,
                    same ? GL_NEAREST : GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::finish() { glFinish(); }

}  // namespace coilsim::render
