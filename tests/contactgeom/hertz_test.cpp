// Hertz's elliptic contact: closed forms, the classical table of Hertz coefficients, and the
// defining equations re-evaluated with Boost.Math's (independent) elliptic integrals.

#include "wheelwear/contactgeom/hertz.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <cmath>
#include <numbers>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

constexpr double kPi = std::numbers::pi;
// The solver stops at |f| <= 1e-14 in ln(B/A); everything downstream is closed form, so results
// hold to ~1e-13 relative.
constexpr double kTight = 1e-12;

double rel(double a, double b) {
  return std::abs(a / b - 1.0);
}

const double kEstar = combined_modulus(200e9, 0.25);

TEST(Hertz, CombinedModulusOfIdenticalBodies) {
  EXPECT_NEAR(kEstar, 200e9 / (2.0 * (1.0 - 0.0625)), 1e-3);
  EXPECT_DOUBLE_EQ(combined_modulus(200e9, 0.25, 200e9, 0.25), kEstar);
  // A rigid counter-body leaves only one compliance.
  EXPECT_NEAR(combined_modulus(200e9, 0.3, 1e30, 0.0), 200e9 / 0.91, 1.0);
}

TEST(Hertz, CircularContactMatchesClosedForm) {
  // Two crowned bodies with relative radius R: A = B = 1/(2R); Johnson 1985, Section 4.2:
  // a = (3NR/(4E*))^(1/3), delta = a^2/R, p0 = 3N/(2 pi a^2).
  const double R = 0.3;
  const double N = 50e3;
  const HertzSolution h = hertz_from_load(0.5 / R, 0.5 / R, kEstar, N);
  const double a = std::cbrt(3.0 * N * R / (4.0 * kEstar));
  EXPECT_LT(rel(h.a, a), kTight);
  EXPECT_LT(rel(h.b, a), kTight);
  EXPECT_LT(rel(h.delta, a * a / R), kTight);
  EXPECT_LT(rel(h.p0, 1.5 * N / (kPi * a * a)), kTight);
  EXPECT_EQ(h.ellipse().psi, 0.0);
}

// Hertz coefficients m, n with a = m (3N/(4E*(A+B)))^(1/3), b = n (...)^(1/3) as functions of
// theta, cos(theta) = |B - A|/(A + B); three-digit table of Timoshenko & Goodier, Theory of
// Elasticity (1951), Section 140 (also Boresi & Schmidt, Advanced Mechanics of Materials).
struct TableRow {
  double theta_deg, m, n;
};
constexpr TableRow kTable[] = {{30, 2.731, 0.493}, {40, 2.136, 0.567}, {50, 1.754, 0.641},
                               {60, 1.486, 0.717}, {80, 1.128, 0.893}, {90, 1.000, 1.000}};

TEST(Hertz, ReproducesTheTableOfHertzCoefficients) {
  for (const TableRow& row : kTable) {
    SCOPED_TRACE(row.theta_deg);
    const double c = std::cos(row.theta_deg * kPi / 180.0);
    const double A = 1.0 - c;  // A + B = 2 [1/m]
    const double B = 1.0 + c;
    const double N = 1e4;
    const double scale = std::cbrt(3.0 * N / (4.0 * kEstar * (A + B)));
    const HertzSolution h = hertz_from_load(A, B, kEstar, N);
    // Half a unit in the table's last digit, plus rounding of the table itself.
    EXPECT_NEAR(h.a / scale, row.m, 6e-4);
    EXPECT_NEAR(h.b / scale, row.n, 6e-4);
  }
}

// Residuals of Hertz's three conditions, with the major axis along x and K, E from Carlson's
// forms: delta = p0 b K / E*, A = p0 b (K - E)/(E* a^2 e^2), B = p0 b (E/k'^2 - K)/(E* a^2 e^2)
// (Johnson 1985, Sections 3.6 and 4.2).
void expect_hertz_conditions(double A, double B, const HertzSolution& h) {
  const bool major_x = h.a >= h.b;
  const double major = major_x ? h.a : h.b;
  const double minor = major_x ? h.b : h.a;
  const double a_curv = major_x ? A : B;  // curvature along the major axis
  const double b_curv = major_x ? B : A;
  const double kc = minor / major;
  const double m = (1.0 - kc) * (1.0 + kc);
  const double K = boost::math::ellint_rf(0.0, kc * kc, 1.0);
  const double k_minus_e = m / 3.0 * boost::math::ellint_rd(0.0, kc * kc, 1.0);
  const double e_minus_kc2k = m * kc * kc / 3.0 * boost::math::ellint_rd(0.0, 1.0, kc * kc);
  const double base = h.p0 * minor / (kEstar * major * major * m);
  EXPECT_LT(rel(h.delta, h.p0 * minor * K / kEstar), 1e-11);
  EXPECT_LT(rel(a_curv, base * k_minus_e), 1e-11);
  EXPECT_LT(rel(b_curv, base * e_minus_kc2k / (kc * kc)), 1e-11);
  EXPECT_LT(rel(h.normal_force, 2.0 / 3.0 * kPi * h.a * h.b * h.p0), kTight);
}

TEST(Hertz, SatisfiesHertzConditionsForRatiosUpTo1e4) {
  for (double ratio : {1e-4, 1e-3, 0.01, 0.1, 0.5, 0.9, 1.1, 2.0, 10.0, 100.0, 1e3, 1e4}) {
    SCOPED_TRACE(ratio);
    const double A = 1.0 / (2.0 * 0.46);  // a 460 mm wheel
    const double B = A / ratio;
    const HertzSolution h = hertz_from_load(A, B, kEstar, 55e3);
    ASSERT_TRUE(std::isfinite(h.a) && std::isfinite(h.b) && std::isfinite(h.p0) &&
                std::isfinite(h.delta));
    expect_hertz_conditions(A, B, h);
    // Asymptote a/b ~ (B/A)^(2/3) for slender ellipses (Johnson 1985, Section 4.2): within a
    // factor 2 over the range, the log correction growing with the ratio.
    const double g = h.ellipticity();
    const double asymptote = std::pow(B / A, 2.0 / 3.0);
    EXPECT_GT(g / asymptote, 0.5);
    EXPECT_LT(g / asymptote, 2.0);
  }
}

TEST(Hertz, SwappingTheCurvaturesSwapsTheAxes) {
  const HertzSolution h1 = hertz_from_load(2.0, 7.0, kEstar, 1e4);
  const HertzSolution h2 = hertz_from_load(7.0, 2.0, kEstar, 1e4);
  EXPECT_DOUBLE_EQ(h1.a, h2.b);
  EXPECT_DOUBLE_EQ(h1.b, h2.a);
  EXPECT_DOUBLE_EQ(h1.p0, h2.p0);
  EXPECT_DOUBLE_EQ(h1.delta, h2.delta);
}

TEST(Hertz, NearlyCircularIsContinuous) {
  // No jump between the circle short-cut and the solved branch.
  const HertzSolution circle = hertz_from_load(1.0, 1.0, kEstar, 1e4);
  const HertzSolution near = hertz_from_load(1.0, 1.0 + 1e-9, kEstar, 1e4);
  EXPECT_LT(rel(near.a, circle.a), 1e-9);
  EXPECT_LT(rel(near.b, circle.b), 1e-9);
  EXPECT_LT(rel(near.delta, circle.delta), 1e-9);
}

TEST(Hertz, ApproachAndLoadAreInverse) {
  const HertzSolution byload = hertz_from_load(1.1, 15.0, kEstar, 72e3);
  const HertzSolution byapproach = hertz_from_approach(1.1, 15.0, kEstar, byload.delta);
  EXPECT_LT(rel(byapproach.normal_force, 72e3), kTight);
  EXPECT_LT(rel(byapproach.a, byload.a), kTight);
  EXPECT_LT(rel(byapproach.p0, byload.p0), kTight);
}

TEST(Hertz, ZeroLoadGivesZeroPatch) {
  const HertzSolution h = hertz_from_load(1.0, 2.0, kEstar, 0.0);
  EXPECT_EQ(h.a, 0.0);
  EXPECT_EQ(h.p0, 0.0);
  EXPECT_EQ(hertz_from_approach(1.0, 2.0, kEstar, 0.0).normal_force, 0.0);
}

TEST(Hertz, RejectsBadInput) {
  EXPECT_THROW(hertz_from_load(1.0, 2.0, kEstar, -1.0), InputError);
  EXPECT_THROW(hertz_from_load(1.0, 2.0, kEstar, std::nan("")), InputError);
  EXPECT_THROW(hertz_from_load(0.0, 2.0, kEstar, 1.0), InputError);
  EXPECT_THROW(hertz_from_load(1.0, -2.0, kEstar, 1.0), InputError);
  EXPECT_THROW(hertz_from_load(1.0, 2.0, 0.0, 1.0), InputError);
  EXPECT_THROW(hertz_from_approach(1.0, 2.0, kEstar, -1e-6), InputError);
  EXPECT_THROW(combined_modulus(200e9, 0.5), InputError);
  EXPECT_THROW(combined_modulus(-1.0, 0.3), InputError);
}

}  // namespace
}  // namespace wheelwear::contactgeom
