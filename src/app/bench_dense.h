#pragma once
// The dense-packing part of `coilsim bench`: 100-1500 mm of a 0.254 mm
// primary coil laid in nested spherical spirals in a 7 mm sac (planning's
// contacts: the sac as a wall, self and rod contact), every segment within
// the contact margin of its neighbours. Reports the step time against the
// length of coil in the sac, with the contact detection's part and the same
// detection with every wall query made afresh (the baseline, same states).
#include <functional>
#include <string>

namespace coilsim {

// Reports dense_step_us_<L>mm, dense_detect_us_<L>mm,
// dense_detect_fresh_us_<L>mm, dense_segments_<L>mm and dense_run_ok_<L>mm
// (thread CPU time) through `set`; prints a table on stdout unless `json`.
// `quick`: 100 and 500 mm only, 5 steps each. Then the sleeping-coil case
// (physics/sleep.h): N mm asleep + about 100 mm awake sliding at 5 mm/s,
// against the same all awake (dense_sleeping_step_us_<N>mm,
// dense_sleeping_all_awake_step_us_<N>mm; N = 250, 500, 1000, quick: 250).
void benchDenseFigures(const std::function<void(const std::string&, double)>& set, bool quick, bool json);

}  // namespace coilsim
