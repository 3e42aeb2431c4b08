// Candidate runs, threads, plan.json / plan.md, merging.
#include "planning/plan.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "io/json_reader.h"
#include "io/units.h"
#include "physics/deployment.h"
#include "planning/contact_forces.h"
#include "planning/placed_coils.h"
#include "planning/run_contacts.h"

namespace coilsim::planning {
namespace {

using nlohmann::ordered_json;

constexpr double kPictureCatheterMm = 4;  // drawn length of the rigid catheter in plan pictures

// Rounded for reports, so plans diff cleanly.
double round6(double v) {
  if (!std::isfinite(v) || v == 0) return v;
  const double scale = std::pow(10.0, 5 - int(std::floor(std::log10(std::abs(v)))));
  return std::round(v * scale) / scale;
}

// Rodrigues rotation of v about unit axis k by angle a.
Vec3 rotate(const Vec3& v, const Vec3& k, double a) {
  return v * std::cos(a) + k.cross(v) * std::sin(a) + k * k.dot(v) * (1 - std::cos(a));
}

}  // namespace

void prepareSac(PlanSetup& setup) {
  if (!setup.sac.mesh) throw std::invalid_argument("the plan has no sac surface");
  setup.sac = makeSac(setup.sac.mesh, setup.sac.neck);
  setup.sacVolume = sacVolume(setup.sac);
  if (!(setup.sacVolume > 0))
    throw std::invalid_argument("the neck plane leaves no volume on the sac side (does its normal point into the sac?)");
  setup.neck = sampleNeck(setup.sac);
}

std::string Candidate::name() const {
  std::string n;
  for (const io::CoilSpec& c : coils) n += (n.empty() ? "" : " + ") + c.name;
  return n;
}

namespace {

// Folds one coil's deployment into the sequence's.
void accumulate(AutoDeployResult& total, AutoDeployResult&& one) {
  total.ok = one.ok;
  total.placed = one.placed;
  total.error = one.error;
  total.notPlaced = one.notPlaced;
  total.time += one.time;
  total.steps += one.steps;
  total.deployed = one.deployed;
  total.maxTipForce = std::max(total.maxTipForce, one.maxTipForce);
  total.maxDeploymentForce = std::max(total.maxDeploymentForce, one.maxDeploymentForce);
  total.maxKickback = std::max(total.maxKickback, one.maxKickback);
  total.corrections += one.corrections;
  total.pullBacks += one.pullBacks;
  total.wallForcesAvailable = total.wallForcesAvailable || one.wallForcesAvailable;
  WallForceStats& w = total.wall;
  w.max = std::max(w.max, one.wall.max);
  w.peak = std::max(w.peak, one.wall.peak);
  w.sum += one.wall.sum;
  w.samples += one.wall.samples;
  w.timeAbove += one.wall.timeAbove;
  AutoDeployResult::Effort& e = total.effort;
  const AutoDeployResult::Effort& o = one.effort;
  e.pushing += o.pushing, e.feeling += o.feeling, e.twisting += o.twisting, e.pausing += o.pausing;
  e.pullingBack += o.pullingBack, e.settling += o.settling, e.afterDetach += o.afterDetach;
  e.substepped += o.substepped;
  e.stepSeconds += o.stepSeconds, e.operatorSeconds += o.operatorSeconds;
  for (const TimedCommand& c : one.timeline) total.timeline.push_back({c.time, c.command});
  for (std::string& l : one.log) total.log.push_back(std::move(l));
}

}  // namespace

CandidateResult runCandidate(const PlanSetup& setup, const Candidate& c, const WallForceCheck& contacts,
                             int detectionThreads, const RunProgressCallback& progress) {
  CandidateResult r;
  r.name = c.name();
  r.variant = c.variant;
  r.sequence = c.sequence;
  r.deploy.placed = false;
  const auto start = std::chrono::steady_clock::now();
  try {
    if (c.coils.empty()) throw std::invalid_argument("a candidate without coils");
    std::vector<PlacedCoil> placed;
    int chainRod = -1, catheterNodes = 0;  // of the last deployment: chain nodes before its tip are catheter
    double before = 0;                     // m of the coils deployed before this one
    for (size_t k = 0; k < c.coils.size(); ++k) {
      const io::CoilSpec& coil = c.coils[k];
      io::SceneSpec spec = setup.scene;
      if (!spec.deployment) throw std::invalid_argument(setup.label + " has no \"deployment\" block");
      io::DeploymentSpec& dep = *spec.deployment;
      io::applyCoil(coil, setup.spacingMm, dep);
      dep.initialDeployedMm = std::min(dep.initialDeployedMm, 0.5 * dep.lengthMm);
      dep.catheter.tipPositionMm += c.tipShiftMm;
      // The rigid catheter is only drawn (setDrawnCatheterActive): a short stub lets the picture frame the sac.
      dep.catheter.drawLengthMm = std::min(dep.catheter.drawLengthMm, kPictureCatheterMm);
      if (c.tipTiltDeg != 0)
        dep.catheter.direction = rotate(dep.catheter.direction.normalized(), dep.catheter.referenceNormal.normalized(),
                                        units::degToRad(c.tipTiltDeg));
      ModelDef def = io::compileScene(spec);
      // Coils placed before come after every rod of the scene and of this
      // deployment, so the deployment's rod indices are those of a run
      // without them: its rods are added here, not by compileModel.
      const Deployment d = addDeployment(*def.device, def);
      def.device.reset();
      const size_t firstPlaced = addPlacedRods(def, placed);
      addRunContacts(def, setup.sac);
      r.model = compileModel(def);
      r.model.device = d;
      r.state = makeState(r.model);
      r.state.contactScratch.threads.setCount(detectionThreads);
      restorePlacedRods(r.state, firstPlaced, placed);
      chainRod = d.chainRod, catheterNodes = d.tipNode;
      setDrawnCatheterActive(d, r.state, false);
      RunProgress told{k, c.coils.size(), coil.name, 0, units::mmToM(coil.lengthMm), before, r.deploy.time};
      const double timeBefore = r.deploy.time;
      const DeployProgress tell = [&](double deployed, double time) {
        told.deployed = deployed, told.time = timeBefore + time;
        progress(told);
      };
      AutoDeployResult one = autoDeploy(r.model, r.state, setup.deploy,
                                        contacts ? contacts : WallForceCheck(hasWallForces),
                                        progress ? tell : DeployProgress());
      before += told.coilLength;
      setDrawnCatheterActive(d, r.state, true);  // for the picture
      if (c.coils.size() > 1) {
        const std::string label = coil.name + ": ";
        for (std::string& l : one.log) l = label + l;
        if (!one.notPlaced.empty()) one.notPlaced = label + one.notPlaced;
        if (!one.error.empty()) one.error = label + one.error;
      }
      const bool goOn = one.ok && one.placed;
      accumulate(r.deploy, std::move(one));
      if (!goOn) break;
      // The placed coils move while the next one goes in: keep their poses, and add this one.
      keepPlacedCoils(def, r.state, firstPlaced, d.freeRod, coil.name, placed);
    }
    r.sac = measureSac(setup.sac, setup.sacVolume, setup.neck, coilLines(r.model, r.state, chainRod, catheterNodes), setup.metrics);
    r.occlusion = occlusionClass(r.sac.packingDensity, r.sac.neckCoverage);
    r.ok = r.deploy.ok;
    r.error = r.deploy.error;
  } catch (const std::exception& e) {
    r.ok = false;
    r.error = e.what();
  }
  r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

int detectionThreadsFor(int runsAtOnce) {
  const unsigned cores = std::thread::hardware_concurrency();
  if (runsAtOnce != 1 || cores < 2) return 1;
  // A core busy with other work is no second core: on the shared 2-core
  // machine at a load of 5-10, detection split over two threads took as
  // long as on one, and a small one three times as long (docs/planning.md).
  double load = 0;
  if (getloadavg(&load, 1) == 1 && load > double(cores) - 1) return 1;
  return 2;
}

std::vector<CandidateResult> runCandidates(const PlanSetup& setup, const std::vector<Candidate>& candidates, int jobs,
                                           const WallForceCheck& contacts) {
  std::vector<CandidateResult> results(candidates.size());
  std::atomic<size_t> next{0};
  const int n = std::max(1, std::min<int>(jobs, int(candidates.size())));
  const int detectionThreads = detectionThreadsFor(n);
  auto worker = [&] {
    for (size_t i = next++; i < candidates.size(); i = next++)
      results[i] = runCandidate(setup, candidates[i], contacts, detectionThreads);
  };
  std::vector<std::thread> threads;
  for (int k = 1; k < n; ++k) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  return results;
}

std::vector<Candidate> sensitivityVariants(const std::vector<io::CoilSpec>& coil, double shiftMm, double tiltDeg) {
  std::vector<Candidate> v;
  v.push_back({coil, "nominal", Vec3::Zero(), 0, {}});
  // The axes across the exit direction are set per scene by runCandidate's
  // catheter; here shifts are along the scene axes, which is what a user
  // reading "tip 0.5 mm higher" means.
  const char* names[3] = {"x", "y", "z"};
  // A zero shift or tilt is the nominal run again: not run twice.
  for (int a = 0; a < 3 && shiftMm != 0; ++a)
    for (const double s : {-shiftMm, shiftMm}) {
      Vec3 shift = Vec3::Zero();
      shift[a] = s;
      char label[48];
      std::snprintf(label, sizeof label, "tip %s%+g mm", names[a], s);
      v.push_back({coil, label, shift, 0, {}});
    }
  for (const double t : {-tiltDeg, tiltDeg}) {
    if (tiltDeg == 0) break;
    char label[48];
    std::snprintf(label, sizeof label, "tilt %+g deg", t);
    v.push_back({coil, label, Vec3::Zero(), t, {}});
  }
  return v;
}

ordered_json planJson(const PlanSetup& setup, const std::vector<CandidateResult>& results) {
  ordered_json plan;
  plan["format"] = "coilsim-plan/1";
  plan["scene"] = setup.label;
  plan["sac_volume_mm3"] = round6(units::m3ToMm3(setup.sacVolume));
  plan["neck_area_mm2"] = round6(units::m2ToMm2(setup.neck.area()));
  plan["push_speed_mm_s"] = round6(units::mToMm(setup.deploy.pushSpeed));
  plan["tip_force_threshold_mN"] = round6(units::nToMn(setup.deploy.forceThreshold));
  ordered_json coils = ordered_json::array();
  for (const CandidateResult& r : results) {
    ordered_json c;
    c["name"] = r.name;
    c["variant"] = r.variant;
    if (!r.sequence.empty()) c["sequence"] = r.sequence;
    c["ok"] = r.ok;
    if (!r.ok) c["error"] = r.error;
    c["placed"] = r.ok && r.deploy.placed;
    if (!r.deploy.notPlaced.empty()) c["not_placed"] = r.deploy.notPlaced;
    c["deployed_mm"] = round6(units::mToMm(r.deploy.deployed));
    c["packing_percent"] = round6(100 * r.sac.packingDensity);
    c["sac_volume_mm3"] = round6(units::m3ToMm3(r.sac.sacVolume));
    c["coil_volume_mm3"] = round6(units::m3ToMm3(r.sac.coilVolume));
    c["coil_length_in_sac_mm"] = round6(units::mToMm(r.sac.coilLengthInSac));
    c["neck_coverage_percent"] = round6(100 * r.sac.neckCoverage);
    c["protruding"] = r.sac.protruding;
    c["protruding_length_mm"] = round6(units::mToMm(r.sac.protrudingLength));
    // Without a contact effect there is no wall force to report: null, not 0.
    if (r.deploy.wallForcesAvailable) {
      // The sustained load (physics/contact/wall_load.h), as the window and the score sheet show it.
      c["max_wall_force_mN"] = round6(units::nToMn(r.deploy.wall.max));
      c["wall_load_window_ms"] = units::sToMs(kWallLoadWindow);
      c["mean_wall_force_mN"] = round6(units::nToMn(r.deploy.wall.mean()));
      c["peak_wall_force_mN"] = round6(units::nToMn(r.deploy.wall.peak));
      c["time_above_safety_s"] = round6(r.deploy.wall.timeAbove);
      c["max_wall_penetration_um"] = round6(units::mToUm(r.deploy.maxWallPenetration));
      c["max_wall_penetration_of_radius"] = round6(r.deploy.maxWallPenetrationOfRadius);
    } else {
      c["max_wall_force_mN"] = nullptr;
      c["mean_wall_force_mN"] = nullptr;
      c["peak_wall_force_mN"] = nullptr;
      c["time_above_safety_s"] = nullptr;
      c["max_wall_penetration_um"] = nullptr;
      c["max_wall_penetration_of_radius"] = nullptr;
    }
    c["kickback_mm"] = round6(units::mToMm(r.deploy.maxKickback));
    c["max_deployment_force_mN"] = round6(units::nToMn(r.deploy.maxDeploymentForce));
    c["max_tip_force_mN"] = round6(units::nToMn(r.deploy.maxTipForce));
    c["corrections"] = r.deploy.corrections;
    c["pull_backs"] = r.deploy.pullBacks;
    c["occlusion_class"] = r.occlusion;
    c["occlusion"] = occlusionClassName(r.occlusion);
    c["simulated_s"] = round6(r.deploy.time);
    c["wall_s"] = round6(r.wallSeconds);
    // Where the run's time went (docs/planning.md, issue 16).
    const AutoDeployResult::Effort& e = r.deploy.effort;
    c["steps"] = r.deploy.steps;
    c["substepped_steps"] = e.substepped;
    c["steps_by_phase"] = {{"pushing", e.pushing},       {"feeling", e.feeling},   {"twisting", e.twisting},
                           {"pausing", e.pausing},       {"pulling_back", e.pullingBack}, {"settling", e.settling},
                           {"after_detach", e.afterDetach}};
    c["step_wall_s"] = round6(e.stepSeconds);
    c["operator_wall_s"] = round6(e.operatorSeconds);
    coils.push_back(std::move(c));
  }
  plan["coils"] = std::move(coils);
  return plan;
}

namespace {

// Per coil with catheter variants (--sensitivity): the spread of the outcome over them.
std::string sensitivityMarkdown(const ordered_json& plan) {
  struct Spread {
    int runs = 0, placed = 0, protruding = 0;
    double lo = 1e300, hi = -1e300, wallHi = 0;
  };
  std::vector<std::pair<std::string, Spread>> coils;
  for (const auto& c : plan.at("coils")) {
    const std::string name = c.value("name", std::string("?"));
    auto it = std::find_if(coils.begin(), coils.end(), [&](const auto& e) { return e.first == name; });
    if (it == coils.end()) it = coils.insert(coils.end(), {name, Spread{}});
    Spread& s = it->second;
    ++s.runs;
    if (c.value("ok", false) && c.value("placed", true)) ++s.placed;
    if (c.value("protruding", false)) ++s.protruding;
    const double p = c.value("packing_percent", 0.0);
    s.lo = std::min(s.lo, p), s.hi = std::max(s.hi, p);
    if (c.contains("max_wall_force_mN") && c["max_wall_force_mN"].is_number())
      s.wallHi = std::max(s.wallHi, c["max_wall_force_mN"].get<double>());
  }
  if (std::none_of(coils.begin(), coils.end(), [](const auto& e) { return e.second.runs > 1; })) return "";
  std::string md = "\n## Sensitivity to the catheter position\n\n| coil | runs | placed | packing (min - max) | "
                   "protruding | max wall mN |\n|---|---|---|---|---|---|\n";
  char buf[512];
  for (const auto& [name, s] : coils) {
    if (s.runs < 2) continue;
    std::snprintf(buf, sizeof buf, "| %s | %d | %d of %d | %.1f - %.1f %% | %d of %d | %.3g |\n", name.c_str(), s.runs,
                  s.placed, s.runs, s.lo, s.hi, s.protruding, s.runs, s.wallHi);
    md += buf;
  }
  md += "\nA robust choice keeps its packing, protrusion and placement over the variants.\n";
  return md;
}

}  // namespace

std::string planMarkdown(const ordered_json& plan) {
  std::string md = "# Coil plan: " + plan.value("scene", std::string("?")) + "\n\n";
  char buf[768];
  std::snprintf(buf, sizeof buf, "Sac volume %.1f mm^3 (closed by the neck plane).\n\n",
                plan.value("sac_volume_mm3", 0.0));
  md += buf;
  md += "| coil | variant | placed | packing | coil vol. mm^3 | neck cov. | protruding | max wall mN | mean wall mN | "
        "kickback mm | push force mN | twists / pull-backs | class |\n";
  md += "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::string notes, images;
  auto number = [](const nlohmann::ordered_json& v, const char* format) {
    if (v.is_null()) return std::string("n/a");
    char w[32];
    std::snprintf(w, sizeof w, format, v.get<double>());
    return std::string(w);
  };
  for (const auto& c : plan.at("coils")) {
    const std::string name = c.value("name", std::string("?")), variant = c.value("variant", std::string("?"));
    const bool ok = c.value("ok", false), placed = c.value("placed", ok);
    const std::string placedText = !ok ? "failed" : placed ? "yes" : "no";
    std::snprintf(buf, sizeof buf, "| %s | %s | %s | %.1f %% | %.2f | %.0f %% | %s | %s | %s | %.3g | %.3g | %d / %d | %s |\n",
                  name.c_str(), variant.c_str(), placedText.c_str(), c.value("packing_percent", 0.0),
                  c.value("coil_volume_mm3", 0.0), c.value("neck_coverage_percent", 0.0),
                  c.value("protruding", false) ? "yes" : "no", number(c["max_wall_force_mN"], "%.3g").c_str(),
                  number(c["mean_wall_force_mN"], "%.3g").c_str(), c.value("kickback_mm", 0.0),
                  c.value("max_deployment_force_mN", 0.0), c.value("corrections", 0), c.value("pull_backs", 0),
                  c.value("occlusion", std::string("?")).c_str());
    md += buf;
    if (!ok) notes += "- " + name + " (" + variant + "): failed: " + c.value("error", std::string()) + "\n";
    else if (c.contains("not_placed")) notes += "- " + name + " (" + variant + "): not placed: " + c["not_placed"].get<std::string>() + "\n";
    if (c.contains("screenshot")) images += "![" + name + " (" + variant + ")](" + c["screenshot"].get<std::string>() + ")\n";
  }
  if (!notes.empty()) md += "\n" + notes;
  md += sensitivityMarkdown(plan);
  md += "\npacking = coil volume (pi r^2 times the coil length inside the sac) / sac volume; placed = pushed out "
        "fully and detached (the operator gives a coil up when the tip force stays high after twists and pull-backs); "
        "push force = largest axial force felt at the catheter tip with the pusher at rest; class: Raymond-Roy-like "
        "prediction from packing and neck coverage (thresholds in docs/planning.md); n/a: the run had no wall "
        "contact to measure.\n";
  if (!images.empty()) md += "\n" + images;
  return md;
}

ordered_json mergePlans(const std::vector<std::string>& files) {
  ordered_json merged;
  merged["format"] = "coilsim-plan/1";
  ordered_json coils = ordered_json::array();
  std::string scenes;
  for (const std::string& f : files) {
    const nlohmann::json doc = io::readJsonFile(f);
    const io::JsonNode root(doc, f);
    if (!root.isObject()) root.expected("a coilsim-plan/1 object");
    root.child("format").oneOf({"coilsim-plan/1"});
    const std::string scene = root.child("scene").string();
    if (scenes.empty()) {
      scenes = scene;
      merged["scene"] = scene;
      merged["sac_volume_mm3"] = root.child("sac_volume_mm3").number();
    } else if (scene != scenes) {
      root.child("scene").fail("plans of different scenes cannot be merged: \"" + scenes + "\" and \"" + scene + "\"");
    }
    for (const io::JsonNode& c : root.child("coils").items(0, SIZE_MAX, "an array of coil results")) {
      c.child("name").string();
      coils.push_back(ordered_json(c.value()));
    }
  }
  merged["coils"] = std::move(coils);
  return merged;
}

}  // namespace coilsim::planning
