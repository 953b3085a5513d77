#pragma once
// The bracketed 1-D root finder of the contact solvers: regula falsi with the Anderson-Bjorck
// modification, safeguarded by bisection (Anderson & Bjorck 1973, BIT 13:253-264). When the
// same end of the bracket is kept twice in a row, its stored value is scaled by
// m = 1 - f(x_new)/f(x_prev), or by 1/2 when m <= 0 (Illinois halves it always; Galdino 2011
// compares the two). Header-only so that the callable inlines.

#include <cmath>

namespace wheelwear::contactgeom::detail {

struct RootResult {
  double x = 0.0;          // best abscissa found
  double fx = 0.0;         // f(x)
  int evaluations = 0;     // calls of f made here (the bracket values are not counted)
  bool converged = false;  // accept(f(x))
  // The final bracket, its ends in the order given (lo need not be below hi), with f's true
  // values there: the regula falsi scales the values it stores, these are never scaled, so
  // they can be compared (e.g. to pick the side of a jump nearer the root).
  double lo = 0.0, f_lo = 0.0;
  double hi = 0.0, f_hi = 0.0;
};

// Finds x in [lo, hi] with accept(f(x)), given f(lo) and f(hi) of opposite signs; accept is a
// predicate on f's value that holds at the root and on an interval around it.
// Terminates when accept(f(x)) (converged); when the bracket is narrower than x_tol (f may jump
// there: not converged, x is the end of the final bracket with the smaller |f|); or after
// max_evaluations calls (not converged, x is the point with the smallest |f| seen).
template <class F, class Accept>
RootResult find_root_bracketed_until(F&& f, double lo, double f_lo, double hi, double f_hi,
                                     Accept&& accept, double x_tol, int max_evaluations) {
  RootResult result;
  // An accepted end, else the one with the smaller |f|.
  const bool take_lo =
      accept(f_lo) != accept(f_hi) ? accept(f_lo) : std::abs(f_lo) <= std::abs(f_hi);
  result.x = take_lo ? lo : hi;
  result.fx = take_lo ? f_lo : f_hi;
  double true_lo = f_lo;
  double true_hi = f_hi;
  const auto finish = [&] {
    result.converged = accept(result.fx);
    result.lo = lo;
    result.f_lo = true_lo;
    result.hi = hi;
    result.f_hi = true_hi;
    return result;
  };
  if (accept(result.fx)) return finish();
  int side = 0;  // which end was replaced last: -1 lo, +1 hi, 0 by bisection
  // Progress since the last reference: the bracket's width and the least |f| then, and the
  // secant steps taken since. Two secant steps that neither halve the bracket nor cut the least
  // |f| to a quarter are followed by a bisection: a superlinear sequence never stalls that way,
  // while at a jump of f (where |f| cannot fall and regula falsi creeps towards one end) every
  // third step halves the bracket, closing it to x_tol in about 3 log2(width / x_tol) steps.
  double width_ref = std::abs(hi - lo);
  double f_ref = std::abs(result.fx);
  int secant_steps = 0;
  while (result.evaluations < max_evaluations && std::abs(hi - lo) > x_tol) {
    double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    // Safeguard: bisect when the secant point falls outside the open bracket or two secant
    // steps have not halved the bracket (regula falsi stagnation).
    const bool outside = !(x > std::fmin(lo, hi) && x < std::fmax(lo, hi));
    const bool bisect = outside || secant_steps >= 2;
    if (bisect) {
      x = 0.5 * (lo + hi);
      side = 0;
    }
    const double fx = f(x);
    ++result.evaluations;
    const bool accepted = accept(fx);
    if (accepted || std::abs(fx) < std::abs(result.fx)) {
      result.x = x;
      result.fx = fx;
    }
    if (accepted) break;
    if ((fx < 0.0) == (f_lo < 0.0)) {
      // x replaces lo. If lo was replaced last time too, hi is kept twice: scale f_hi down.
      // f_lo is then f at the previous iterate, unscaled.
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
    if (bisect || std::abs(hi - lo) <= 0.5 * width_ref || std::abs(result.fx) <= 0.25 * f_ref) {
      width_ref = std::abs(hi - lo);
      f_ref = std::abs(result.fx);
      secant_steps = 0;
    } else {
      ++secant_steps;
    }
  }
  if (!accept(result.fx) && std::abs(hi - lo) <= x_tol) {
    // Collapsed on a jump: answer next to it rather than wherever |f| happened to be least.
    result.x = std::abs(true_lo) <= std::abs(true_hi) ? lo : hi;
    result.fx = std::abs(true_lo) <= std::abs(true_hi) ? true_lo : true_hi;
  }
  return finish();
}

// As find_root_bracketed_until, accepting |f(x)| <= f_tol.
template <class F>
RootResult find_root_bracketed(F&& f, double lo, double f_lo, double hi, double f_hi, double f_tol,
                               double x_tol, int max_evaluations) {
  return find_root_bracketed_until(
      f, lo, f_lo, hi, f_hi, [f_tol](double v) { return std::abs(v) <= f_tol; }, x_tol,
      max_evaluations);
}

}  // namespace wheelwear::contactgeom::detail
