// Gravity: the weight of each node's piece of rod, m_i g, from Model::gravity.
#include "physics/effects/builtin.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

class Gravity final : public Effect {
 public:
  std::string_view name() const override { return "gravity"; }
  std::string_view description() const override { return "weight of the rod, m g per node"; }
  void apply(const EffectContext& c, std::span<const double>, RodForces& out) const override {
    for (int i = 0; i < c.state.activeNodes; ++i) out.force[i].head<3>() += c.loadFactor * c.state.nodes[i].mass * c.model.gravity;
  }
  double energy(const EffectContext& c, std::span<const double>) const override {
    double e = 0;
    for (int i = 0; i < c.state.activeNodes; ++i) e -= c.state.nodes[i].mass * c.model.gravity.dot(c.state.x[i]);
    return e;
  }
};

}  // namespace

std::unique_ptr<Effect> makeGravityEffect() { return std::make_unique<Gravity>(); }

}  // namespace coilsim
