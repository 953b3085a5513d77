#include "wheelwear/tangential/kalker_coefficients.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {

namespace {

// Kalker 1990, Table E.3, columns nu = 0, 0.25, 0.5 for C11, C22, C23. Checked value by value
// against the copy in CONTACT's m_hertz.f90 (subroutine linrol) and, for nu = 0.25, against
// Table 1 of Liu, Fu & Bruni 2022 (which confirms C23 = 1.25 at a/b = 0.8).
struct Row {
  std::array<double, 3> c11, c22, c23;
};

// Rows for a/b = 0.1, 0.2, ..., 1.0 (wide ellipses, a <= b).
constexpr std::array<Row, 10> kWide = {{
    {{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}},
    {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}},
    {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}},
    {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}},
    {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}},
    {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}},
    {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}},
    {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}},
    {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}},
    {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}},
}};

// Rows for b/a = 0.1, 0.2, ..., 1.0 (slender ellipses, a >= b).
constexpr std::array<Row, 10> kSlender = {{
    {{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}},
    {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}},
    {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}},
    {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}},
    {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}},
    {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}},
    {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}},
    {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}},
    {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}},
    {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}},
}};

// Quadratic through (0, 1/c0), (0.25, 1/c1), (0.5, 1/c2), inverted.
double interpolate_in_nu(const std::array<double, 3>& c, double nu) {
  const double l0 = (nu - 0.25) * (nu - 0.5) / ((0.0 - 0.25) * (0.0 - 0.5));
  const double l1 = (nu - 0.0) * (nu - 0.5) / ((0.25 - 0.0) * (0.25 - 0.5));
  const double l2 = (nu - 0.0) * (nu - 0.25) / ((0.5 - 0.0) * (0.5 - 0.25));
  return 1.0 / (l0 / c[0] + l1 / c[1] + l2 / c[2]);
}

// Table value at ratio r = min(a/b, b/a) in [0.1, 1] of the wide or slender half.
KalkerCoefficients from_table(const std::array<Row, 10>& rows, double r, double nu) {
  const double position = std::clamp(r * 10.0 - 1.0, 0.0, 9.0);
  const auto lower = std::min(static_cast<std::size_t>(position), std::size_t{8});
  const double w = position - static_cast<double>(lower);
  const Row& r0 = rows[lower];
  const Row& r1 = rows[lower + 1];
  auto blend = [w](const std::array<double, 3>& p, const std::array<double, 3>& q) {
    return std::array<double, 3>{(1 - w) * p[0] + w * q[0], (1 - w) * p[1] + w * q[1],
                                 (1 - w) * p[2] + w * q[2]};
  };
  return {interpolate_in_nu(blend(r0.c11, r1.c11), nu),
          interpolate_in_nu(blend(r0.c22, r1.c22), nu),
          interpolate_in_nu(blend(r0.c23, r1.c23), nu), false};
}

// Kalker's asymptotes for a/b -> 0 (g = a/b).
KalkerCoefficients wide_asymptote(double g, double nu) {
  constexpr double pi = std::numbers::pi;
  return {pi * pi / (4.0 * (1.0 - nu)), pi * pi / 4.0,
          pi * std::sqrt(g) / (3.0 * (1.0 - nu)) * (1.0 + nu * (std::log(16.0 / g) - 5.0)), true};
}

// Kalker's asymptotes for b/a -> 0 (g = b/a).
KalkerCoefficients slender_asymptote(double g, double nu) {
  constexpr double pi = std::numbers::pi;
  const double lambda = std::log(16.0 / (g * g));
  const double k = 3.0 - std::log(4.0);
  const double d11 = lambda - 2.0 * nu;
  const double d22 = (1.0 - nu) * lambda + 2.0 * nu;
  return {2.0 * pi / (d11 * g) * (1.0 + k / d11),
          2.0 * pi / (g * d22) * (1.0 + (1.0 - nu) * k / d22),
          2.0 * pi / (3.0 * std::pow(g, 1.5) * ((1.0 - nu) * lambda - 2.0 + 4.0 * nu)), true};
}

// The asymptote alone jumps by up to 5 % at the table's end (C23 at a/b = 0.1); scaling it by
// the ratio table/asymptote at the end row keeps every coefficient continuous in a/b, which
// the wear loop needs, and keeps the asymptotic growth rate.
KalkerCoefficients matched(KalkerCoefficients asym, KalkerCoefficients asym_end,
                           KalkerCoefficients table_end) {
  asym.c11 *= table_end.c11 / asym_end.c11;
  asym.c22 *= table_end.c22 / asym_end.c22;
  asym.c23 *= table_end.c23 / asym_end.c23;
  return asym;
}

}  // namespace

KalkerCoefficients kalker_coefficients(double a_over_b, double nu) {
  require_finite("a/b", a_over_b);
  require_finite("nu", nu);
  require(a_over_b > 0.0, "a/b", a_over_b, "the ellipse's semi-axes ratio must be positive");
  require(nu >= 0.0 && nu <= 0.5, "nu", nu, "Kalker's table covers Poisson's ratio 0 ... 0.5");
  constexpr double kEnd = 0.1;
  if (a_over_b <= 1.0) {
    if (a_over_b >= kEnd) return from_table(kWide, a_over_b, nu);
    return matched(wide_asymptote(a_over_b, nu), wide_asymptote(kEnd, nu),
                   from_table(kWide, kEnd, nu));
  }
  const double b_over_a = 1.0 / a_over_b;
  if (b_over_a >= kEnd) return from_table(kSlender, b_over_a, nu);
  return matched(slender_asymptote(b_over_a, nu), slender_asymptote(kEnd, nu),
                 from_table(kSlender, kEnd, nu));
}

}  // namespace wheelwear::tangential
