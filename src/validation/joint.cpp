#include "validation/joint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "validation/params.h"
#include "validation/significance.h"
#include "validation/text.h"

namespace coilsim::validation {
namespace {

std::vector<FitMember> membersOf(const std::vector<JointFile>& files, const std::vector<ModelParams>& starts) {
  std::vector<FitMember> out;
  for (size_t i = 0; i < files.size(); ++i) out.push_back({files[i].sim, files[i].cmp, starts[i]});
  return out;
}

double maxSigma(const std::vector<JointFile>& files) {
  double s = 0;
  for (const JointFile& f : files)
    for (size_t k = 0; k < f.cmp->measurement().stages.size(); ++k) s = std::max(s, f.cmp->stageSigma(k));
  return s;
}

// Is the drop from `rssJoint` (shared values) to `rssSeparate` (one value
// per file for `extra` more parameters) significant?
bool mustDiffer(double rssJoint, double rssSeparate, double m, int shared, int extra, double sigma,
                double& explained) {
  const double drop = rssJoint - rssSeparate;
  explained = std::clamp(drop / std::max(rssJoint, 1e-300), 0.0, 1.0);
  const double dof = std::max(1.0, m - shared - extra);
  const double F = drop > 0 ? (drop / extra) / (rssSeparate / dof) : 0.0;
  return F > fCritical(extra) && std::sqrt(std::max(0.0, drop) / (m / 3.0)) > sigma && explained >= 0.25;
}

}  // namespace

JointDiagnosis diagnoseJoint(const std::vector<JointFile>& files, const std::vector<std::string>& fitIn,
                             const std::function<void(const std::string&)>& progress) {
  JointDiagnosis d;
  auto say = [&](const std::string& s) {
    if (progress) progress(s);
  };
  if (files.size() < 2) {
    d.message = "a joint fit needs two files or more";
    return d;
  }
  d.fit = fitIn.empty() ? std::vector<std::string>{youngModulusFit()} : fitIn;
  std::vector<ModelParams> starts;
  for (const JointFile& f : files) starts.push_back(f.start);
  FitOptions fo;
  fo.params = d.fit;
  say("joint: fitting " + std::to_string(d.fit.size()) + " parameter(s) once for " + std::to_string(files.size()) + " files");
  d.joint = identifyJoint(membersOf(files, starts), fo);
  if (!d.joint.ok) {
    d.message = "joint fit failed: " + d.joint.message;
    d.failure = d.joint.failure;
    return d;
  }
  double rssSeparate = 0;
  for (size_t i = 0; i < files.size(); ++i) {
    say("joint: fitting file " + std::to_string(i + 1) + " alone");
    d.separate.push_back(identify(*files[i].sim, *files[i].cmp, starts[i], fo));
    if (!d.separate.back().ok) {
      d.message = "fit of file " + std::to_string(i + 1) + " alone failed: " + d.separate.back().message;
      d.failure = d.separate.back().failure;
      return d;
    }
    rssSeparate += d.separate.back().rss;
  }
  const double m = double(d.joint.residual.size()), sigma = maxSigma(files);
  const int p = int(d.fit.size()), extra = p * int(files.size() - 1);
  double explained = 0;
  const bool differ = mustDiffer(d.joint.rss, rssSeparate, m, p, extra, sigma, explained);
  for (size_t k = 0; k < d.fit.size(); ++k) {
    ParameterSpread s;
    s.param = d.fit[k];
    s.unit = d.joint.fitted[k].unit, s.toSI = d.joint.fitted[k].toSI;
    s.joint = d.joint.fitted[k].value;
    for (const FitResult& f : d.separate) s.perFile.push_back(f.fitted[k].value), s.sigmaPerFile.push_back(f.fitted[k].sigma);
    s.explainedFraction = explained;
    s.mustDiffer = differ;
    d.spread.push_back(s);
  }
  if (!differ) {
    d.verdict = "One set of coil parameters fits every file: no parameter must differ between them (letting them "
                "differ removes " + fmt("%.0f", 100 * explained) + " % of the joint residual).";
    d.ok = true;
    return d;
  }
  // Effects whose values the setup implies, switched on in every file.
  for (const Effect* e : EffectRegistry::global().all()) {
    std::vector<ModelParams> with = starts;
    bool setupDriven = false;
    for (size_t i = 0; i < files.size(); ++i) {
      if (with[i].effect(e->name())) continue;  // already on
      const std::optional<Diagnosable> dg = e->diagnosis(setupHint(files[i].cmp->measurement()));
      if (!dg || dg->fromSetup.empty()) break;
      with[i].effects.push_back(effectFromFile(std::string(e->name()), files[i].cmp->measurement()));
      setupDriven = true;
    }
    if (!setupDriven) continue;
    JointEffect je;
    je.effect = std::string(e->name());
    say("joint: " + je.effect + " on in every file at its setup's values");
    je.fit = identifyJoint(membersOf(files, with), fo);
    if (!je.fit.ok) continue;
    double rssSep = 0;
    for (size_t i = 0; i < files.size(); ++i) {
      const FitResult f = identify(*files[i].sim, *files[i].cmp, with[i], fo);
      rssSep += f.ok ? f.rss : INFINITY;
      je.perFileAfter.push_back(f.ok ? f.fitted[0].value : NAN);
    }
    const double drop = d.joint.rss - je.fit.rss;
    je.explainedFraction = std::clamp(drop / std::max(d.joint.rss, 1e-300), 0.0, 1.0);
    je.significant = je.explainedFraction >= 0.25 && std::sqrt(std::max(0.0, drop) / (m / 3.0)) > sigma;
    double left = 0;
    je.removesSpread = !mustDiffer(je.fit.rss, rssSep, m, p, extra, sigma, left);
    d.effects.push_back(je);
  }
  std::stable_sort(d.effects.begin(), d.effects.end(), [](const JointEffect& a, const JointEffect& b) {
    if ((a.significant && a.removesSpread) != (b.significant && b.removesSpread)) return a.significant && a.removesSpread;
    return a.explainedFraction > b.explainedFraction;
  });
  std::string values;
  const ParameterSpread& s0 = d.spread.front();
  for (size_t i = 0; i < s0.perFile.size(); ++i)
    values += (i ? ", " : "") + fmt("%.4g", s0.perFile[i] / s0.toSI);
  d.verdict = s0.param + " must differ between the files to fit them (" + values + " " + s0.unit +
              "; one value for all leaves " + fmt("%.0f", 100 * explained) +
              " % more residual): an effect that differs between the setups is missing.";
  if (!d.effects.empty() && d.effects.front().significant && d.effects.front().removesSpread)
    d.verdict += " " + d.effects.front().effect + ", on in every file at its setup's values, explains " +
                 fmt("%.0f", 100 * d.effects.front().explainedFraction) +
                 " % of the joint residual and one " + s0.param + " then fits all files (" +
                 fmt("%.4g", d.effects.front().fit.fitted[0].value / s0.toSI) + " " + s0.unit + ").";
  else
    d.verdict += " No setup-driven effect removes the difference.";
  d.ok = true;
  return d;
}

}  // namespace coilsim::validation
