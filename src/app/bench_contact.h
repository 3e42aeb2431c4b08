#pragma once
// The contact part of `coilsim bench`: a 150 mm coil (300 beams) pushed at
// 10 mm/s into a sidewall aneurysm phantom of about 50,000 triangles with
// wall and self-contact on. Reports, in thread CPU time, the mean step time
// with contacts, the contact detection alone, the same detection with every
// wall query made afresh (the baseline, whose contacts must be the same),
// and the step of the same deployment without contacts.
#include <functional>
#include <string>

namespace coilsim {

// Reports contact_step_us_n300, contact_detect_us_n300,
// contact_detect_fresh_us_n300, contact_detect_speedup_n300,
// contact_detect_mismatches (sampled steps whose wall contacts differ from
// the baseline's: 0 unless a shortcut is wrong), contact_free_step_us_n300,
// contact_over_free_n300, contact_mesh_triangles, contact_max_penetration_um
// and contact_max_penetration_of_radius (the run's own record of the deepest
// wall penetration) through `set`; prints a short table on stdout unless
// `json`. `quick` pushes 10 mm instead of 60 mm.
void benchContactFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json);

}  // namespace coilsim
