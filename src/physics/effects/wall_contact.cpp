// Wall contact: rod capsules against the obstacles' triangle meshes
// (aneurysm sac, parent vessel, phantom): a penalty, or with rigid = 1 each
// node held by a unilateral constraint; regularised Coulomb friction. Model and reasons: physics/contact/response.h;
// detection: physics/contact/detect.h.
#include "physics/contact/detect.h"
#include "physics/effects/builtin.h"
#include "physics/model.h"
#include "physics/state.h"

namespace coilsim {
namespace {

constexpr ParamSpec kParams[] = {
    {"stiffness_n_mm2", "N/mm2", "penalty stiffness per length of rod pressed into the wall (N/mm per mm)", 200.0, 0.0,
     1e4, 1e6},
    {"damping_ratio", "1", "normal (and sticking) damping as a fraction of critical for the node mass", 1.0, 0.0, 10.0,
     1.0},
    {"margin_mm", "mm", "distance at which a wall contact is tracked before it touches", 0.05, 0.0, 5.0, 1e-3},
    {"friction_static", "1", "static Coulomb coefficient coil-wall", 0.3, 0.0, 5.0, 1.0},
    {"friction_dynamic", "1", "dynamic Coulomb coefficient coil-wall", 0.2, 0.0, 5.0, 1.0},
    {"friction_stiffness_ratio", "1", "stick spring stiffness over normal stiffness (regularised Coulomb)", 0.5, 0.01,
     10.0, 1.0},
    // 10 / mm^3: a wire up to the cavity test's (EI / r = 19.9 N mm, within
    // 3 % of r at 200 N/mm^2) keeps stiffness_n_mm2, the scenes' soft coils
    // (0.019 N mm) far below it; the paper's 0.356 mm wire (265 N mm) gets
    // 2650 N/mm^2 (detect.h, wallStiffness).
    {"stiffness_per_rigidity_1_mm3", "1/mm3",
     "the penalty per length is at least this times the wire's bending rigidity over its radius, EI / r, so a stiffer "
     "wire meets a stiffer wall (0: stiffness_n_mm2 alone)",
     10.0, 0.0, 1e4, 1e9},
    // docs/contact.md, "Why a constraint per node against the wall": with
    // the penalty the largest load of a push followed the penalty. Off by
    // default until every test passes under it and its cost is within the
    // issue's bound (same section, "Not the default yet").
    {"rigid", "1",
     "1: each node is held against the wall by a unilateral constraint, whose multiplier is the wall force "
     "(stiffness_n_mm2 then only sets friction's stick spring); 0: the penalty",
     0.0, 0.0, 1.0, 1.0},
};

constexpr size_t kStiffness = paramIndex(kParams, "stiffness_n_mm2"), kDamping = paramIndex(kParams, "damping_ratio"),
                 kMargin = paramIndex(kParams, "margin_mm"), kStatic = paramIndex(kParams, "friction_static"),
                 kDynamic = paramIndex(kParams, "friction_dynamic"), kStick = paramIndex(kParams, "friction_stiffness_ratio"),
                 kPerRigidity = paramIndex(kParams, "stiffness_per_rigidity_1_mm3"), kRigid = paramIndex(kParams, "rigid");

ContactLaw lawOf(std::span<const double> p) {
  ContactLaw law{p[kStiffness], p[kDamping], p[kStatic], p[kDynamic], p[kStick], 1.0};
  law.rigid = p[kRigid] > 0.5;
  return law;
}

// A wall held by constraints: what the last step's solves left each node's
// friction becomes what this step starts from (a step retaken in substeps
// starts from it again: the first substep does not detect). Nodes are
// counted from the distal end, so a node inserted or withdrawn at a
// deploying catheter tip keeps its friction.
void keepWallFriction(State& state) {
  for (RodState& r : state.rods) {
    RodContacts& rc = r.contact;
    const size_t nodes = r.x.size();
    const int active = r.activeNodes, before = rc.wallFrictionNodes;
    rc.wallFrictionBefore.assign(nodes, {});
    if (rc.wallFrictionAfter.size() == nodes)
      for (int k = 0; k < std::min(active, before); ++k)
        rc.wallFrictionBefore[active - 1 - k] = rc.wallFrictionAfter[before - 1 - k];
    rc.wallFrictionAfter.assign(nodes, {});
    rc.wallFrictionNodes = active;
  }
}

class WallContact final : public Effect {
 public:
  std::string_view name() const override { return "wall_contact"; }
  std::string_view description() const override { return "rods against the obstacle meshes, with friction"; }
  std::span<const ParamSpec> params() const override { return kParams; }
  void beginStep(const Model& model, std::span<const double> p, State& state, double h) const override {
    if (p[kRigid] > 0.5) keepWallFriction(state);
    detectWallContacts(model, state, h, p[kMargin], lawOf(p), p[kPerRigidity]);
  }
  // A node sliding fast along a curved wall leaves the tangent plane its
  // step was solved with: the step is retaken in substeps (detect.h).
  std::optional<Failure> endStep(const Model& model, std::span<const double> p, const State& state,
                                 double) const override {
    return checkWallContacts(model, state, p[kMargin], p[kRigid] > 0.5);
  }
  bool constrainsNodes(std::span<const double> p) const override { return p[kRigid] > 0.5; }
  void apply(const EffectContext& c, std::span<const double> p, RodForces& out) const override {
    ContactLaw law = lawOf(p);
    law.stiffness = wallStiffness(law.stiffness, p[kPerRigidity], c.rod);
    applyContacts(c.state.contact.wall, c, law, out);
  }
};

}  // namespace

std::unique_ptr<Effect> makeWallContactEffect() { return std::make_unique<WallContact>(); }

}  // namespace coilsim
