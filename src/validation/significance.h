#pragma once
// The significance threshold the diagnosis and the joint fit share.
#include <algorithm>

namespace coilsim::validation {

// chi^2_p quantile at 0.999 divided by p: the F(p, inf) critical value that
// a residual drop from p extra parameters must exceed (p clamped to 1..6).
inline double fCritical(int p) {
  static const double q[] = {10.83, 13.82, 16.27, 18.47, 20.52, 22.46};
  p = std::clamp(p, 1, 6);
  return q[p - 1] / p;
}

}  // namespace coilsim::validation
