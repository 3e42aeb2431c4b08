#pragma once
// Draws the core's DrawData with OpenGL 3.3 core into a frame of its own
// (an off-screen framebuffer), in one of three views: "3d" (lit tubes,
// transparent vessels), "xray" (fluoroscopy) and "biplane" (two X-ray
// projections side by side). The caller may draw an overlay (the ImGui
// panel) into the same frame, then read it back or show it in a window.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/draw_data.h"
#include "render/camera.h"
#include "render/geometry.h"
#include "render/image.h"

namespace coilsim::render {

enum class ViewMode { Shaded, XRay, Biplane };

// "3d", "xray", "biplane"; nullopt for anything else.
std::optional<ViewMode> parseViewMode(std::string_view name);
const char* viewModeName(ViewMode mode);

// Attenuation coefficients are per metre of matter crossed; the defaults
// make a 0.3 mm platinum wire nearly black, a microcatheter faint and an
// 8 mm contrast-filled aneurysm a mid-grey roadmap.
struct XRaySettings {
  float muMetal = 7000;     // 1/m, coil (platinum)
  float muWire = 4000;      // 1/m, guide wire
  float muCatheter = 600;   // 1/m
  float muContrast = 90;    // 1/m, contrast medium in the vessel meshes
  float outline = 2.0f;     // weight of the vessel outline (roadmap)
  float brightness = 0.88f; // unattenuated intensity, 0-1
  float noise = 0.05f;      // grain amplitude, 0-1
  float vignette = 0.6f;    // darkening towards the image edge, 0-1
  // Pixels of the X-ray image per frame pixel: 0 picks 1/2 for views over
  // 480 pixels tall (a fluoroscope is soft anyway, and software GL spends
  // most of an X-ray frame per image pixel), else 1.
  float resolutionScale = 0;
};

struct RenderSettings {
  ViewMode mode = ViewMode::Shaded;
  int samples = 4;              // multisampling of the 3D view (0: off); falls back to 0 if unsupported
  TubeOptions tube{16, 3, 1.0, 3};  // at most 16 sides, 3 cap rings, 3 rings between nodes
  // Each tube at the detail its size on screen needs (tubeDetail), up to
  // `tube`; off: every tube at `tube`'s detail, as the renderer drew before.
  bool tubeDetailBySize = true;
  // Keep triangles that did not change (tubes, the vessels' draw order
  // while the camera stays); off: everything built and sent every frame.
  bool keepGeometry = true;
  bool drawMeshes = true;
  bool drawPoints = true;       // 3D view only: X-rays do not show contact markers
  double pointRadius = 0;       // m; 0 picks 1.6 times the thickest tube
  std::array<float, 3> backgroundTop{0.10f, 0.12f, 0.16f};     // display colours
  std::array<float, 3> backgroundBottom{0.27f, 0.30f, 0.35f};
  std::array<float, 3> sideColour{0.06f, 0.06f, 0.07f};       // the frame outside the scene area
  XRaySettings xray;
};

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;  // pixels, origin at the bottom left
};

// One projection drawn in the frame (two in biplane), for overlays.
struct ViewportInfo {
  int x = 0, y = 0, width = 0, height = 0;  // pixels, origin at the bottom left
  std::string label;                         // "3D", "AP", "LAT"
  Camera camera;
};

// Fits the camera to `bounds` for a view of width x height pixels, keeping
// its direction; in biplane the distance fits both projections (frontal and
// lateral, each in half the width).
void fitCamera(Camera& camera, const Bounds& bounds, ViewMode mode, int width, int height);

class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Builds the shaders. Needs a current OpenGL 3.3 context with the GL table
  // loaded (a Backend does both). Returns false with the reason in `error`.
  bool init(std::string& error);

  // Draws one frame of width x height pixels. In biplane mode `camera` is
  // the frontal (AP) projection and the lateral one is derived from it.
  // Returns false if the frame buffers cannot be made (the reason in `error`).
  bool render(const DrawData& data, const Camera& camera, const RenderSettings& settings, int width, int height,
              std::string& error);
  // The same with the scene confined to `area` of the frame (beside a side
  // panel); the rest of the frame is filled with settings.sideColour.
  bool render(const DrawData& data, const Camera& camera, const RenderSettings& settings, int width, int height,
              const Rect& area, std::string& error);

  const std::vector<ViewportInfo>& viewports() const;
  int width() const;
  int height() const;
  // Binds the frame so that an overlay draws on top of the scene.
  void bindFrame();
  // Reads the frame (scene and overlay) back, first row at the top.
  bool readFrame(Image& out);
  // Copies the frame to the default framebuffer (the window), scaled to fit.
  void present(int framebufferWidth, int framebufferHeight);
  // Waits for the GPU, for timing.
  void finish();
  // Reads the window's back buffer (after present(), before the swap), to
  // check what the window really shows.
  static bool readWindowPixels(int width, int height, Image& out);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace coilsim::render
