// Kalker's exact theory on wheel/rail patches found by contactgeom (wheel_rail_exact.hpp):
// against Hertz's closed form where the gap is nearly quadratic, against CONTACT's wheel/rail
// module (tests/data/contact, set d: S1002 on UIC60, Fz = 55 kN, y_ws = -8 ... 10 mm), and its
// refusal of bad input.

#include "wheelwear/tangential/exact/wheel_rail_exact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <numbers>
#include <string>

#include "support/contact_cases.hpp"
#include "support/reference_profiles.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::tangential {
namespace {

using testing::benchmark_pair;
namespace contact = testing::contact;

// The exact normal solve imposes the patch's normal force; its iteration stops at 1e-8 N.
constexpr double kImposedNormalForce = 1e-6;  // [relative]

// The single patch of the benchmark pair at lateral shift dy [m] under 55 kN.
contactgeom::WheelRailPatch only_patch(double dy) {
  contactgeom::WheelsetPose pose;
  pose.dy = dy;
  const auto c = contactgeom::solve_wheel_rail(benchmark_pair(), pose, 55e3);
  EXPECT_EQ(c.status, contactgeom::WheelRailStatus::ok) << c.message;
  EXPECT_EQ(c.patches.size(), 1u) << "dy " << dy;
  return c.patches.at(0);
}

// Semi-axes of the contact elements: half the extent of their centres plus one element.
struct Extent {
  double a = 0.0, b = 0.0;
};
Extent extent(const ExactSolution& s) {
  double x0 = 1.0, x1 = -1.0, y0 = 1.0, y1 = -1.0;
  const ElementGrid& g = s.grid;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      if (s.pn[static_cast<std::size_t>(j * g.nx + i)] > 0.0) {
        x0 = std::min(x0, g.x(i));
        x1 = std::max(x1, g.x(i));
        y0 = std::min(y0, g.y(j));
        y1 = std::max(y1, g.y(j));
      }
  return {0.5 * (x1 - x0 + g.dx), 0.5 * (y1 - y0 + g.dy)};
}

// On the tread (y_ws = 4 ... 8 mm: contact angle < 0.01 rad, KP's psi ~0.1) the gap is close to
// A x^2 + B s^2 with Hertz's A = cos(delta)/(2 R) and B from the profiles' curvatures at O
// (contactgeom's HertzSolution, from the profiles, not from the sampled gap). The exact
// solution must then be Hertz's: approach, peak pressure, semi-axes and area.
TEST(WheelRailExact, TreadContactMatchesHertz) {
  for (double y_ws : {4e-3, 6e-3, 8e-3}) {
    const contactgeom::WheelRailPatch p = only_patch(-y_ws);
    ASSERT_TRUE(p.hertz.has_value());
    contactgeom::WheelsetPose pose;
    pose.dy = -y_ws;
    const WheelRailExactSolution s = wheel_rail_exact(benchmark_pair(), pose, p, {}, 0.35);
    ASSERT_EQ(s.rolling.status, ExactStatus::converged) << s.rolling.message;
    const contactgeom::HertzSolution& hz = *p.hertz;
    const ElementGrid& g = s.rolling.grid;
    // The exact theory's approach and peak pressure for a quadratic gap on elements of about
    // a/15 lie within 0.4 % of Hertz (exact_normal_test: 0.1 % and 0.4 % on a/8), and the
    // gap departs from the quadratic by its cubic terms over the patch (psi ~ 0.1); measured
    // 0.3 % and 0.2 % at y_ws = 4 mm: bound 1.5 %.
    constexpr double kNearlyHertz = 0.015;  // [relative]
    EXPECT_NEAR(s.approach / hz.delta, 1.0, kNearlyHertz) << "y_ws " << y_ws;
    const double pmax = *std::max_element(s.rolling.pn.begin(), s.rolling.pn.end());
    EXPECT_NEAR(pmax / hz.p0, 1.0, kNearlyHertz) << "y_ws " << y_ws;
    // Semi-axes to the element (the edge lies somewhere in the outermost contact element) plus
    // 3 % for the asymmetric gap (measured at y_ws = 4 mm: a -0.08 mm, b +0.19 mm, with
    // elements of 0.38 and 0.35 mm).
    const Extent e = extent(s.rolling);
    EXPECT_NEAR(e.a, hz.a, g.dx + 0.03 * hz.a) << "y_ws " << y_ws;
    EXPECT_NEAR(e.b, hz.b, g.dy + 0.03 * hz.b) << "y_ws " << y_ws;
    // Area: one ring of boundary elements (perimeter times half an element) plus 3 %.
    const double ring = std::numbers::pi * (hz.a + hz.b) * 0.5 * std::max(g.dx, g.dy);
    EXPECT_NEAR(s.contact_area, hz.area(), ring + 0.03 * hz.area()) << "y_ws " << y_ws;
    EXPECT_NEAR(s.rolling.normal_force, p.normal_force, kImposedNormalForce * p.normal_force);
  }
}

// The gap at O: the least undeformed distance of the grid's rows lies at the patch's O (s = 0)
// and vanishes there (the approach's datum): within the quadratic's value one element away.
TEST(WheelRailExact, GapIsLeastAtTheInitialContactPoint) {
  const contactgeom::WheelRailPatch p = only_patch(-6e-3);
  contactgeom::WheelsetPose pose;
  pose.dy = -6e-3;
  const WheelRailExactSolution s = wheel_rail_exact(benchmark_pair(), pose, p, {}, 0.35);
  const ElementGrid& g = s.rolling.grid;
  const auto least = std::min_element(s.h.begin(), s.h.end());
  const int e = static_cast<int>(std::distance(s.h.begin(), least));
  EXPECT_LE(std::abs(g.y(e / g.nx)), g.dy);
  EXPECT_LE(std::abs(g.x(e % g.nx)), g.dx);
  const double one_element =
      p.hertz->delta * (std::pow(g.dx / p.hertz->a, 2.0) + std::pow(g.dy / p.hertz->b, 2.0));
  EXPECT_GE(*least, -1e-12);
  EXPECT_LE(*least, one_element);
}

// CONTACT's wheel/rail cases: its creepages (of the rail, body 1 there, at its reference
// point; moved to O by vx - phi s_icp) on our patch. Forces are compared normalised by each
// program's own normal force (ours from Kik-Piotrowski at Fz = 55 kN; CONTACT's FN also
// carries the vertical part of the tangential force, 9 % more in the flange contact).
//
// Measured on 40 x 40 elements, |F/(mu N) - CONTACT's| <= 0.75 % everywhere except y_ws = -2
// (2.7 %) and 0 (2.6 %). Where they differ, the gaps differ: on the tread contactgeom's gap is
// 2-11 % steeper across the patch than CONTACT's row minima (GapAgreesWithContactsOnTheTread),
// which profile smoothing (0, 0.3, 1 mm: rail crown R300 and wheel curvature unchanged to 1e-3)
// and the contact-plane projection (delta < 0.02 rad) do not explain; it makes our areas 1-3 %
// smaller and leaves the normalised forces within 1 %. At y_ws = 0 and -2 the patch is 11-20 mm
// wide over an almost flat gap whose far end differs in shape (at y_ws = 0, 11 mm from O:
// 23 um ours, 8.5 um CONTACT's), so the areas (y_ws = -2: +20 %) and forces differ more.
TEST(WheelRailExact, ForcesMatchContactsWheelRailCases) {
  // 1 % of mu N where the gaps agree in shape (CONTACT's own 0.2 -> 0.1 mm change: 0.65 %;
  // measured <= 0.75 %); 3.5 % where they do not (see above; measured 2.7 %).
  constexpr double kSameGapShape = 0.01, kOtherGapShape = 0.035;  // [mu N]
  std::size_t compared = 0;
  for (const contact::WheelRailCase& c : contact::wheel_rail_cases()) {
    const int y_ws = c.y_ws_mm;
    contactgeom::WheelsetPose pose;
    pose.dy = -c.y_ws;
    const contactgeom::WheelRailPatch p = only_patch(pose.dy);
    const Creepages at_O{c.creepages.vx - c.creepages.phi * c.s_icp, c.creepages.vy,
                         c.creepages.phi};
    WheelRailExactOptions options;
    // At y_ws = -2 the exact area reaches 1.3 times the Kik-Piotrowski patch on its field side.
    if (y_ws == -2) options.margin = 2.0;
    const WheelRailExactSolution s =
        wheel_rail_exact(benchmark_pair(), pose, p, at_O, c.mu, options);
    ASSERT_EQ(s.rolling.status, ExactStatus::converged) << s.rolling.message;
    const double ours = c.mu * p.normal_force, theirs = c.mu * c.FN;
    const double dx = std::abs(s.rolling.forces.Fx / ours - c.FX / theirs);
    const double ds = std::abs(s.rolling.forces.Fy / ours - c.FS / theirs);
    const double bound = (y_ws == 0 || y_ws == -2) ? kOtherGapShape : kSameGapShape;
    EXPECT_LT(dx, bound) << "y_ws " << y_ws;
    EXPECT_LT(ds, bound) << "y_ws " << y_ws;
    EXPECT_NEAR(s.rolling.normal_force, p.normal_force, kImposedNormalForce * p.normal_force);
    ++compared;
  }
  EXPECT_EQ(compared, contact::kWheelRailCases);
}

// The undeformed distance in CONTACT's planar contact (the plane inclined by the rail's angle
// averaged over the interpenetration, both profiles turned into it, the wheel moved down by its
// rigid approach): the exact normal solve on it at CONTACT's normal force FN and on CONTACT's
// 0.2 mm elements gives CONTACT's area and peak pressure in all ten cases, from the tread to
// the flank at 1.21 rad. Measured within 1.5 % and 2.1 % (y_ws = -8); bounds twice that. The
// plane at O with the vertical gap times its cosine gave 59.7 mm^2 on the flank (+11 %).
TEST(WheelRailExact, NormalSolveInContactsPlaneMatchesContact) {
  contactgeom::WheelRailOptions options;
  options.kp.penetration = contactgeom::KpPenetration::hertz_calibrated;
  options.contact_plane = contactgeom::ContactPlane::weighted;
  int compared = 0;
  for (const contact::WheelRailCase& row : contact::wheel_rail_cases()) {
    contactgeom::WheelsetPose pose;
    pose.dy = -row.y_ws;
    const auto c = contactgeom::solve_wheel_rail(benchmark_pair(), pose, 55e3, options);
    ASSERT_EQ(c.patches.size(), 1u) << "y_ws " << row.y_ws_mm;
    contactgeom::WheelRailPatch p = c.patches[0];
    p.normal_force = row.FN;
    WheelRailExactOptions grid;
    grid.margin = row.y_ws_mm == -2 ? 2.5 : 1.5;  // -2: the wedge-like gap (above)
    grid.nx = static_cast<int>(std::ceil(grid.margin * p.measures.length / row.dx));
    grid.ny = static_cast<int>(std::ceil(grid.margin * p.measures.width / row.ds));
    const WheelRailExactSolution s = wheel_rail_exact(benchmark_pair(), pose, p, {}, 0.35, grid);
    ASSERT_EQ(s.rolling.status, ExactStatus::converged) << s.rolling.message;
    const double pmax = *std::max_element(s.rolling.pn.begin(), s.rolling.pn.end());
    EXPECT_NEAR(s.contact_area / row.area, 1.0, 0.03) << "y_ws " << row.y_ws_mm;
    EXPECT_NEAR(pmax / row.p_max, 1.0, 0.04) << "y_ws " << row.y_ws_mm;
    compared += 2;
  }
  EXPECT_EQ(compared, 2 * contact::kWheelRailCases);
}

// The row minima of the sampled gap against CONTACT's (d_wheelrail_rows_dx0.2.csv, from O,
// linearly interpolated between its 0.2 mm rows) on the tread, y_ws = 2 ... 10 mm, where both
// are below 40 um: ours is steeper by a factor nearly constant over each patch, measured 1.08 ...
// 1.11 at y_ws = 2 mm falling to 1.02 ... 1.03 at 10 mm (see above). Bound: the factor within
// [1, 1.15] and its spread over one patch's rows below 0.05 (measured 0.027).
TEST(WheelRailExact, GapAgreesWithContactsOnTheTread) {
  int tread_cases = 0;
  for (const contact::WheelRailCase& c : contact::wheel_rail_cases()) {
    const int y_ws = c.y_ws_mm;
    if (y_ws < 2) continue;
    ++tread_cases;
    contactgeom::WheelsetPose pose;
    pose.dy = -c.y_ws;
    const contactgeom::WheelRailPatch p = only_patch(pose.dy);
    const WheelRailExactSolution s = wheel_rail_exact(benchmark_pair(), pose, p, {}, c.mu);
    std::map<double, double> reference;  // s from O [m] -> least distance of the row [m]
    for (const contact::WheelRailRow& r : c.rows) reference[r.s - c.s_icp] = r.h_min;
    const ElementGrid& g = s.rolling.grid;
    double lo = 10.0, hi = 0.0;
    int compared = 0;
    for (int j = 0; j < g.ny; ++j) {
      double least = 1.0;
      for (int i = 0; i < g.nx; ++i)
        least = std::min(least, s.h[static_cast<std::size_t>(j * g.nx + i)]);
      const auto above = reference.lower_bound(g.y(j));
      if (above == reference.begin() || above == reference.end()) continue;
      const auto below = std::prev(above);
      const double t = (g.y(j) - below->first) / (above->first - below->first);
      const double theirs = below->second + t * (above->second - below->second);
      if (theirs < 5e-6 || theirs > 40e-6) continue;  // near O both are rounding; far: lobes
      lo = std::min(lo, least / theirs);
      hi = std::max(hi, least / theirs);
      ++compared;
    }
    EXPECT_GT(compared, 3) << "y_ws " << y_ws;
    EXPECT_GE(lo, 1.0) << "y_ws " << y_ws;
    EXPECT_LE(hi, 1.15) << "y_ws " << y_ws;
    EXPECT_LE(hi - lo, 0.05) << "y_ws " << y_ws;
  }
  EXPECT_EQ(tread_cases, 5);  // y_ws = 2, 4, ..., 10 mm
}

// From the flange root onto the flank (dy 6 to 8 mm in 0.05 mm steps; S1002 on UIC60 at
// 55 kN, where CONTACT's y_ws = -8 case lies), the Hertz-calibrated patch in CONTACT's weighted
// plane against the exact normal solve on the same undeformed distance (both profiles turned
// into that plane): area within 10 %, pmax within 15 % (the bounds the flange-contact work sets).
// Measured at most 6.9 % and 4.9 % on the root (6.0-6.45 mm), 8.4 % and 4.0 % on the flank
// (6.9-8.0 mm). From 6.5 to 6.85 mm the contact passes from root to flank over the root's
// shelf, one connected patch 10 mm wide at 6.7 mm: the strips' patch is 10-22 % small and their
// pmax up to 40 % low there (one semi-ellipse per strip cannot carry the flank's peak beside the
// shelf's), and those steps are not compared here (docs/normal-contact.md).
TEST(WheelRailExact, HertzCalibratedPatchesFollowTheExactSolveOntoTheFlank) {
  contactgeom::WheelRailOptions options;
  options.kp.penetration = contactgeom::KpPenetration::hertz_calibrated;
  options.contact_plane = contactgeom::ContactPlane::weighted;
  WheelRailExactOptions grid;
  grid.nx = 60;
  grid.ny = 60;
  grid.margin = 2.5;
  double worst_area = 0.0, worst_pmax = 0.0;
  int compared = 0;
  for (int step = 0; step <= 40; ++step) {
    if (step >= 10 && step <= 17) continue;  // 6.5 ... 6.85 mm: the transition
    contactgeom::WheelsetPose pose;
    pose.dy = 6e-3 + step * 0.05e-3;
    const auto c = contactgeom::solve_wheel_rail(benchmark_pair(), pose, 55e3, options);
    ASSERT_EQ(c.status, contactgeom::WheelRailStatus::ok) << c.message;
    ASSERT_EQ(c.patches.size(), 1u) << "dy " << pose.dy;
    const contactgeom::WheelRailPatch& p = c.patches[0];
    const WheelRailExactSolution s = wheel_rail_exact(benchmark_pair(), pose, p, {}, 0.35, grid);
    ASSERT_EQ(s.rolling.status, ExactStatus::converged) << s.rolling.message;
    const double pmax = *std::max_element(s.rolling.pn.begin(), s.rolling.pn.end());
    const double area = p.measures.area / s.contact_area - 1.0;
    const double peak = p.pmax / pmax - 1.0;
    worst_area = std::max(worst_area, std::abs(area));
    worst_pmax = std::max(worst_pmax, std::abs(peak));
    EXPECT_LT(std::abs(area), 0.10) << "dy " << pose.dy;
    EXPECT_LT(std::abs(peak), 0.15) << "dy " << pose.dy;
    compared += 2;
  }
  RecordProperty("worst_area", std::to_string(worst_area));
  RecordProperty("worst_pmax", std::to_string(worst_pmax));
  EXPECT_EQ(compared, 2 * 33);
}

// With radius_variation each row's longitudinal creepage is the wheel's rolling radius departing
// from its tangent at O, over the rolling radius: against EN 13715's S1002 itself
// (s1002_nominal_z, the standard's sections, not the profile's spline) across the 23 mm wide
// tread patch of new S1002 on 60E1 1:40, centred, 100 kN, and the grid 1.3 times as wide. The
// profile's spline through the standard's points follows its sections to about 1 nm, so 2e-9
// of creepage (1 nm of radius) is the bound (measured 2e-11); the departure reaches 1.1e-3
// (0.5 mm of radius) at the grid's edges.
TEST(WheelRailExact, RadiusVariationIsTheTreadsDepartureFromItsTangentAtO) {
  const contactgeom::WheelRailPair pair(profiles::s1002(), profiles::rail_60e1());
  const contactgeom::WheelsetPose centred;
  const auto c = contactgeom::solve_wheel_rail(pair, centred, 100e3);
  ASSERT_EQ(c.patches.size(), 1u);
  const contactgeom::WheelRailPatch& p = c.patches[0];
  WheelRailExactOptions options;
  options.nx = 20;
  options.ny = 80;
  options.radius_variation = true;
  const WheelRailExactSolution s =
      wheel_rail_exact(pair, centred, p, {1e-3, 0.0, 0.0}, 0.3, options);
  ASSERT_EQ(s.row_vx.size(), static_cast<std::size_t>(s.rolling.grid.ny));

  const double y_O = -p.y_wheel;
  const double z_O = profiles::s1002_nominal_z(y_O);
  constexpr double kStep = 1e-6;  // [m] central difference of a polynomial section: exact to 1e-10
  const double slope =
      (profiles::s1002_nominal_z(y_O + kStep) - profiles::s1002_nominal_z(y_O - kStep)) /
      (2.0 * kStep);
  double largest = 0.0;
  for (int j = 0; j < s.rolling.grid.ny; ++j) {
    const double t = -s.rolling.grid.y(j) / std::sqrt(1.0 + slope * slope);  // along the tangent
    const double departure = profiles::s1002_nominal_z(y_O + t) - z_O - slope * t;
    const double expected = -departure / p.rolling_radius;
    EXPECT_NEAR(s.row_vx[static_cast<std::size_t>(j)], expected, 2e-9) << "row " << j;
    largest = std::max(largest, std::abs(expected));
  }
  EXPECT_GT(largest, 1e-3);  // the comparison spans a real departure

  // Off, the rows add nothing and the solution is the planar one.
  options.radius_variation = false;
  EXPECT_TRUE(wheel_rail_exact(pair, centred, p, {1e-3, 0.0, 0.0}, 0.3, options).row_vx.empty());
}

// Bad input is refused with a message that names it.
TEST(WheelRailExact, RefusesBadInput) {
  const contactgeom::WheelRailPatch p = only_patch(-4e-3);
  contactgeom::WheelsetPose pose;
  pose.dy = -4e-3;
  auto message = [&](const contactgeom::WheelRailPatch& patch, const Creepages& v, double mu,
                     const WheelRailExactOptions& options) -> std::string {
    try {
      wheel_rail_exact(benchmark_pair(), pose, patch, v, mu, options);
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  WheelRailExactOptions small;
  small.nx = 3;
  EXPECT_NE(message(p, {}, 0.35, small).find("nx"), std::string::npos);
  WheelRailExactOptions tight;
  tight.margin = 0.9;
  EXPECT_NE(message(p, {}, 0.35, tight).find("margin"), std::string::npos);
  EXPECT_NE(message(p, {}, std::nan(""), {}).find("mu"), std::string::npos);
  EXPECT_NE(message(p, {std::nan(""), 0.0, 0.0}, 0.35, {}), "accepted");
  contactgeom::WheelRailPatch bad = p;
  bad.contact_angle = std::nan("");
  EXPECT_NE(message(bad, {}, 0.35, {}).find("patch.contact_angle"), std::string::npos);
  bad = p;
  bad.measures.length = 0.0;
  EXPECT_NE(message(bad, {}, 0.35, {}).find("patch.measures.length"), std::string::npos);
  // A patch whose O lies off the profiles.
  bad = p;
  bad.y_rail = 1.0;
  EXPECT_NE(message(bad, {}, 0.35, {}).find("patch.y_rail"), std::string::npos);
  // The exact area outgrows a grid that only just covers the Kik-Piotrowski patch (margin 1):
  // the message names the edge and the fix.
  WheelRailExactOptions snug;
  snug.margin = 1.0;
  const std::string off_grid = message(p, {}, 0.35, snug);
  EXPECT_NE(off_grid.find("edge"), std::string::npos) << off_grid;
  EXPECT_NE(off_grid.find("increase margin"), std::string::npos) << off_grid;
}

}  // namespace
}  // namespace wheelwear::tangential
