#include "validation/simulate.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/deployment.h"
#include "physics/run.h"
#include "validation/params.h"

namespace coilsim::validation {
namespace {

// The model of a measurement: its coil deployed from the file's catheter tip.
struct Built {
  Model model;
  const Deployment& dep() const { return *model.device; }
};

Built build(const Measurement& m, const ModelParams& p, int beams, double timeStep) {
  ModelDef def;
  def.timeStep = timeStep;
  def.gravity = m.gravity;
  def.damping = {0.0, 0.0};  // the paper's model: no damping beyond the integrator's
  def.effects.push_back(EffectRegistry::global().use("gravity"));
  bool compliant = false;
  for (const EffectUse& e : p.effects) {
    def.effects.push_back(e);
    compliant = compliant || (e.enabled && releasesClamp(e));
  }
  DeploymentDef d;
  d.coil = p.coil;
  d.coilBeams = beams;
  d.tip = m.tip;
  d.maxPushSpeed = 1e9, d.maxTwistRate = 1e9;  // the file's history is what happened
  // A compliant catheter: the tip node hangs on the catheter_compliance spring instead of the rigid clamp.
  d.tipClamped = !compliant;
  def.device = d;
  return {compileModel(def)};
}

StaticOptions staticOptions() {
  StaticOptions o;
  o.loadSteps = 1;  // each push starts from the previous equilibrium under full load
  o.maxBisections = 8;
  o.positionTolerance = 1e-9;
  o.rotationTolerance = 1e-8;
  return o;
}

// Static equilibrium; solveStatic detects contacts (self_contact) at every
// Newton iteration itself.
StaticReport solveWithEffects(const Built& b, State& s) { return solveStatic(b.model, s, staticOptions()); }

// Pushes from the state's current deployed length to `target` in increments
// of at most `step`, an equilibrium after each; halves the increment on
// failure. Nothing, or the last static solve's failure, saying how far the
// coil was pushed.
std::optional<Failure> pushStatic(const Built& b, State& s, double target, double twist, double step) {
  double inc = step;
  while (s.device.deployed < target - 1e-12) {
    const double next = std::min(target, s.device.deployed + inc);
    const State saved = s;
    slideDeployment(b.model, s, next, twist);
    const StaticReport r = solveWithEffects(b, s);
    if (r.converged()) {
      inc = std::min(step, inc * 2);
      continue;
    }
    s = saved;
    inc *= 0.5;
    if (inc < 1e-3 * step) {
      Failure f = *r.failure;
      f.text += " (pushing the coil to " + std::to_string(next * 1e3) + " mm)";
      return f;
    }
  }
  return std::nullopt;
}

// Deployed length and twist of a push history at time t (linear between samples, held outside).
void historyAt(const Stage& st, double t, double& l, double& tw) {
  const auto& h = st.pushHistory;
  if (t <= h.front().time) { l = h.front().deployed, tw = h.front().twist; return; }
  if (t >= h.back().time) { l = h.back().deployed, tw = h.back().twist; return; }
  size_t k = 1;
  while (h[k].time < t) ++k;
  const double f = (t - h[k - 1].time) / (h[k].time - h[k - 1].time);
  l = h[k - 1].deployed + f * (h[k].deployed - h[k - 1].deployed);
  tw = h[k - 1].twist + f * (h[k].twist - h[k - 1].twist);
}

StageSim collect(const Built& b, const State& s) {
  StageSim out;
  const DeviceState& ds = s.device;
  const RodState& chain = s.rods[b.dep().chainRod];
  for (int i = 0; i < chain.activeNodes; ++i) {
    out.x.push_back(chain.x[i]);
    // Node i >= 1 is coil material node j = k + i - 1 at u_j = L - j h; s = l - u_j.
    const int j = ds.firstOutside + i - 1;
    out.s.push_back(i == 0 ? 0.0 : ds.deployed - (b.dep().coilLength - j * b.dep().spacing));
    if (!chain.x[i].allFinite() && !out.failure) {
      out.failure = badRod(b.model.rods[size_t(b.dep().chainRod)].name, "non-finite node position");
      out.failure->kind = FailureKind::BlowUp;
      out.failure->node = i;
    }
  }
  return out;
}

}  // namespace

ModelParams ModelParams::nominal(const Measurement& m) {
  ModelParams p;
  p.coil = m.coil;
  if (!(p.coil.youngModulus > 0)) p.coil.youngModulus = 10e9;
  return p;
}

EffectUse* ModelParams::effect(std::string_view name) {
  for (EffectUse& e : effects)
    if (e.name() == name) return &e;
  return nullptr;
}
const EffectUse* ModelParams::effect(std::string_view name) const {
  for (const EffectUse& e : effects)
    if (e.name() == name) return &e;
  return nullptr;
}

StageSimulator::StageSimulator(const Measurement& m, const SimOptions& o) : m_(m), options_(o) {
  if (!(o.spacing > 0) || !(o.pushIncrement > 0) || !(o.timeStep > 0))
    throw std::invalid_argument("simulation options must be positive");
  beams_ = std::max(4, int(std::lround(m.coil.length / o.spacing)));
  cache_.resize(m.stages.size());
}

std::vector<StageSim> StageSimulator::run(const ModelParams& p, bool warmStart) {
  std::vector<StageSim> out(m_.stages.size());
  Built b;
  try {
    b = build(m_, p, beams_, options_.timeStep);
  } catch (const PhysicsError& e) {
    for (auto& o : out) o.failure = e.failure();
    return out;
  } catch (const std::exception& e) {  // an effect's value a parameter set cannot take (EffectUse::set)
    for (auto& o : out) o.failure = badDefinition("the model of " + m_.name, e.what());
    return out;
  }
  // Static stages by twist, then deployed length: each continues the previous one.
  std::vector<size_t> order;
  for (size_t i = 0; i < m_.stages.size(); ++i) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t c) {
    const Stage &A = m_.stages[a], &C = m_.stages[c];
    return A.twist != C.twist ? A.twist < C.twist : A.deployed < C.deployed;
  });
  State s = makeState(b.model);
  bool pushing = false;  // s holds a static continuation
  for (const size_t i : order) {
    const Stage& st = m_.stages[i];
    if (st.dynamic()) continue;
    Cache& c = cache_[i];
    if (warmStart && c.valid) {
      State w = makeState(b.model);
      resetDevice(b.model, w, st.deployed, st.twist);
      RodState& chain = w.rods[b.dep().chainRod];
      if (int(c.x.size()) == chain.activeNodes) {
        std::copy(c.x.begin(), c.x.end(), chain.x.begin());
        std::copy(c.q.begin(), c.q.end(), chain.q.begin());
        const StaticReport r = solveWithEffects(b, w);
        if (r.converged()) {
          out[i] = collect(b, w);
          c.x.assign(chain.x.begin(), chain.x.begin() + chain.activeNodes);
          c.q.assign(chain.q.begin(), chain.q.begin() + chain.activeNodes);
          continue;
        }
      }
    }
    if (!pushing || s.device.twist != st.twist || s.device.deployed > st.deployed) {
      s = makeState(b.model);
      resetDevice(b.model, s, 0.0, st.twist);
      pushing = true;
    }
    if (std::optional<Failure> failed = pushStatic(b, s, st.deployed, st.twist, options_.pushIncrement)) {
      out[i].failure = std::move(failed);
      pushing = false;
      continue;
    }
    out[i] = collect(b, s);
    const RodState& chain = s.rods[b.dep().chainRod];
    c.valid = true;
    c.x.assign(chain.x.begin(), chain.x.begin() + chain.activeNodes);
    c.q.assign(chain.q.begin(), chain.q.begin() + chain.activeNodes);
  }
  for (size_t i = 0; i < m_.stages.size(); ++i) {
    const Stage& st = m_.stages[i];
    if (!st.dynamic()) continue;
    State d = makeState(b.model);
    double l0, tw0;
    historyAt(st, st.pushHistory.front().time, l0, tw0);
    resetDevice(b.model, d, 0.0, tw0);
    std::optional<Failure> failed = pushStatic(b, d, l0, tw0, options_.pushIncrement);
    const double h = b.model.timeStep;
    for (double t = st.pushHistory.front().time; !failed && t < st.captureTime - 0.5 * h; t += h) {
      double l, tw;
      historyAt(st, t + h, l, tw);
      // The file's push history drives the device (not commands): set, then advance.
      setDeployment(b.model, d, l, tw);
      if (StepReport r = advance(b.model, d); !r.ok()) {
        failed = std::move(r.failure);
        failed->time = t;  // on the file's clock, as its push history reads
      }
    }
    if (failed) {
      out[i].failure = std::move(failed);
      continue;
    }
    out[i] = collect(b, d);
  }
  return out;
}

}  // namespace coilsim::validation
