#pragma once
// The contact part of `coilsim bench`: a 150 mm coil (300 beams) pushed at
// 10 mm/s into a sidewall aneurysm phantom of about 50,000 triangles with
// wall and self-contact on. Reports the mean step time with contacts, the
// part of it spent in contact detection, and the ratio to the contact-free
// step measured on the same states in the same run.
#include <functional>
#include <string>

namespace coilsim {

// Reports contact_step_us_n300, contact_detect_us_n300,
// contact_free_step_us_n300, contact_over_free_n300, contact_mesh_triangles
// contact_max_penetration_um and contact_max_penetration_of_radius (the
// run's own record of the deepest wall penetration) through `set`; prints a short table on
// stdout unless `json`. `quick` pushes 10 mm instead of 60 mm.
void benchContactFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json);

}  // namespace coilsim
