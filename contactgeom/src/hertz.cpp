#include "wheelwear/contactgeom/hertz.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "bracketed_root.hpp"
#include "wheelwear/contactgeom/elliptic_integrals.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

constexpr double kPi = std::numbers::pi;

void check_modulus(std::string_view field_E, double E, std::string_view field_nu, double nu) {
  require_finite(field_E, E);
  require_finite(field_nu, nu);
  require(E > 0.0, field_E, E, "Young's modulus must be positive (Pa)");
  require(nu >= 0.0 && nu < 0.5, field_nu, nu, "Poisson's ratio must lie in [0, 0.5)");
}

void check_curvatures(double A, double B, double E_star) {
  require_finite("A", A);
  require_finite("B", B);
  require_finite("E_star", E_star);
  require(A > 0.0, "A", A, "the relative curvature coefficient along x must be positive (1/m)");
  require(B > 0.0, "B", B, "the relative curvature coefficient along y must be positive (1/m)");
  require(E_star > 0.0, "E_star", E_star, "the combined modulus must be positive (Pa)");
}

// B/A as a function of the axis ratio k' = minor/major for the major axis along x:
// (E - k'^2 K) / (k'^2 (K - E)). It falls monotonically from infinity (k' -> 0) to 1 (k' = 1).
double curvature_ratio(double kc) {
  if (kc >= 1.0) return 1.0;
  const CompleteEllipticIntegrals e = complete_elliptic_integrals_kc(kc);
  return e.E_minus_kc2_K / (kc * kc * e.K_minus_E);
}

// Axis ratio k' = minor/major in (0, 1] for the curvature ratio r = B/A >= 1.
double axis_ratio(double r) {
  // Below this the ellipse is a circle to rounding (1 - k' ~ (r - 1)/1.5 near r = 1).
  if (r - 1.0 <= 4.0 * std::numeric_limits<double>::epsilon()) return 1.0;
  const double log_r = std::log(r);
  // f(t) = ln(B/A (k' = e^t)) - ln r falls monotonically in t; f(0) = -ln r < 0.
  auto f = [log_r](double t) { return std::log(curvature_ratio(std::exp(t))) - log_r; };
  // Bracket from the asymptote a/b ~ (B/A)^(2/3) (Johnson 1985, Section 4.2): the true k'
  // lies above r^(-2/3) for large r, so halving from there finds f > 0 in a few steps.
  double t_lo = -2.0 / 3.0 * log_r;
  double f_lo = f(t_lo);
  for (int i = 0; i < 200 && f_lo <= 0.0; ++i) {
    t_lo -= std::numbers::ln2;
    f_lo = f(t_lo);
  }
  if (f_lo <= 0.0) {
    // Unreachable for finite r: the ratio grows without bound as k' -> 0.
    throw std::logic_error("hertz: no axis ratio bracketed for B/A = " + std::to_string(r));
  }
  // Terminates when |f| <= 1e-14 (|d ln(B/A) / d ln k'| lies between 1.5 and 2, so k' is then
  // good to 1e-14 relative) or when the bracket in t is below 1e-15, the rounding noise of f.
  const detail::RootResult root =
      detail::find_root_bracketed(f, t_lo, f_lo, 0.0, -log_r, 1e-14, 1e-15, 200);
  return std::exp(root.x);
}

// Hertz solution for a unit normal force with the major axis along x (A <= B).
HertzSolution unit_load_major_x(double A, double B, double E_star) {
  const double kc = axis_ratio(B / A);
  const CompleteEllipticIntegrals e = complete_elliptic_integrals_kc(kc);
  const double m = (1.0 - kc) * (1.0 + kc);  // e^2
  // (K - E)/e^2 tends to pi/4 for the circle.
  const double k_minus_e_over_m = m > 0.0 ? e.K_minus_E / m : 0.25 * kPi;
  HertzSolution s;
  s.normal_force = 1.0;
  s.a = std::cbrt(3.0 * k_minus_e_over_m / (2.0 * kPi * E_star * A));
  s.b = kc * s.a;
  s.p0 = 3.0 / (2.0 * kPi * s.a * s.b);
  s.delta = s.p0 * s.b * e.K / E_star;
  return s;
}

// Hertz solution for a unit normal force, any A, B.
HertzSolution unit_load(double A, double B, double E_star) {
  if (A <= B) return unit_load_major_x(A, B, E_star);
  HertzSolution s = unit_load_major_x(B, A, E_star);
  std::swap(s.a, s.b);
  return s;
}

// Scales the unit-load solution: a, b, p0 ~ N^(1/3), delta ~ N^(2/3).
HertzSolution scaled(const HertzSolution& unit, double N) {
  HertzSolution s;
  const double c = std::cbrt(N);
  s.normal_force = N;
  s.a = unit.a * c;
  s.b = unit.b * c;
  s.p0 = unit.p0 * c;
  s.delta = unit.delta * c * c;
  return s;
}

}  // namespace

double HertzSolution::area() const {
  return kPi * a * b;
}

double combined_modulus(double E1, double nu1, double E2, double nu2) {
  check_modulus("E1", E1, "nu1", nu1);
  check_modulus("E2", E2, "nu2", nu2);
  return 1.0 / ((1.0 - nu1 * nu1) / E1 + (1.0 - nu2 * nu2) / E2);
}

double combined_modulus(double E, double nu) {
  check_modulus("E", E, "nu", nu);
  return E / (2.0 * (1.0 - nu * nu));
}

HertzSolution hertz_from_load(double A, double B, double E_star, double N) {
  check_curvatures(A, B, E_star);
  require_finite("N", N);
  require(N >= 0.0, "N", N, "the normal force must not be negative (N)");
  if (N == 0.0) return {};
  return scaled(unit_load(A, B, E_star), N);
}

HertzSolution hertz_from_approach(double A, double B, double E_star, double delta) {
  check_curvatures(A, B, E_star);
  require_finite("delta", delta);
  require(delta >= 0.0, "delta", delta, "the approach must not be negative (m)");
  if (delta == 0.0) return {};
  const HertzSolution unit = unit_load(A, B, E_star);
  HertzSolution s = scaled(unit, std::pow(delta / unit.delta, 1.5));
  s.delta = delta;  // exact, rather than the rounded round trip
  return s;
}

}  // namespace wheelwear::contactgeom
