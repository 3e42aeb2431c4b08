#include "physics/contact/report.h"

#include <algorithm>

namespace coilsim {

ContactSummary summarizeContacts(const State& state) {
  ContactSummary s;
  for (const RodState& r : state.rods) {
    const RodContacts& c = r.contact;
    for (const double f : c.wallForce) {
      s.maxWallForce = std::max(s.maxWallForce, f);
      s.totalWallForce += f;
    }
    s.maxPenetration = std::max(s.maxPenetration, c.wallPenetration);
    s.wallContacts += int(c.wall.size());
    s.selfContacts += int(c.self.size());
    s.rodContacts += int(c.rod.size());
  }
  return s;
}

void appendContactPoints(const State& state, double metresPerNewton, DrawData& out) {
  for (const RodState& r : state.rods) {
    const RodContacts& c = r.contact;
    const auto add = [&](const std::vector<double>& force, const std::vector<ContactPoint>& list, const Colour& colour) {
      // One point per node (lists are sorted by segment), along the normal of its first contact.
      int drawn = -1;
      for (const ContactPoint& p : list)
        for (const int node : {p.segment, p.segment + 1}) {
          if (node <= drawn || node >= int(force.size()) || force[node] <= 0) continue;
          drawn = node;
          out.points.push_back({r.x[node], metresPerNewton * force[node] * p.normal, colour});
        }
    };
    add(c.wallForce, c.wall, Colour(1, 0.85f, 0, 1));
    add(c.selfForce, c.self, Colour(0, 0.9f, 1, 1));
    add(c.rodForce, c.rod, Colour(0, 0.9f, 1, 1));
  }
}

}  // namespace coilsim
