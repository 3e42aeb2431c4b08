#include "validation/diagnose.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "validation/fit_staged.h"
#include "validation/params.h"
#include "validation/significance.h"
#include "validation/text.h"

namespace coilsim::validation {
namespace {

// A finding must explain at least this share of the baseline residual: a
// candidate that trims a few per cent off a residual left by something else
// (e.g. the differences between two rod models) is not the missing effect.
constexpr double kMinExplained = 0.25;

}  // namespace

Candidate candidateFor(const std::string& effect, const Measurement& m) {
  Candidate c;
  c.effect = effect;
  const Effect* e = EffectRegistry::global().find(effect);
  if (!e) return c;
  const std::optional<Diagnosable> d = e->diagnosis(setupHint(m));
  if (d) {
    for (const auto& [param, value] : d->held) c.held.emplace_back(std::string(param), value);
    for (const FitSpec& f : d->fit) {
      c.params.push_back(effect + "." + std::string(f.param));
      c.offValue.push_back(f.off);
      c.typicalValue.push_back(f.typical);
    }
  } else if (!e->params().empty()) {
    // An effect that says nothing of diagnosis: its first parameter from 0 (off) to its default.
    const ParamSpec& s = e->params()[0];
    c.params = {effect + "." + std::string(s.name)};
    c.offValue = {0.0};
    c.typicalValue = {s.defaultValue * s.toSI};
  }
  // Parameterless effects: switched on, nothing fitted.
  return c;
}

std::vector<Candidate> defaultCandidates(const Measurement& m) {
  std::vector<Candidate> out;
  for (const Effect* e : EffectRegistry::global().all())
    if (e->diagnosis(setupHint(m))) out.push_back(candidateFor(std::string(e->name()), m));
  return out;
}

ModelParams withCandidate(const ModelParams& p, const Candidate& c) {
  ModelParams q = p;
  if (!q.effect(c.effect)) {
    q.effects.push_back(EffectRegistry::global().use(c.effect));
    for (const auto& [param, value] : c.held) q.effects.back().set(param, value);
  }
  for (size_t k = 0; k < c.params.size(); ++k) setParam(q, c.params[k], c.offValue[k]);
  return q;
}

Fingerprint fingerprint(const Comparison& cmp, const std::vector<StageComparison>& stages) {
  Fingerprint f;
  const Measurement& m = cmp.measurement();
  const Vec3 g = m.gravity.norm() > 0 ? Vec3(m.gravity.normalized()) : Vec3(0, 0, -1);
  std::vector<double> logL, logR;
  for (size_t k = 0; k < stages.size(); ++k) {
    const StageComparison& s = stages[k];
    double ag = 0, ac = 0, ax = 0, third[3] = {0, 0, 0};
    const size_t n = s.sim.size();
    const double l = s.s.empty() ? 0 : s.s.back();
    for (size_t i = 0; i < n; ++i) {
      const Vec3 r = s.sim[i] - s.meas[i];
      const Vec3 t = (s.sim[std::min(n - 1, i + 1)] - s.sim[i == 0 ? 0 : i - 1]).normalized();
      Vec3 et = t - t.dot(g) * g;
      et = et.norm() > 1e-6 ? Vec3(et.normalized()) : Vec3::Zero();
      const double rg = r.dot(g), rt = r.dot(et);
      ag += rg * rg, ac += rt * rt, ax += std::max(0.0, r.squaredNorm() - rg * rg - rt * rt);
      third[std::min(2, int(3 * s.s[i] / std::max(l, 1e-12)))] += r.squaredNorm();
    }
    const double nn = std::max<double>(1, double(n)), tot = ag + ac + ax;
    f.rmsAlongGravity.push_back(std::sqrt(ag / nn));
    f.rmsAlongCoil.push_back(std::sqrt(ac / nn));
    f.rmsAcross.push_back(std::sqrt(ax / nn));
    f.rmsTotal.push_back(std::sqrt(tot / nn));
    f.shareProximal.push_back(tot > 0 ? third[0] / tot : 0);
    f.shareMiddle.push_back(tot > 0 ? third[1] / tot : 0);
    f.shareDistal.push_back(tot > 0 ? third[2] / tot : 0);
    if (f.rmsTotal.back() / std::sqrt(3.0) > 1.5 * s.sigma) f.aboveNoise = true;
    if (l > 0 && f.rmsTotal.back() > 0) logL.push_back(std::log(l)), logR.push_back(std::log(f.rmsTotal.back()));
  }
  if (logL.size() >= 2) {
    double ml = 0, mr = 0;
    for (size_t i = 0; i < logL.size(); ++i) ml += logL[i], mr += logR[i];
    ml /= double(logL.size()), mr /= double(logL.size());
    double sxy = 0, sxx = 0;
    for (size_t i = 0; i < logL.size(); ++i) sxy += (logL[i] - ml) * (logR[i] - mr), sxx += (logL[i] - ml) * (logL[i] - ml);
    f.growthExponent = sxx > 0 ? sxy / sxx : 0;
  }
  // The summary: the dominant direction and place over all stages.
  double G = 0, C = 0, X = 0, P = 0, M = 0, D = 0;
  for (size_t k = 0; k < f.rmsTotal.size(); ++k) {
    G += f.rmsAlongGravity[k] * f.rmsAlongGravity[k], C += f.rmsAlongCoil[k] * f.rmsAlongCoil[k];
    X += f.rmsAcross[k] * f.rmsAcross[k];
    P += f.shareProximal[k], M += f.shareMiddle[k], D += f.shareDistal[k];
  }
  const double T = std::max(G + C + X, 1e-300);
  std::string dir = G / T > 0.5 ? "mostly along gravity" : C / T > 0.5 ? "mostly along the coil" : X / T > 0.5 ? "mostly across the coil, horizontal" : "in all directions";
  std::string where = P > M && P > D && P / (P + M + D) > 0.45 ? "concentrated near the clamp"
                      : D / std::max(P + M + D, 1e-300) > 0.5 ? "concentrated distally"
                                                              : "spread along the coil";
  f.summary = std::string(f.aboveNoise ? "Residual above the noise floor, " : "Residual at the noise floor, ") + dir +
              " (" + fmt("%.0f", 100 * G / T) + " % along gravity, " + fmt("%.0f", 100 * C / T) + " % along the coil, " +
              fmt("%.0f", 100 * X / T) + " % across), " + where + ", growing with deployed length as l^" +
              fmt("%.1f", f.growthExponent) + ".";
  if (f.aboveNoise) {
    if (G / T > 0.5 && f.growthExponent > 1.5)
      f.summary += " A sag error that grows fast with length points to the load or the stiffness (weight, buoyancy, E).";
    else if (X / T > 0.5)
      f.summary += " A sideways error points to a force not along gravity (tilted bench, flow) or to the tip's roll.";
    else if (P / (P + M + D) > 0.45)
      f.summary += " An error at the clamp points to the boundary condition (catheter compliance, tip angle).";
    else if (C / T > 0.5)
      f.summary += " An error along the coil points to its length or arc-length bookkeeping (push, stretch, friction).";
  }
  return f;
}

namespace {

// The refit of candidate `c` added to `base` (whose fitted names are
// `baseFit`), regularised, judged against the residual `rssRef` of the
// model it extends: explained fraction and significance (diagnose.h).
CandidateResult refit(StageSimulator& sim, const Comparison& cmp, const ModelParams& base,
                      const std::vector<std::string>& baseFit, const Candidate& c, double rssRef, double sigma,
                      CandidateResult cr) {
  ModelParams s = withCandidate(base, c);
  for (size_t k = 0; k < c.params.size(); ++k) setParam(s, c.params[k], c.typicalValue[k]);
  FitOptions f2;
  f2.params = baseFit;
  f2.params.insert(f2.params.end(), c.params.begin(), c.params.end());
  f2.regularised = true;
  cr.fit = identifySmoothFirst(sim, cmp, s, f2).fit;
  if (!cr.fit.ok) {
    cr.note = "refit failed: " + cr.fit.message;
    return cr;
  }
  cr.refitted = true;
  const double m = double(cr.fit.residual.size());
  const double drop = rssRef - cr.fit.rss;
  cr.explainedFraction = std::clamp(drop / rssRef, 0.0, 1.0);
  const int pc = std::max<int>(1, int(c.params.size()));
  const double dof = std::max(1.0, m - double(f2.params.size()));
  const double F = drop > 0 ? (drop / pc) / (cr.fit.rss / dof) : 0.0;
  const double removedRmsPerNode = std::sqrt(std::max(0.0, drop) / (m / 3.0));
  cr.significant = F > fCritical(pc) && removedRmsPerNode > sigma && cr.explainedFraction >= kMinExplained;
  cr.stageErrorAfter.clear();
  for (const StageComparison& sc : cmp.compare(sim.run(cr.fit.params, true))) cr.stageErrorAfter.push_back(sc.metrics.stageError);
  return cr;
}

std::vector<std::string> fittedNames(const FitResult& f) {
  std::vector<std::string> out;
  for (const FittedValue& v : f.fitted) out.push_back(v.name);
  return out;
}

// The prior check of a free fit: the implausible values, in words.
void checkPriors(const FitResult& f, std::vector<std::string>& implausible, std::string& verdict) {
  std::string words;
  for (const FittedValue& v : f.fitted) {
    if (v.plausible || !v.prior.known) continue;
    implausible.push_back(v.name);
    if (!words.empty()) words += "; ";
    words += v.name + " = " + fmt("%.4g", v.value / v.toSI) + " " + v.unit + ", " +
             fmt("%.2f", v.value / v.prior.nominal) + "x its nominal " + fmt("%.4g", v.prior.nominal / v.toSI) +
             ", outside the plausible " + fmt("%.4g", v.prior.low / v.toSI) + "-" + fmt("%.4g", v.prior.high / v.toSI) +
             " " + v.unit;
  }
  if (!words.empty())
    verdict = "The baseline fits only with implausible values (" + words +
              "): the model lacks something that the fit absorbs into them. Candidates are ranked against the "
              "regularised baseline (the values held to their plausible bands).";
}

}  // namespace

Diagnosis diagnose(StageSimulator& sim, const Comparison& cmp, const ModelParams& start, const DiagnoseOptions& o) {
  Diagnosis d;
  auto say = [&](const std::string& s) {
    if (o.progress) o.progress(s);
  };
  std::vector<std::string> baseFit = o.fit;
  if (std::none_of(baseFit.begin(), baseFit.end(), isYoungModulus))
    baseFit.insert(baseFit.begin(), youngModulusFit());
  say("baseline: fitting " + std::to_string(baseFit.size()) + " parameter(s)");
  FitOptions fo;
  fo.params = baseFit;
  d.baseline = identify(sim, cmp, start, fo);
  if (!d.baseline.ok) {
    d.message = "baseline fit failed: " + d.baseline.message;
    d.failure = d.baseline.failure;
    return d;
  }
  checkPriors(d.baseline, d.implausible, d.priorVerdict);
  if (d.implausible.empty()) {
    d.regularisedBaseline = d.baseline;  // the penalty is zero inside the bands: the same fit
    d.regularisedBaseline.regularised = true;
  } else {
    say("baseline: implausible values, fitting again with priors in force");
    fo.regularised = true;
    d.regularisedBaseline = identify(sim, cmp, start, fo);
    if (!d.regularisedBaseline.ok) {
      d.message = "regularised baseline fit failed: " + d.regularisedBaseline.message;
      d.failure = d.regularisedBaseline.failure;
      return d;
    }
  }
  const FitResult& base = d.regularisedBaseline;
  d.baselineStages = cmp.compare(sim.run(d.baseline.params, true));
  d.fingerprint = fingerprint(cmp, d.implausible.empty() ? d.baselineStages : cmp.compare(sim.run(base.params, true)));
  // Refits start from the regularised baseline, except where the free fit
  // was implausible: that value is what the missing effect was absorbed
  // into (at its band's edge once regularised), so a candidate that
  // explains the data starts from the nominal instead. Started at the band's
  // edge, the self-contact refit of self-contact-dynamic stayed there (E
  // 10.8 GPa for 6.8, the contact distance at its own lower edge).
  ModelParams refitStart = base.params;
  for (const FittedValue& v : d.baseline.fitted)
    if (!v.plausible && v.prior.known) setParam(refitStart, v.name, v.prior.nominal);
  const Eigen::VectorXd r0 = base.residual;
  const double rss0 = std::max(base.rss, 1e-300);
  double sigma = 0;
  for (size_t k = 0; k < cmp.measurement().stages.size(); ++k) sigma = std::max(sigma, cmp.stageSigma(k));

  const std::vector<Candidate> cands = o.candidates.empty() ? defaultCandidates(cmp.measurement()) : o.candidates;
  // 1. Screening.
  for (const Candidate& c : cands) {
    say("screening " + c.effect);
    CandidateResult cr;
    cr.effect = c.effect;
    const ModelParams off = withCandidate(base.params, c);
    const Eigen::VectorXd rOff = evaluateResiduals(sim, cmp, off, true);
    if (rOff.size() != r0.size()) {
      cr.note = "the model fails with this effect switched on";
      d.candidates.push_back(cr);
      continue;
    }
    Eigen::MatrixXd Jc(r0.size(), std::max<Eigen::Index>(1, Eigen::Index(c.params.size())));
    if (c.params.empty()) Jc.col(0) = rOff - r0;  // on at defaults: a single column on - off
    for (size_t k = 0; k < c.params.size(); ++k) {
      ModelParams on = off;
      setParam(on, c.params[k], c.typicalValue[k]);
      const Eigen::VectorXd rOn = evaluateResiduals(sim, cmp, on, true);
      Jc.col(Eigen::Index(k)) = rOn.size() == rOff.size() ? Eigen::VectorXd((rOn - rOff) / (c.typicalValue[k] - c.offValue[k]))
                                                          : Eigen::VectorXd::Zero(r0.size());
    }
    const Eigen::MatrixXd& J0 = base.jacobian;
    Eigen::MatrixXd A(r0.size(), J0.cols() + Jc.cols());
    A << J0, Jc;
    const Eigen::VectorXd rb = c.params.empty() ? r0 : rOff;
    const Eigen::VectorXd delta = A.colPivHouseholderQr().solve(-rb);
    const double predicted = (rb + A * delta).squaredNorm();
    cr.screenedFraction = std::clamp((rss0 - predicted) / rss0, 0.0, 1.0);
    if (c.params.empty()) cr.screenedFraction = std::clamp((rss0 - rOff.squaredNorm()) / rss0, 0.0, 1.0);
    // How much of the candidate's signature the baseline parameters can already make.
    if (Jc.norm() * std::abs(c.typicalValue.empty() ? 1.0 : c.typicalValue[0] - c.offValue[0]) < 1e-9 * std::max(1e-3, r0.norm())) {
      cr.note = c.effect == "drag" ? "no effect on these stages (drag acts only in a push_history stage)"
                                   : "no measurable effect on these stages";
      cr.screenedFraction = 0;
    } else if (J0.cols() > 0) {
      const Eigen::MatrixXd proj = J0 * J0.colPivHouseholderQr().solve(Jc);
      const double unique = (Jc - proj).norm() / Jc.norm();
      if (unique < 0.03)
        cr.note = "indistinguishable from the baseline parameters in these data (" + fmt("%.1f", 100 * unique) +
                  " % of its signature is its own)";
    }
    cr.explainedFraction = cr.screenedFraction;
    d.candidates.push_back(cr);
  }
  // 2. Full refits of the best screened candidates (and of those without parameters).
  std::vector<size_t> order(d.candidates.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return d.candidates[a].screenedFraction > d.candidates[b].screenedFraction;
  });
  int refits = 0;
  for (const size_t i : order) {
    CandidateResult& cr = d.candidates[i];
    const Candidate& c = cands[i];
    if (!cr.note.empty() && cr.note.rfind("indistinguishable", 0) != 0) continue;
    if (!c.params.empty() && refits >= o.refitTop) continue;
    if (!c.params.empty()) ++refits;
    say("refitting with " + c.effect);
    cr = refit(sim, cmp, refitStart, baseFit, c, rss0, sigma, cr);
  }
  std::vector<size_t> rank = order;
  std::stable_sort(rank.begin(), rank.end(), [&](size_t a, size_t b) {
    const CandidateResult &A = d.candidates[a], &B = d.candidates[b];
    if (A.significant != B.significant) return A.significant;
    return A.explainedFraction > B.explainedFraction;
  });
  // 3. Forward selection: the best significant candidate joins the model;
  // the others are refitted on top of it, until none is significant.
  FitResult current = base;
  std::vector<bool> used(cands.size(), false);
  if (!rank.empty() && d.candidates[rank.front()].significant) {
    const size_t first = rank.front();
    used[first] = true;
    d.selected.push_back({cands[first].effect, d.candidates[first].explainedFraction, d.candidates[first]});
    current = d.candidates[first].fit;
    while (int(d.selected.size()) < o.maxEffects) {
      const double rssCur = std::max(current.rss, 1e-300);
      SelectionStep best;
      bool found = false;
      int tried = 0;
      for (const size_t i : rank) {
        if (used[i] || tried >= o.refitTop) continue;
        // Nor one the baseline parameters can mimic: it could then only
        // stand in for a parameter its prior holds at the band's edge.
        if (!d.candidates[i].note.empty()) continue;
        ++tried;
        say("with " + d.selected.back().effect + ": refitting with " + cands[i].effect);
        CandidateResult cr;
        cr.effect = cands[i].effect;
        cr = refit(sim, cmp, current.params, fittedNames(current), cands[i], rssCur, sigma, cr);
        if (cr.significant && (!found || cr.explainedFraction > best.explainedFraction)) {
          best = {cands[i].effect, cr.explainedFraction, cr};
          found = true;
        }
      }
      if (!found) break;
      for (size_t i = 0; i < cands.size(); ++i)
        if (cands[i].effect == best.effect) used[i] = true;
      current = best.result.fit;
      d.selected.push_back(best);
    }
  }
  std::vector<CandidateResult> ranked;
  for (const size_t i : rank) ranked.push_back(d.candidates[i]);
  d.candidates = ranked;
  // The selected model without priors too: both fits are reported.
  if (!d.selected.empty()) {
    say("free fit of the selected model");
    FitOptions ff;
    ff.params = fittedNames(current);
    d.selected.back().result.freeFit = identify(sim, cmp, current.params, ff);
  }
  if (!d.selected.empty()) {
    std::string names;
    for (const SelectionStep& s : d.selected)
      names += (names.empty() ? "" : ", then ") + s.effect + " (" + fmt("%.0f", 100 * s.explainedFraction) + " %)";
    d.verdict = "Missing, in order: " + names +
                ", each explaining that share of the residual left before it, significantly above the noise.";
  } else if (d.fingerprint.aboveNoise) {
    d.verdict = "No candidate explains the residual significantly; it is above the noise floor: see the fingerprint.";
  } else {
    d.verdict = "The base model explains the data to the noise level: no effect is needed.";
  }
  if (!d.priorVerdict.empty()) d.verdict = d.priorVerdict + " " + d.verdict;
  // 4. The final model: adequacy and the prediction check.
  d.finalStages = cmp.compare(sim.run(current.params, false));
  d.adequacy = adequacy(cmp, d.finalStages);
  if (o.predict && cmp.measurement().stages.size() >= 2) {
    say("prediction check: fitting all stages but the last");
    d.prediction = predictLastStage(cmp, sim.options(), current.params, fittedNames(current),
                                    d.finalStages.back().metrics.stageError, true);
  }
  d.ok = true;
  return d;
}

}  // namespace coilsim::validation
