#pragma once
// Bracketed 1-D root finder for the contact solvers: regula falsi with the Anderson-Bjorck
// modification, safeguarded by bisection (Anderson & Bjorck 1973, BIT 13:253-264; see also
// Galdino 2011 for the comparison with Illinois). Header-only so that the callable inlines.

#include <cmath>

namespace wheelwear::contactgeom::detail {

struct RootResult {
  double x = 0.0;          // best abscissa found
  double fx = 0.0;         // f(x)
  int evaluations = 0;     // calls of f made here (the bracket values are not counted)
  bool converged = false;  // |f(x)| <= f_tol
};

// Finds x in [lo, hi] with |f(x)| <= f_tol, given f(lo) and f(hi) of opposite signs.
// Terminates when |f(x)| <= f_tol (converged); when the bracket is narrower than x_tol (f may
// jump there: not converged, x is the end of the final bracket with the smaller |f|); or after
// max_evaluations calls (not converged, x is the best point seen).
template <class F>
RootResult find_root_bracketed(F&& f, double lo, double f_lo, double hi, double f_hi, double f_tol,
                               double x_tol, int max_evaluations) {
  RootResult result;
  result.x = std::abs(f_lo) <= std::abs(f_hi) ? lo : hi;
  result.fx = std::abs(f_lo) <= std::abs(f_hi) ? f_lo : f_hi;
  if (std::abs(result.fx) <= f_tol) {
    result.converged = true;
    return result;
  }
  // The regula falsi uses scaled end values (Anderson-Bjorck); the true ones pick the answer.
  double true_lo = f_lo;
  double true_hi = f_hi;
  int side = 0;  // which end was replaced last: -1 lo, +1 hi
  double width_before = std::abs(hi - lo);
  while (result.evaluations < max_evaluations && std::abs(hi - lo) > x_tol) {
    double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    // Safeguard: bisect when the secant point falls outside the open bracket or the bracket
    // has not halved in the last three steps (regula falsi stagnation).
    const bool outside = !(x > std::fmin(lo, hi) && x < std::fmax(lo, hi));
    const bool stagnant = result.evaluations % 3 == 2 && std::abs(hi - lo) > 0.5 * width_before;
    if (result.evaluations % 3 == 2) width_before = std::abs(hi - lo);
    if (outside || stagnant) {
      x = 0.5 * (lo + hi);
      side = 0;
    }
    const double fx = f(x);
    ++result.evaluations;
    if (std::abs(fx) < std::abs(result.fx)) {
      result.x = x;
      result.fx = fx;
    }
    if (std::abs(fx) <= f_tol) break;
    if ((fx < 0.0) == (f_lo < 0.0)) {
      // x replaces lo. If lo was replaced last time too, scale f_hi down (Anderson-Bjorck).
      if (side == -1) {
        const double m = 1.0 - fx / f_lo;
        f_hi *= m > 0.0 ? m : 0.5;
      }
      lo = x;
      f_lo = fx;
      true_lo = fx;
      side = -1;
    } else {
      if (side == +1) {
        const double m = 1.0 - fx / f_hi;
        f_lo *= m > 0.0 ? m : 0.5;
      }
      hi = x;
      f_hi = fx;
      true_hi = fx;
      side = +1;
    }
  }
  result.converged = std::abs(result.fx) <= f_tol;
  if (!result.converged && std::abs(hi - lo) <= x_tol) {
    // Collapsed on a jump: answer next to it rather than wherever |f| happened to be least.
    result.x = std::abs(true_lo) <= std::abs(true_hi) ? lo : hi;
    result.fx = std::abs(true_lo) <= std::abs(true_hi) ? true_lo : true_hi;
  }
  return result;
}

}  // namespace wheelwear::contactgeom::detail
