#include "ui/contact_overlay.h"

#include <algorithm>

namespace coilsim::ui {
namespace {

// The contact fields are read only if the State has them (a build without
// the contact effects has no RodState::contact): the requires-expression
// names every field used, so a State without them compiles to "none".
template <class Rod>
void visit(const Rod& r, double radius, ContactSummary& sum, double& maxForce, DrawData* out, double scale) {
  if constexpr (requires {
                  r.contact.wall;
                  r.contact.self;
                  r.contact.rod;
                  r.contact.wallForce;
                  r.contact.wall.front().segment;
                  r.contact.wall.front().s;
                  r.contact.wall.front().normal;
                  r.contact.wall.front().normalForce;
                }) {
    sum.available = true;
    for (double f : r.contact.wallForce) sum.maxWallForce = std::max(sum.maxWallForce, f);
    const auto* lists = &r.contact.wall;
    for (const auto* list : {&r.contact.wall, &r.contact.self, &r.contact.rod}) {
      for (const auto& c : *list) {
        if (c.segment < 0 || c.segment + 1 >= r.activeNodes) continue;
        if (!out) {
          ++sum.contacts;
          maxForce = std::max(maxForce, c.normalForce);
          continue;
        }
        DrawPoint p;
        p.position = (1 - c.s) * r.x[size_t(c.segment)] + c.s * r.x[size_t(c.segment) + 1] - radius * c.normal;
        p.vector = c.normal * (c.normalForce * scale);
        p.colour = list == lists ? kWallContactColour : kCoilContactColour;
        out->points.push_back(p);
      }
    }
  } else {
    (void)r, (void)radius, (void)sum, (void)maxForce, (void)out, (void)scale;
  }
}

}  // namespace

ContactSummary addContactMarkers(const Model& model, const State& state, double arrowLength, DrawData& out) {
  ContactSummary sum;
  sum.wallLoad = state.stats.wallLoad.now;
  sum.wallLoadMax = state.stats.wallLoad.max;
  double maxForce = 0;
  auto radius = [&](size_t k) { return k < model.rods.size() ? model.rods[k].section.radius : 0.0; };
  // First the largest force (for the arrows' scale), then the markers.
  for (size_t k = 0; k < state.rods.size(); ++k)
    if (state.rods[k].active) visit(state.rods[k], radius(k), sum, maxForce, nullptr, 0);
  const double scale = maxForce > 0 ? arrowLength / maxForce : 0;
  for (size_t k = 0; k < state.rods.size(); ++k)
    if (state.rods[k].active) visit(state.rods[k], radius(k), sum, maxForce, &out, scale);
  return sum;
}

double contactMarkerRadius(const Model& model) {
  double thinnest = 0;
  for (const RodModel& r : model.rods)
    if (r.section.radius > 0 && (thinnest == 0 || r.section.radius < thinnest)) thinnest = r.section.radius;
  return 0.6 * thinnest;
}

}  // namespace coilsim::ui
