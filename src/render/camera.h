#pragma once
// An orbit camera around a target point, z up (the core's gravity is -z),
// and the bounds it is fitted to. GL-free: matrices are plain Eigen.
#include <Eigen/Core>

#include "physics/draw_data.h"

namespace coilsim::render {

using Mat4f = Eigen::Matrix4f;

struct Bounds {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  bool empty() const { return lo.x() > hi.x(); }
  void add(const Vec3& p, double pad = 0);
  Vec3 centre() const { return empty() ? Vec3::Zero() : Vec3(0.5 * (lo + hi)); }
  double radius() const { return empty() ? 0.0 : 0.5 * (hi - lo).norm(); }
};

// Everything drawn: tube centre lines padded by their radius, mesh vertices,
// points and arrow tips. Non-finite positions are skipped.
Bounds boundsOf(const DrawData& data);

struct Camera {
  Vec3 target = Vec3::Zero();  // m
  double distance = 0.05;      // m, eye to target
  double yaw = -1.0;           // rad about +z; 0 puts the eye on +x
  double pitch = 0.4;          // rad above the horizontal plane
  double fovY = 0.5;           // rad, vertical field of view
  double nearPlane = 1e-3, farPlane = 1.0;  // m, set by fit() and zoom()
  double sceneRadius = 0.01;   // m, kept by fit() to place the clip planes

  Vec3 eye() const;
  Vec3 forward() const;  // unit, eye to target
  Vec3 right() const;    // unit, screen right
  Vec3 up() const;       // unit, screen up

  // World to eye (OpenGL convention: looking down -z).
  Mat4f view() const;
  // Perspective projection for a viewport of aspect width / height.
  Mat4f projection(double aspect) const;

  // Moves the eye so that the box fits the view from the current direction
  // (with `margin` > 1 leaving a border); sets the clip planes.
  void fit(const Bounds& bounds, double aspect, double margin = 1.1);
  void orbit(double dyaw, double dpitch);
  // Moves the target in the screen plane by fractions of the view height.
  void pan(double dx, double dy);
  // factor > 1 moves closer.
  void zoom(double factor);
  void updateClipPlanes();
};

// The eye direction of fluoroscopy projections (z up, y anterior): AP looks
// along +y from the front, lateral along -x from the patient's right side.
Camera apView(const Camera& base);
Camera lateralView(const Camera& ap);

}  // namespace coilsim::render
