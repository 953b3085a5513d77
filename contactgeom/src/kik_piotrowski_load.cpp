// The Kik-Piotrowski normal problem under a prescribed load: the rigid approach that carries it
// (the solution at one approach is kik_piotrowski.cpp's).

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "bracketed_root.hpp"
#include "kik_piotrowski_eval.hpp"
#include "load_residual.hpp"
#include "wheelwear/contactgeom/elliptic_integrals.hpp"
#include "wheelwear/contactgeom/kik_piotrowski.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

constexpr double kPi = std::numbers::pi;

// First guess of the approach above the gap minimum: KP's own closed form for the quadratic gap
// h = A x^2 + B s^2 at the minimum strip. There the virtual patch is the ellipse
// a' = sqrt(eps delta/A), b' = sqrt(eps delta/B) with the Hertzian pressure shape, so
// I2 = 2 pi/3 a'^2 b' and I1 = a' pi beta K(e) (beta the minor semi-axis, k'^2 = min/max of
// A, B; Johnson 1985, Section 3.6), and N = pi E* delta I2/I1 gives
// delta^(3/2) = 3 N sqrt(min(A, B)) K(e) / (2 pi E* sqrt(eps)). B comes from the second
// difference of h, at least 1 % of A so that a flat gap still gives a finite guess. Only the
// number of iterations depends on the guess.
double initial_approach(const GapStrips& g, const detail::LowestStrip& m, double E_star, double N,
                        double eps) {
  const double a = g.ax[m.index];
  double b = 0.0;
  if (m.index > 0 && m.index + 1 < g.size() && std::isfinite(g.h[m.index - 1]) &&
      std::isfinite(g.h[m.index + 1])) {
    b = (g.h[m.index - 1] - 2.0 * g.h[m.index] + g.h[m.index + 1]) / (2.0 * g.ds * g.ds);
  }
  b = std::max(b, 0.01 * a);
  const double lo = std::min(a, b);
  const double hi = std::max(a, b);
  const double K = complete_elliptic_integrals_kc(std::sqrt(lo / hi)).K;
  return std::pow(3.0 * N * std::sqrt(lo) * K / (2.0 * kPi * E_star * std::sqrt(eps)), 2.0 / 3.0);
}

}  // namespace

void solve_kp_load(const GapStrips& gap, double E_star, double N, const KpOptions& options,
                   KpResult& result) {
  gap.validate();
  options.validate();
  detail::check_modulus(E_star);
  require_finite("N", N);
  require(N >= 0.0, "N", N, "the normal force must not be negative (N)");
  result.evaluations = 0;
  const detail::LowestStrip m = detail::lowest_strip(gap);
  if (m.index == gap.size()) {
    detail::set_no_contact(result, 0.0, "no strip has a finite gap: no potential contact");
    return;
  }
  if (N == 0.0) {
    detail::set_no_contact(result, m.h, "zero normal force");
    return;
  }
  // The first guess needs a factor; the circle's 1/2 where the patch chooses its own.
  const double eps = options.penetration == KpPenetration::fixed ? options.epsilon : 0.5;
  const detail::LoadTolerance met{options.load_tolerance};
  int evaluations = 0;
  // f(d) = (N(h_min + d)/N)^(2/3) - 1 is close to linear in the approach d (N ~ d^(3/2)) and
  // rises with d except where two contact regions merge. met(f): |N(h_min + d)/N - 1| <= tol.
  detail::EvaluationCache cache;
  auto f = [&](double d) {
    ++evaluations;
    return detail::load_residual(detail::total_load(gap, m.h + d, options, E_star, cache), N);
  };

  // Phase 1: secant steps from the closed-form guess until the root is met or bracketed. A
  // step that leaves [d/4, 4d] (or a flat secant) falls back to the linear model d/(f + 1);
  // while N is still zero (f = -1) d quadruples. Phase 1 gives up after a few steps that do not
  // halve |f| (N(delta) need not be monotone where contact regions merge).
  double d0 = initial_approach(gap, m, E_star, N, eps);
  double f0 = f(d0);
  double d1 = d0;
  double f1 = f0;
  if (!met(f0)) {
    d1 = f0 > -1.0 ? d0 / (1.0 + f0) : 4.0 * d0;
    f1 = f(d1);
  }
  int stalls = 0;
  while (!met(f1) && (f1 > 0.0) == (f0 > 0.0) && stalls < 3 &&
         evaluations < options.max_evaluations) {
    double next = f1 > -1.0 ? d1 / (1.0 + f1) : 4.0 * d1;
    if (f1 != f0) {
      const double secant = d1 - f1 * (d1 - d0) / (f1 - f0);
      if (secant > 0.25 * d1 && secant < 4.0 * d1) next = secant;
    }
    const double previous = std::abs(f1);
    d0 = d1;
    f0 = f1;
    d1 = next;
    f1 = f(d1);
    if (std::abs(f1) > 0.5 * previous) ++stalls;
  }
  if (!met(f1) && (f1 > 0.0) == (f0 > 0.0)) {
    // Phase 1 stalled: fall back to a guaranteed bracket. N = 0 at d = 0 (f = -1 exactly, no
    // evaluation needed) if some f > 0 is known; otherwise double d until N exceeds the load.
    if (f1 > 0.0) {
      d0 = 0.0;
      f0 = -1.0;
    } else {
      while (f1 <= 0.0 && evaluations < options.max_evaluations) {
        d0 = d1;
        f0 = f1;
        d1 *= 2.0;
        f1 = f(d1);
      }
    }
  }

  // The point that meets the load, else the one with the smaller |f|.
  const bool take0 = met(f0) != met(f1) ? met(f0) : std::abs(f0) <= std::abs(f1);
  double d = take0 ? d0 : d1;
  if (!met(take0 ? f0 : f1) && (f1 > 0.0) != (f0 > 0.0)) {
    // Phase 2 terminates when met(f), or on a bracket below 1e-13 of d (N jumps there, where
    // two contact regions merge), or at max_evaluations.
    d = detail::find_root_bracketed_until(f, d0, f0, d1, f1, met, 1e-13 * std::max(d0, d1),
                                          options.max_evaluations - evaluations)
            .x;
  }

  detail::fill_result(gap, m.h + d, options, E_star, cache, result);
  result.evaluations = evaluations;
  if (met.met(result.normal_force, N)) {
    result.status = KpStatus::converged;
    result.message.clear();
  } else {
    result.status = KpStatus::not_converged;
    result.message =
        "normal force " + std::to_string(result.normal_force) + " N instead of " +
        std::to_string(N) + " N after " + std::to_string(evaluations) +
        " evaluations (N(delta) jumps where contact regions merge, or the evaluation budget ran"
        " out)";
  }
}

KpResult solve_kp_load(const GapStrips& gap, double E_star, double N, const KpOptions& options) {
  KpResult result;
  solve_kp_load(gap, E_star, N, options, result);
  return result;
}

}  // namespace wheelwear::contactgeom
