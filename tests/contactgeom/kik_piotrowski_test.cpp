// Kik-Piotrowski normal problem on strips: the Hertz limit (a gap that is exactly quadratic),
// KP's own closed form for that gap, convergence as the strips shrink, flat and shifted gaps,
// no-contact and bad input (several contact regions: kik_piotrowski_regions_test.cpp).

#include "wheelwear/contactgeom/kik_piotrowski.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_rf.hpp>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "kp_test_support.hpp"
#include "wheelwear/contactgeom/hertz.hpp"
#include "wheelwear/contactgeom/patch_measures.hpp"
#include "wheelwear/contactgeom/sdec_regularisation.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

constexpr double kPi = std::numbers::pi;
const double kEstar = combined_modulus(200e9, 0.25);
using kp_test::double_well;
using kp_test::format_number;
using kp_test::kA;
using kp_test::kLoad;
using kp_test::rel;
using kp_test::Strips;
using kp_test::with_epsilon;

// KP's own solution for the quadratic gap h = A x^2 + B s^2 (derived from the formulas in
// kik_piotrowski.hpp): the virtual patch is the ellipse a' = sqrt(eps delta/A),
// b' = sqrt(eps delta/B) with the Hertzian pressure shape, so I2 = 2 pi/3 a'^2 b' and
// I1 = a' pi beta K(e) (beta the minor semi-axis; Johnson 1985, Section 3.6), which gives
// delta^(3/2) = 3 N sqrt(min(A, B)) K(e) / (2 pi E* sqrt(eps)) and p_O = 3N/(2 pi a' b').
struct KpEllipse {
  double a, b, delta, p0;
};
KpEllipse kp_closed_form(double A, double B, double eps, double N) {
  const double lo = std::min(A, B), hi = std::max(A, B);
  const double K = boost::math::ellint_rf(0.0, lo / hi, 1.0);  // k'^2 = min/max
  const double delta =
      std::pow(3.0 * N * std::sqrt(lo) * K / (2.0 * kPi * kEstar * std::sqrt(eps)), 2.0 / 3.0);
  KpEllipse e;
  e.delta = delta;
  e.a = std::sqrt(eps * delta / A);
  e.b = std::sqrt(eps * delta / B);
  e.p0 = 3.0 * N / (2.0 * kPi * e.a * e.b);
  return e;
}

TEST(KikPiotrowski, HalfEpsilonOnACircularGapIsHertz) {
  // Circular-arc wheel on circular-arc rail with equal relative curvatures: Hertz's circle.
  // With eps = 1/2 the KP formulas are exact for it; what remains is the strip model's error
  // at the lateral edges, O(ds^1.5): 0.1 mm strips on an 11 mm patch.
  const double B = kA;
  const Strips s([B](double y) { return B * y * y; }, -8e-3, 8e-3, 1e-4);
  const KpResult r = solve_kp_load(s.gap, kEstar, kLoad, with_epsilon(0.5));
  ASSERT_EQ(r.status, KpStatus::converged) << r.message;
  ASSERT_EQ(r.patches.size(), 1u);
  const KpPatch& p = r.patches[0];
  const HertzSolution h = hertz_from_load(kA, B, kEstar, kLoad);
  const PatchMeasures m = measure_patch(p);
  RecordProperty("area_rel", format_number(m.area / h.area() - 1.0));
  RecordProperty("pmax_rel", format_number(p.pmax / h.p0 - 1.0));
  RecordProperty("a_rel", format_number(p.x_lead_O / h.a - 1.0));
  RecordProperty("delta_rel", format_number(r.approach / h.delta - 1.0));
  RecordProperty("width_minus_2b_mm", format_number((m.width - 2.0 * h.b) * 1e3));
  EXPECT_LT(rel(r.normal_force, kLoad), 2e-10);
  EXPECT_LT(rel(p.x_lead_O, h.a), 2e-3);           // strip model: O(ds^1.5) on the load
  EXPECT_LT(std::abs(m.width - 2.0 * h.b), 1e-4);  // one strip
  EXPECT_LT(rel(m.area, h.area()), 3e-3);
  EXPECT_LT(rel(p.p_O, h.p0), 3e-3);
  EXPECT_LT(rel(r.approach, h.delta), 3e-3);
  EXPECT_DOUBLE_EQ(p.pmax, p.p_O);
  EXPECT_NEAR(regularise_sdec(m).psi, 0.0, 1e-12);
}

struct EllipseCase {
  double b_over_a_curvature;  // B/A
  double tol;                 // strip-model tolerance on area, p_O, delta against closed form
  double area_bound;          // |KP area / Hertz area - 1|, closed-form value rounded up
  double p_bound;             // |KP p_O / Hertz p0 - 1|, likewise
};

class KpQuadraticGap : public ::testing::TestWithParam<EllipseCase> {};

TEST_P(KpQuadraticGap, MatchesItsClosedFormAndDeviatesFromHertzAsPredicted) {
  const EllipseCase c = GetParam();
  const double B = kA * c.b_over_a_curvature;
  const double eps = 0.55;
  const KpEllipse kp = kp_closed_form(kA, B, eps, kLoad);
  const HertzSolution hz = hertz_from_load(kA, B, kEstar, kLoad);
  const double ds = std::min(1e-4, kp.b / 40.3);  // at least 80 strips, edge off a centre
  // Strip centres at k ds, symmetric about the gap minimum.
  const double half_span = (std::ceil(1.3 * kp.b / ds) + 0.5) * ds;
  const Strips s([B](double y) { return B * y * y; }, -half_span, half_span, ds);
  const KpResult r = solve_kp_load(s.gap, kEstar, kLoad, with_epsilon(eps));
  ASSERT_EQ(r.status, KpStatus::converged) << r.message;
  ASSERT_EQ(r.patches.size(), 1u);
  const KpPatch& p = r.patches[0];
  const PatchMeasures m = measure_patch(p);

  // The numerical solution reproduces KP's closed form up to the strip model.
  EXPECT_LT(rel(m.area, kPi * kp.a * kp.b), c.tol);
  EXPECT_LT(rel(p.x_lead_O, kp.a), c.tol);
  EXPECT_LE(std::abs(m.width - 2.0 * kp.b), ds);  // the edge strip is in or out
  EXPECT_LT(rel(p.p_O, kp.p0), c.tol);
  EXPECT_LT(rel(r.approach, kp.delta), c.tol);
  // Symmetric gap on a symmetric grid: psi = 0 to rounding.
  EXPECT_NEAR(p.s_O, 0.0, 1e-15);
  EXPECT_NEAR(regularise_sdec(m).psi, 0.0, 1e-12);

  // Against Hertz, KP's patch keeps the gap's ellipse, a'/b' = sqrt(B/A), where Hertz's is
  // more slender (~ (B/A)^(2/3)), and eps = 0.55 over-sizes it slightly. The deviations are
  // those of the closed forms, recorded here and bounded below.
  const double area_dev = kp.a * kp.b / (hz.a * hz.b) - 1.0;
  const double p_dev = kp.p0 / hz.p0 - 1.0;
  RecordProperty("strip_model_area", format_number(m.area / (kPi * kp.a * kp.b) - 1.0));
  RecordProperty("strip_model_p0", format_number(p.p_O / kp.p0 - 1.0));
  RecordProperty("strip_model_delta", format_number(r.approach / kp.delta - 1.0));
  RecordProperty("kp_vs_hertz_area", format_number(area_dev));
  RecordProperty("kp_vs_hertz_pmax", format_number(p_dev));
  RecordProperty("kp_vs_hertz_a", format_number(kp.a / hz.a - 1.0));
  RecordProperty("kp_vs_hertz_b", format_number(kp.b / hz.b - 1.0));
  EXPECT_LT(std::abs(m.area / hz.area() - 1.0 - area_dev), 1.1 * c.tol);
  EXPECT_LT(std::abs(area_dev), c.area_bound);
  EXPECT_LT(std::abs(p_dev), c.p_bound);
}

// Closed-form deviations of KP (eps = 0.55) from Hertz: circle +6.6 % area, -6.2 % p0;
// B/A = 1.53 (a 460 mm wheel on a 300 mm crown) +6.9 %, -6.5 %; B/A = 10 or 1/10 +15.0 %,
// -13.1 %; near-conformal B/A = 1e-3 +49 %, -33 %. KP's patch keeps the gap's ellipse
// (a/b = sqrt(B/A)) where Hertz's is more slender, so the deviation grows with the ratio.
INSTANTIATE_TEST_SUITE_P(
    Ratios, KpQuadraticGap,
    ::testing::Values(EllipseCase{1.0, 3e-3, 0.07, 0.07}, EllipseCase{1.53, 3e-3, 0.07, 0.07},
                      EllipseCase{0.1, 3e-3, 0.16, 0.14}, EllipseCase{10.0, 3e-3, 0.16, 0.14},
                      EllipseCase{1e-3, 3e-3, 0.50, 0.34}),
    [](const ::testing::TestParamInfo<EllipseCase>& param_info) {
      std::string name = "B_over_A_" + format_number(param_info.param.b_over_a_curvature);
      for (char& ch : name) {
        if (ch == '.') ch = '_';
      }
      return name;
    });

TEST(KikPiotrowski, CircularGapDeviationFromHertzIsTheEpsilonEffect) {
  // Closed form for the circle: KP with eps is Hertz with R scaled by 2 eps, so at equal load
  // a grows by (2 eps)^(1/3) = 3.2 %, area by 6.6 %, p_O falls by 6.2 %, delta by 3.1 %.
  const KpEllipse kp = kp_closed_form(kA, kA, 0.55, kLoad);
  const HertzSolution hz = hertz_from_load(kA, kA, kEstar, kLoad);
  EXPECT_NEAR(kp.a / hz.a, std::cbrt(1.1), 1e-12);
  EXPECT_NEAR(kp.p0 / hz.p0, std::pow(1.1, -2.0 / 3.0), 1e-12);
  EXPECT_NEAR(kp.delta / hz.delta, std::pow(1.1, -1.0 / 3.0), 1e-12);
}

TEST(KikPiotrowski, AreaConvergesAsStripsShrink) {
  // Off-centre grid (O between strip centres) to exercise the parabola fit too.
  const double B = 2.0 * kA;
  const KpEllipse kp = kp_closed_form(kA, B, 0.55, kLoad);
  double coarsest = 0.0, finest = 0.0;
  for (double ds : {4e-4, 2e-4, 1e-4, 5e-5, 2.5e-5}) {
    const Strips s([B](double y) { return B * y * y; }, -8e-3, 8e-3, ds, kA, 0.3);
    const KpResult r = solve_kp_load(s.gap, kEstar, kLoad);
    ASSERT_EQ(r.status, KpStatus::converged);
    const PatchMeasures m = measure_patch(r.patches[0]);
    const double error = rel(m.area, kPi * kp.a * kp.b);
    // The strip model misses O(ds^1.5) at the lateral edges, with a coefficient that
    // oscillates with where the edge falls in its strip; measured 0.015 ... 0.15.
    EXPECT_LT(error, 0.25 * std::pow(ds / kp.b, 1.5)) << ds;
    if (coarsest == 0.0) coarsest = error;
    finest = error;
    // O is off the strip centres: the strip extents are lopsided by less than one strip.
    EXPECT_LT(std::abs(regularise_sdec(m).psi), ds / m.width) << ds;
    // The parabola through three samples of a quadratic gap finds O exactly.
    EXPECT_NEAR(r.patches[0].s_O, 0.0, 1e-12);
  }
  EXPECT_LT(finest, 0.1 * coarsest);  // 0.4 mm -> 0.025 mm: 6.8e-4 -> 6.8e-6 measured
  RecordProperty("area_error_at_25um", format_number(finest));
}

TEST(KikPiotrowski, PrescribedApproachAndLoadAgree) {
  const Strips s([](double y) { return 3.0 * y * y; }, -8e-3, 8e-3, 1e-4);
  const KpResult byload = solve_kp_load(s.gap, kEstar, kLoad);
  const KpResult byapproach = solve_kp_approach(s.gap, kEstar, byload.approach);
  ASSERT_EQ(byapproach.status, KpStatus::converged);
  EXPECT_LT(rel(byapproach.normal_force, kLoad), 2e-10);
  EXPECT_EQ(byapproach.patches[0].strips.size(), byload.patches[0].strips.size());
  // Converges in a handful of evaluations: the iteration variable is nearly linear.
  EXPECT_LE(byload.evaluations, 8);
  RecordProperty("evaluations", byload.evaluations);
}

TEST(KikPiotrowski, GapDatumAndUnitsDoNotMatter) {
  // The same contact in metres with an offset gap datum, and in millimetres (N/mm^2, 1/mm).
  // Grid offset by 0.3 strips so that no strip lies exactly on a switch of the influence
  // quadrature (2, 4, 8 widths from O), where rounding alone could pick either rule.
  const double B = 3.0;
  const Strips si([B](double y) { return B * y * y - 2e-4; }, -8e-3, 8e-3, 1e-4, kA, 0.3);
  const KpResult r = solve_kp_load(si.gap, kEstar, kLoad);
  std::vector<double> h_mm, ax_mm;
  for (double v : si.h) h_mm.push_back((v + 2e-4) * 1e3);
  for (double v : si.ax) ax_mm.push_back(v * 1e-3);
  GapStrips mm{si.gap.s_first * 1e3, si.gap.ds * 1e3, h_mm, ax_mm};
  const KpResult r_mm = solve_kp_load(mm, kEstar * 1e-6, kLoad);
  ASSERT_EQ(r.status, KpStatus::converged);
  ASSERT_EQ(r_mm.status, KpStatus::converged);
  // Only the load iteration's tolerance (1e-10 on (N/N_target)^(2/3)) separates them.
  EXPECT_LT(rel(r_mm.approach * 1e-3, r.approach + 2e-4), 1e-9);
  EXPECT_LT(rel(r_mm.pmax * 1e6, r.pmax), 1e-9);
  EXPECT_LT(rel(measure_patch(r_mm.patches[0]).area * 1e-6, measure_patch(r.patches[0]).area),
            1e-9);
}

// A double well: tread-like minimum at s = -6 mm (h = 0) and flange-like minimum at s = +9 mm
// (h = h2), separated by a hump.
TEST(KikPiotrowski, FlatGapHasNoNaNAndPutsOInTheMiddle) {
  // h = 0 over 6 mm, rising quadratically outside: O is undefined inside the flat part; the
  // solver takes the middle of the tie, and everything stays finite.
  auto flat = [](double y) {
    const double d = std::max(0.0, std::abs(y) - 3e-3);
    return 50.0 * d * d;
  };
  const Strips s(flat, -10e-3, 10e-3, 1e-4);
  const KpResult r = solve_kp_load(s.gap, kEstar, kLoad);
  ASSERT_EQ(r.status, KpStatus::converged) << r.message;
  ASSERT_EQ(r.patches.size(), 1u);
  const KpPatch& p = r.patches[0];
  EXPECT_NEAR(p.s_O, 0.0, 1e-15);
  const PatchMeasures m = measure_patch(p);
  EXPECT_GT(m.width, 6e-3);
  for (const KpStrip& strip : p.strips) {
    EXPECT_TRUE(std::isfinite(strip.x_lead) && std::isfinite(strip.p_peak));
  }
  EXPECT_TRUE(std::isfinite(r.pmax) && r.pmax > 0.0);
}

TEST(KikPiotrowski, ShiftingTheGapMovesThePatchWithoutJumps) {
  // A smooth asymmetric gap shifted by fractions of a strip: O follows through the parabola
  // fit and the measures change only by the strip model's ripple.
  auto gap = [](double y) { return y < 0.0 ? 2.0 * y * y : 1.0 * y * y + 20.0 * y * y * y; };
  double area0 = 0.0;
  double previous_offset = 0.0;
  for (int k = 0; k <= 10; ++k) {
    const double shift = k * 1e-5;  // 0 ... 0.1 mm in 10 um steps
    const Strips s([&](double y) { return gap(y - shift); }, -10e-3, 10e-3, 1e-4);
    const KpResult r = solve_kp_load(s.gap, kEstar, kLoad);
    ASSERT_EQ(r.status, KpStatus::converged);
    const PatchMeasures m = measure_patch(r.patches[0]);
    // The parabola fit of a gap whose curvature jumps at its minimum is biased by up to a
    // quarter strip, but the bias changes smoothly as the gap moves (here < 0.05 strip/step).
    const double offset = r.patches[0].s_O - shift;
    EXPECT_LT(std::abs(offset), 0.25e-4) << k;
    if (k > 0) {
      EXPECT_LT(std::abs(offset - previous_offset), 0.05e-4) << k;
    }
    previous_offset = offset;
    if (k == 0) area0 = m.area;
    EXPECT_LT(rel(m.area, area0), 3e-3) << k;  // ripple of the strip model
  }
}

TEST(KikPiotrowski, NoContactIsAStatus) {
  const Strips s([](double y) { return 3.0 * y * y + 1e-4; }, -8e-3, 8e-3, 1e-4);
  const KpResult below = solve_kp_approach(s.gap, kEstar, 0.5e-4);
  EXPECT_EQ(below.status, KpStatus::no_contact);
  EXPECT_TRUE(below.patches.empty());
  EXPECT_EQ(below.normal_force, 0.0);
  EXPECT_FALSE(below.message.empty());
  EXPECT_EQ(solve_kp_load(s.gap, kEstar, 0.0).status, KpStatus::no_contact);

  const Strips none([](double) { return std::numeric_limits<double>::infinity(); }, -1e-3, 1e-3,
                    1e-4);
  const KpResult r = solve_kp_load(none.gap, kEstar, kLoad);
  EXPECT_EQ(r.status, KpStatus::no_contact);
  EXPECT_FALSE(std::isnan(r.approach));
}

TEST(KikPiotrowski, ReusedResultEqualsFreshResult) {
  const Strips a([](double y) { return double_well(y, 5e-6); }, -20e-3, 20e-3, 1e-4);
  const Strips b([](double y) { return 3.0 * y * y; }, -8e-3, 8e-3, 1e-4);
  KpResult reused;
  solve_kp_load(a.gap, kEstar, kLoad, {}, reused);
  solve_kp_load(b.gap, kEstar, kLoad, {}, reused);
  const KpResult fresh = solve_kp_load(b.gap, kEstar, kLoad);
  ASSERT_EQ(reused.patches.size(), fresh.patches.size());
  EXPECT_EQ(reused.approach, fresh.approach);
  EXPECT_EQ(reused.patches[0].strips.size(), fresh.patches[0].strips.size());
  EXPECT_EQ(reused.patches[0].pmax, fresh.patches[0].pmax);

  KpResult reused_approach;
  solve_kp_approach(a.gap, kEstar, fresh.approach, {}, reused_approach);
  solve_kp_approach(b.gap, kEstar, fresh.approach, {}, reused_approach);
  const KpResult fresh_approach = solve_kp_approach(b.gap, kEstar, fresh.approach);
  ASSERT_EQ(reused_approach.patches.size(), 1u);
  EXPECT_EQ(reused_approach.normal_force, fresh_approach.normal_force);
  EXPECT_EQ(reused_approach.patches[0].strips.size(), fresh_approach.patches[0].strips.size());
  solve_kp_approach(b.gap, kEstar, -1.0, {}, reused_approach);
  EXPECT_EQ(reused_approach.status, KpStatus::no_contact);
  EXPECT_TRUE(reused_approach.patches.empty());
}

TEST(KikPiotrowski, RejectsBadInput) {
  Strips s([](double y) { return 3.0 * y * y; }, -8e-3, 8e-3, 1e-4);
  EXPECT_THROW(solve_kp_load(s.gap, kEstar, -1.0), InputError);
  EXPECT_THROW(solve_kp_load(s.gap, kEstar, std::nan("")), InputError);
  EXPECT_THROW(solve_kp_load(s.gap, 0.0, kLoad), InputError);
  EXPECT_THROW(solve_kp_approach(s.gap, kEstar, std::nan("")), InputError);
  EXPECT_THROW(solve_kp_load(s.gap, kEstar, kLoad, with_epsilon(0.0)), InputError);
  EXPECT_THROW(solve_kp_load(s.gap, kEstar, kLoad, with_epsilon(1.5)), InputError);

  GapStrips bad = s.gap;
  bad.ds = 0.0;
  EXPECT_THROW(solve_kp_load(bad, kEstar, kLoad), InputError);
  bad = s.gap;
  bad.ax = std::span<const double>(s.ax).first(3);
  EXPECT_THROW(solve_kp_load(bad, kEstar, kLoad), InputError);
  s.h[10] = std::nan("");
  EXPECT_THROW(solve_kp_load(s.gap, kEstar, kLoad), InputError);
  s.h[10] = -std::numeric_limits<double>::infinity();
  EXPECT_THROW(solve_kp_load(s.gap, kEstar, kLoad), InputError);
  s.h[10] = 0.0;
  s.ax[5] = 0.0;
  EXPECT_THROW(solve_kp_load(s.gap, kEstar, kLoad), InputError);
}

}  // namespace
}  // namespace wheelwear::contactgeom
