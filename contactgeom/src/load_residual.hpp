#pragma once
// The residual of the contact solvers' load iterations and their stopping test on the load.

#include <cmath>

namespace wheelwear::contactgeom::detail {

// f = (F/F_target)^(2/3) - 1: nearly linear in the approach (Hertz: F ~ d^(3/2)), so that the
// regula falsi on it converges in a few steps; -1 where nothing is loaded.
inline double load_residual(double load, double target) {
  return std::pow(load / target, 2.0 / 3.0) - 1.0;
}

// The stopping test |F/F_target - 1| <= tol on the residual f: F/F_target = (1 + f)^(3/2)
// rises with f, so the test is below <= f <= above, with 1 -/+ tol mapped the same way.
struct LoadTolerance {
  double tol;
  double below = std::pow(1.0 - tol, 2.0 / 3.0) - 1.0;
  double above = std::pow(1.0 + tol, 2.0 / 3.0) - 1.0;
  bool operator()(double f) const { return f >= below && f <= above; }
  // The test on the loads themselves, for the final status.
  bool met(double load, double target) const { return std::abs(load / target - 1.0) <= tol; }
};

}  // namespace wheelwear::contactgeom::detail
