// The winding order of a packed wire (see winding_order.h).
#include "planning/winding_order.h"

#include <cmath>

namespace coilsim::planning {

WindingOrder windingOrder(const std::vector<Vec3>& p, const Vec3& c) {
  WindingOrder out;
  Vec3 j = Vec3::Zero();
  double scale = 0;
  for (size_t i = 1; i < p.size(); ++i) {
    const Vec3 w = (0.5 * (p[i] + p[i - 1]) - c).cross(p[i] - p[i - 1]);
    j += w;
    scale += w.norm();
  }
  const double net = j.norm();
  if (!(net > 1e-12 * scale)) return out;
  out.axis = j / net;
  double total = 0;
  for (size_t i = 1; i < p.size(); ++i)
    total += std::abs((0.5 * (p[i] + p[i - 1]) - c).cross(p[i] - p[i - 1]).dot(out.axis));
  out.order = net / total;
  return out;
}

}  // namespace coilsim::planning
