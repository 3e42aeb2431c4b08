#pragma once
// A physical effect (gravity, buoyancy, drag, contact...) is a small class
// behind this interface, registered by name at start-up with all the others
// (effects/builtin.cpp), so that adding one is one new file plus one line.
// Parameter values live in the Model (EffectUse), in SI, so an Effect object
// itself is stateless and shared. An effect also says what it means to the
// validation workbench (diagnosis()): which of its parameters a fit varies,
// their values when off and typical, their plausible band, whether it
// replaces the rigid clamp at the catheter tip.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "physics/failure.h"
#include "physics/math.h"
#include "physics/node_friction.h"
#include "physics/pair_coupling.h"
#include "physics/wall_spring.h"
#include "physics/param.h"

namespace coilsim {

struct Model;
struct RodModel;
struct RodState;
struct State;

// What kind of solve an effect contributes to. A static solve has zero
// velocities and no step; contacts then act without friction or damping
// (with Coulomb friction an equilibrium depends on the path that led to it,
// which a static solve does not follow) and may couple distant nodes
// (RodForces::coupling).
enum class SolveKind { Dynamic, Static };

// What an effect reads for one rod.
struct EffectContext {
  const Model& model;
  const RodModel& rod;
  const RodState& state;
  double time = 0;        // s
  double loadFactor = 1;  // static continuation scales external effects by this
  double timeStep = 0;    // s, the step being taken (a substep's when a step is split)
  SolveKind solve = SolveKind::Dynamic;
};

// Stiffness between two nodes of one rod that are not neighbours (a contact
// between distant segments of a coil), or between neighbours through a
// contact: -d force[row] / d position[col], global, N/m.
struct NodeCoupling {
  int row = 0, col = 0;
  Mat3 stiffness = Mat3::Zero();
};

// A unilateral constraint an effect asks of one node in a dynamic step
// (a wall contact, docs/contact.md): by the step's end the node must have
// moved at least `depth` (m) along `normal` from where it is at this
// assembly (depth < 0: it may approach by -depth). The step's solve
// (physics/unilateral.h) holds it as an equality while its multiplier
// pushes and releases it when it would pull; the multiplier, the force the
// constraint exerts along `normal` (N, >= 0), is written to *force. With
// `friction` the held node also feels Coulomb friction capped by its
// multiplier (physics/node_friction.h).
struct NodeConstraint {
  int node = 0;
  Vec3 normal = Vec3::UnitZ();
  double depth = 0;
  double* force = nullptr;
  NodeFriction friction;
};

// Where an effect writes for one rod; all arrays have one entry per node.
struct RodForces {
  std::vector<Vec6>& force;      // force (N, rows 0-2) and moment (N m, rows 3-5), global
  std::vector<Mat6>& stiffness;  // -d force / d (position, rotation), added to the implicit matrix
  std::vector<Mat6>& damping;    // -d force / d (velocity, angular velocity)
  bool& touchedMatrix;           // set true when writing stiffness or damping
  // Stiffness between distant nodes, set in a static solve only (solveStatic
  // solves with a general sparse factorisation when there are any). A
  // dynamic step's block-tridiagonal solve holds neighbours only: nullptr,
  // and contacts lump what they can onto the diagonal blocks.
  std::vector<NodeCoupling>* coupling = nullptr;
  // Unilateral constraints on nodes, set in a dynamic step only.
  std::vector<NodeConstraint>* constraints = nullptr;
  // Pair contacts solved with both sides moving (physics/pair_coupling.h),
  // set in a dynamic step that couples them: a pair contact then writes its
  // coupling here instead of lumping its stiffness onto the diagonal.
  std::vector<PairCoupling>* pairs = nullptr;
  // Wall nodes' normal springs in the same step (physics/wall_spring.h),
  // for the wall force its solve applied.
  std::vector<WallSpring>* wallSprings = nullptr;
};

// What the workbench knows of a bench setup when it asks an effect how to
// take part (the fluid's properties set buoyancy's and drag's values).
struct SetupHint {
  double mediumDensity = 1.2;        // kg/m^3
  double mediumViscosity = 1.8e-5;   // Pa s
};

// One parameter a fit varies: its value meaning "effect off", a typical
// value (the screening's finite difference reaches it), and the band of
// physically plausible values (the prior), SI.
struct FitSpec {
  std::string_view param;
  double off = 0, typical = 0;
  double plausibleLow = 0, plausibleHigh = 0;
};

// How an effect takes part in validation: as a candidate missing effect
// (`fit` non-empty, or a parameterless switch), with values implied by the
// setup, values it is held at whenever the workbench switches it on (a
// model fitted to measurements must not depend on them: see
// self_contact), and whether it releases the rigid clamp at the tip.
struct Diagnosable {
  std::vector<FitSpec> fit;
  std::vector<std::pair<std::string_view, double>> fromSetup;  // parameter, SI value the setup implies
  std::vector<std::pair<std::string_view, double>> held;       // parameter, SI value in every validation model
  bool releasesClamp = false;
};

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string_view name() const = 0;
  virtual std::string_view description() const = 0;
  virtual std::span<const ParamSpec> params() const { return {}; }
  // Adds this effect's forces (and their derivatives where they matter for
  // stability) for one rod. `values` are SI, one per params() entry.
  virtual void apply(const EffectContext& ctx, std::span<const double> values, RodForces& out) const = 0;
  // Whether this effect holds nodes by unilateral constraints in a dynamic
  // step (RodForces::constraints): each rod's solve is then an active-set
  // solve of its own, and pair contacts are lumped rather than coupled
  // (physics/pair_coupling.h). Default: no.
  virtual bool constrainsNodes(std::span<const double>) const { return false; }
  // Potential energy of a conservative effect (J), for energy bookkeeping.
  virtual double energy(const EffectContext&, std::span<const double>) const { return 0; }
  // Called once at the start of each dynamic step (of length h: a
  // substep's when a step is split), before any rod is assembled, for
  // effects that look at all rods together (contact detection); they keep
  // what they find in the State. Default: nothing.
  virtual void beginStep(const Model&, std::span<const double>, State&, double /*h*/) const {}
  // Called after every rod has been stepped, for effects whose beginStep
  // prepared what the step's own motion can outrun (a contact reached
  // within the step that was not in its implicit solve). An answer is a
  // Failure of kind MissedContact naming the rod and beam that went too
  // deep (quantity, value and limit: the depth and the tolerance, m); the
  // step is then taken again in substeps, each with its own beginStep
  // (physics/dynamics.cpp). Default: nothing missed.
  virtual std::optional<Failure> endStep(const Model&, std::span<const double>, const State&, double /*h*/) const {
    return std::nullopt;
  }
  // The largest fraction in (0, 1] of a proposed static Newton update of rod
  // `rod` (dx: one position change per active node) that this effect
  // accepts: contacts refuse updates that would carry one segment through
  // another, which no penalty can undo afterwards. Default: all of it.
  virtual double limitStaticUpdate(const Model&, std::span<const double>, const State&, int /*rod*/,
                                   std::span<const Vec3> /*dx*/) const {
    return 1.0;
  }
  // How the validation workbench uses this effect; nullopt: not a candidate
  // missing effect (gravity, which every model has; wall and coil-coil
  // contact, which a bench in free fluid does not meet).
  virtual std::optional<Diagnosable> diagnosis(const SetupHint&) const { return std::nullopt; }
};

// One effect switched into a model, with its parameter values (SI).
struct EffectUse {
  const Effect* effect = nullptr;
  std::vector<double> values;
  bool enabled = true;
  std::string_view name() const { return effect->name(); }
  // Value of the parameter called `param`; throws std::out_of_range if none.
  double value(std::string_view param) const;
  void set(std::string_view param, double si);
};

class EffectRegistry {
 public:
  // The process-wide registry, with the built-in effects already added.
  static EffectRegistry& global();
  // Takes ownership; throws PhysicsError (physics/failure.h) if the name is taken.
  const Effect* add(std::unique_ptr<Effect> effect);
  const Effect* find(std::string_view name) const;
  std::vector<const Effect*> all() const;
  // An EffectUse with default values; throws PhysicsError (physics/failure.h) naming
  // the unknown effect and listing the known ones.
  EffectUse use(std::string_view name) const;

 private:
  std::vector<std::unique_ptr<Effect>> effects_;
};

// Adds the built-in effects; the one place a new effect gets its line.
void registerBuiltinEffects(EffectRegistry& registry);

}  // namespace coilsim
