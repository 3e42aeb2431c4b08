#include "render/camera.h"

#include <algorithm>
#include <cmath>

namespace coilsim::render {

void Bounds::add(const Vec3& p, double pad) {
  if (!p.allFinite()) return;
  lo = lo.cwiseMin(p - Vec3::Constant(pad));
  hi = hi.cwiseMax(p + Vec3::Constant(pad));
}

Bounds boundsOf(const DrawData& data) {
  Bounds b;
  for (const DrawTube& t : data.tubes)
    for (const Vec3& c : t.centre) b.add(c, t.radius);
  for (const DrawMesh& m : data.meshes)
    for (const Vec3& v : m.vertices) b.add(v);
  for (const DrawPoint& p : data.points) {
    b.add(p.position);
    b.add(p.position + p.vector);
  }
  return b;
}

Vec3 Camera::eye() const { return target - distance * forward(); }

Vec3 Camera::forward() const {
  // The eye sits at (cos p cos y, cos p sin y, sin p) from the target.
  return -Vec3(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
}

Vec3 Camera::right() const { return Vec3(-std::sin(yaw), std::cos(yaw), 0.0); }

Vec3 Camera::up() const { return right().cross(forward()); }

Mat4f Camera::view() const {
  const Vec3 f = forward(), r = right(), u = up(), e = eye();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = r.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -r.dot(e);
  m(1, 3) = -u.dot(e);
  m(2, 3) = f.dot(e);
  return m.cast<float>();
}

Mat4f Camera::projection(double aspect) const {
  const double t = 1.0 / std::tan(0.5 * fovY), n = nearPlane, f = farPlane;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = t / std::max(aspect, 1e-6);
  p(1, 1) = t;
  p(2, 2) = -(f + n) / (f - n);
  p(2, 3) = -2.0 * f * n / (f - n);
  p(3, 2) = -1.0;
  return p.cast<float>();
}

void Camera::fit(const Bounds& bounds, double aspect, double margin) {
  if (bounds.empty()) return;
  target = bounds.centre();
  sceneRadius = std::max(bounds.radius(), 1e-6);
  // A corner at offset (x, y, z) in the camera basis (z away from the eye)
  // stays inside the frustum when |x| <= (d + z) tan(hx) and likewise for y.
  const double ty = std::tan(0.5 * fovY), tx = ty * std::max(aspect, 1e-6);
  const Vec3 f = forward(), r = right(), u = up();
  double d = 0;
  for (int k = 0; k < 8; ++k) {
    const Vec3 c((k & 1) ? bounds.hi.x() : bounds.lo.x(), (k & 2) ? bounds.hi.y() : bounds.lo.y(),
                 (k & 4) ? bounds.hi.z() : bounds.lo.z());
    const Vec3 o = c - target;
    const double z = o.dot(f);
    d = std::max({d, margin * std::abs(o.dot(r)) / tx - z, margin * std::abs(o.dot(u)) / ty - z});
  }
  distance = std::max(d, 2.0 * sceneRadius * 0.05);
  updateClipPlanes();
}

void Camera::updateClipPlanes() {
  // Clip planes bracket the scene sphere; the near plane never reaches the eye.
  nearPlane = std::max(distance - 2.0 * sceneRadius, distance * 0.02);
  farPlane = distance + 2.0 * sceneRadius;
}

void Camera::orbit(double dyaw, double dpitch) {
  constexpr double kLimit = 1.5533;  // 89 degrees: keep away from the poles where z-up degenerates
  yaw = std::remainder(yaw + dyaw, 2.0 * M_PI);
  pitch = std::clamp(pitch + dpitch, -kLimit, kLimit);
}

void Camera::pan(double dx, double dy) {
  const double h = 2.0 * distance * std::tan(0.5 * fovY);
  target += h * (dx * right() + dy * up());
}

void Camera::zoom(double factor) {
  distance = std::clamp(distance / std::max(factor, 1e-3), sceneRadius * 0.05, sceneRadius * 200.0);
  updateClipPlanes();
}

Camera apView(const Camera& base) {
  Camera c = base;
  c.yaw = -0.5 * M_PI;  // eye on -y (in front), looking along +y
  c.pitch = 0;
  return c;
}

Camera lateralView(const Camera& ap) {
  Camera c = ap;
  c.yaw = ap.yaw + 0.5 * M_PI;  // the C-arm turned a quarter turn about the vertical
  return c;
}

}  // namespace coilsim::render
