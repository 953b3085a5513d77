// Honest wheel/rail contact states: vertical and lateral forces summed strip by strip with the
// local contact angle, and the status past_flange for contact beyond the flange's steepest point.
// S1002 on 60E1 1:40 at 55 kN unless said otherwise; the flange geometry and the strip forces are
// recomputed here from the profiles and the patches' strips, independently of the solver's own.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "support/csv_table.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::contactgeom {
namespace {

constexpr double kLoad = 55e3;
// WheelRailOptions::load_tolerance, the stopping test of the vertical force.
constexpr double kLoadTolerance = 1e-9;
// Sums of the same products in another order: rounding of a few hundred terms, 1e-16 each.
constexpr double kRoundOff = 1e-12;
// The slope a contact may lose past the steepest point and stay ok (kFlangeSlopeTolerance in
// contactgeom/src/wheel_rail_gap.hpp), and how far from that limit the classification here must
// agree with the solver's: its bisection places the limit to 1e-9 m of arc, the flange face turns
// 0.05 rad per mm, so 1e-3 rad is wide.
constexpr double kSlopeTolerance = 0.02;
constexpr double kClassificationMargin = 1e-3;

const WheelRailPair& s1002_on_60e1() {
  static const WheelRailPair pair(profiles::s1002(), profiles::rail_60e1());
  return pair;
}

WheelRailContact solve_at(const WheelRailPair& pair, double dy) {
  WheelsetPose pose;
  pose.dy = dy;
  return solve_wheel_rail(pair, pose, kLoad);
}

// Slope angle of the wheel surface at arc length s, atan(-dz/dy) [rad]: + where it rises towards
// the tread, as the active flank does.
double wheel_slope(const profiles::Profile& wheel, double s) {
  const profiles::Point t = wheel.tangent(s);
  return std::atan2(-t[1], t[0]);
}

// The active flank of a wheel, found here on a 0.01 mm grid: from the flange tip (largest z
// before the taping line) to the taping line, with its steepest point.
struct Flank {
  double s_tip = 0.0, s_steepest = 0.0, steepest = 0.0;  // [m], [m], [rad]
  std::vector<double> s, slope;                          // the grid [m] and slopes [rad]
};

Flank flank_of(const profiles::Profile& wheel) {
  Flank f;
  const double s_tape = wheel.surface_at(0.0)->s, step = 0.01e-3;
  double z_tip = -1.0;
  for (double s = 0.0; s <= s_tape; s += step) {
    if (wheel.position(s)[1] > z_tip) {
      z_tip = wheel.position(s)[1];
      f.s_tip = s;
    }
  }
  for (double s = f.s_tip; s <= s_tape; s += step) {
    f.s.push_back(s);
    f.slope.push_back(wheel_slope(wheel, s));
    if (f.slope.back() > f.steepest) {
      f.steepest = f.slope.back();
      f.s_steepest = s;
    }
  }
  return f;
}

// Where O lies against the flank's steepest point, with `margin` [rad] of slack towards `past`:
// beyond it towards the tip (or on the back face) and more than kSlopeTolerance less steep.
bool beyond_steepest(const Flank& f, const profiles::Profile& wheel, double s_O, double margin) {
  return s_O < f.s_steepest && wheel_slope(wheel, s_O) < f.steepest - kSlopeTolerance + margin;
}

// The contact angle gamma at the centre of every strip of a patch [rad], from the rail profile's
// slope there: the strip at s lies at rail-frame y = -y_rail - (s - s_O) cos(angle at O).
std::vector<double> strip_angles(const WheelRailPair& pair, const WheelRailPatch& p) {
  std::vector<double> gamma;
  const double c = std::cos(p.contact_angle);
  for (const KpStrip& strip : p.kp.strips) {
    const double y = -p.y_rail - (strip.s - p.kp.s_O) * c;
    gamma.push_back(std::atan(-pair.rail.surface_at(y)->dz_dy));
  }
  return gamma;
}

// The line load of a strip by numerical integration of its pressure, x = x_lead sin(t): the
// integrand p_peak x_lead cos^2(t) is a trigonometric polynomial, which the midpoint rule in t
// integrates exactly with more than two points.
double integrated_line_load(const KpStrip& strip) {
  const int n = 16;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double t = -0.5 * std::numbers::pi + (k + 0.5) * std::numbers::pi / n;
    sum += strip.pressure(strip.x_lead * std::sin(t)) * strip.x_lead * std::cos(t);
  }
  return sum * std::numbers::pi / n;
}

// A patch's forces from the integrated pressure and the strip angles of strip_angles [N].
struct Forces {
  double normal = 0.0, vertical = 0.0, lateral = 0.0;
};

Forces integrated_forces(const WheelRailPair& pair, const WheelRailPatch& p) {
  const std::vector<double> gamma = strip_angles(pair, p);
  Forces f;
  for (std::size_t j = 0; j < gamma.size(); ++j) {
    const double load = integrated_line_load(p.kp.strips[j]) * p.kp.ds;
    f.normal += load;
    f.vertical += load * std::cos(gamma[j]);
    f.lateral += load * std::sin(gamma[j]);
  }
  return f;
}

// (a), (b): from the tread (-8 mm) over the flange root and flank to past the flange tip (+30
// mm) in 0.1 mm steps. Every state is ok, load_jump or past_flange; past_flange exactly where a
// loaded patch has its O beyond the steepest point (by the flank found here, up to the margin);
// once past, no later state is ok; flank contact on the steepest stretch stays ok; every shift
// from 20 mm on (past the flange tip, contact angles 0.61 to 0.25 rad) is past_flange. The vertical
// force meets the load to the solver's tolerance at every ok and past_flange state, and equals the
// sum of the patches' shares to round-off.
TEST(WheelRailPastFlange, SweepFromTheTreadOverTheFlangeTip) {
  const WheelRailPair& pair = s1002_on_60e1();
  const Flank flank = flank_of(pair.wheel);
  // S1002's straight flank: 70 deg, between the R13 root and the R20 face.
  ASSERT_NEAR(flank.steepest, std::atan(2.747477419), 2e-3);
  int ok_on_steepest_stretch = 0, past = 0, jumps = 0;
  double last_ok = -1.0, first_past = 1.0;
  for (int step = -80; step <= 300; ++step) {
    const double dy = step * 1e-4;
    const WheelRailContact c = solve_at(pair, dy);
    ASSERT_TRUE(c.status == WheelRailStatus::ok || c.status == WheelRailStatus::load_jump ||
                c.status == WheelRailStatus::past_flange)
        << "dy " << dy << ": " << status_name(c.status) << ": " << c.message;
    bool surely_beyond = false, maybe_beyond = false;
    double shares = 0.0;
    for (const WheelRailPatch& p : c.patches) {
      surely_beyond |= beyond_steepest(flank, pair.wheel, p.s_wheel, -kClassificationMargin);
      maybe_beyond |= beyond_steepest(flank, pair.wheel, p.s_wheel, kClassificationMargin);
      shares += p.vertical_force;
    }
    EXPECT_NEAR(shares, c.vertical_force, kRoundOff * kLoad) << "dy " << dy;
    if (c.status == WheelRailStatus::load_jump) {
      // Where the regions merge the vertical force jumps over the load: the nearer side, said.
      ++jumps;
      EXPECT_GT(std::abs(c.vertical_force / kLoad - 1.0), kLoadTolerance) << "dy " << dy;
      EXPECT_NE(c.message.find(std::to_string(c.vertical_force)), std::string::npos) << c.message;
      EXPECT_FALSE(surely_beyond) << "dy " << dy;
      continue;
    }
    EXPECT_LE(std::abs(c.vertical_force / kLoad - 1.0), kLoadTolerance) << "dy " << dy;
    if (c.status == WheelRailStatus::ok) {
      EXPECT_FALSE(maybe_beyond) << "dy " << dy;
      EXPECT_TRUE(c.message.empty()) << c.message;
      last_ok = dy;
      for (const WheelRailPatch& p : c.patches)
        ok_on_steepest_stretch += p.contact_angle > flank.steepest - kSlopeTolerance;
    } else {
      EXPECT_TRUE(surely_beyond) << "dy " << dy;
      EXPECT_NE(c.message.find("flange"), std::string::npos) << c.message;
      first_past = std::min(first_past, dy);
      ++past;
    }
    if (dy >= 20e-3) {
      EXPECT_EQ(c.status, WheelRailStatus::past_flange) << "dy " << dy;
      EXPECT_LT(c.patches.front().contact_angle, 0.7) << "dy " << dy;
    }
  }
  EXPECT_LT(last_ok, first_past);
  // Flank contact from 6.7 to 8 mm: O on the straight flank, where the slope is the steepest.
  EXPECT_GE(ok_on_steepest_stretch, 10);
  EXPECT_GE(past, 200);
  EXPECT_LE(jumps, 4);
  RecordProperty("first_past_flange_dy_mm", std::to_string(first_past * 1e3));
}

// (c): where the flange root's and the flank's regions make one patch (6.6 to 6.75 mm), its
// strips span contact angles from 0.6 to 1.2 rad and one angle at O projects it wrongly: N cos
// misses the load by up to half. The strip-wise vertical force meets the load to the solver's
// tolerance, and both forces equal those integrated here from KpStrip::pressure and the rail's
// local slope to round-off (the midpoint rule is exact on the semi-ellipse, see above).
TEST(WheelRailStripForces, MergedRootAndFlankPatchCarriesTheLoad) {
  const WheelRailPair& pair = s1002_on_60e1();
  int merged = 0;
  double worst_one_angle = 0.0;
  for (int step = 0; step <= 40; ++step) {
    const double dy = 6.55e-3 + step * 0.005e-3;
    const WheelRailContact c = solve_at(pair, dy);
    ASSERT_EQ(c.status, WheelRailStatus::ok) << "dy " << dy << ": " << c.message;
    ASSERT_EQ(c.patches.size(), 1u) << "dy " << dy;
    const WheelRailPatch& p = c.patches[0];
    const double one_angle = p.normal_force * std::cos(p.contact_angle) / kLoad - 1.0;
    const std::vector<double> gamma = strip_angles(pair, p);
    const auto [lo, hi] = std::minmax_element(gamma.begin(), gamma.end());
    const Forces f = integrated_forces(pair, p);
    EXPECT_NEAR(f.normal, p.normal_force, kRoundOff * kLoad) << "dy " << dy;
    EXPECT_NEAR(f.vertical, p.vertical_force, kRoundOff * kLoad) << "dy " << dy;
    EXPECT_NEAR(f.lateral, p.lateral_force, kRoundOff * kLoad) << "dy " << dy;
    EXPECT_NEAR(f.vertical / kLoad, 1.0, kLoadTolerance + kRoundOff) << "dy " << dy;
    if (std::abs(one_angle) > 0.25) {
      EXPECT_GT(*hi - *lo, 0.4) << "dy " << dy;  // a patch over the root and the flank
      worst_one_angle = std::min(worst_one_angle, one_angle);
      ++merged;
    }
  }
  EXPECT_GE(merged, 10);
  EXPECT_LT(worst_one_angle, -0.4);
  RecordProperty("worst_one_angle_miss", std::to_string(worst_one_angle));
}

// (d): a single tread patch: with w(s) = q(s) ds / N and the load-weighted mean angle
// g = sum w gamma, Taylor's theorem with the linear term summing to zero gives
// |V/N - cos g|, |L/N - sin g| <= sum w (gamma - g)^2 / 2 <= D^2 / 2, D = max |gamma - g|: the
// strip-wise and one-angle forces agree to second order in the angle's spread. Against the angle
// at O, which need not be the mean, a first-order term remains:
// |V/N - cos(angle_O)| <= |sin(angle_O)| D_O + D_O^2 / 2, D_O = max |gamma - angle_O|.
// On the tread D < 0.06 rad (the widest patch, 0 mm, spans 0.056 rad of the 60E1 crown), so
// strip-wise and mean-angle projections differ by less than 2e-3 relative.
TEST(WheelRailStripForces, TreadPatchAgreesWithOneAngleToSecondOrder) {
  const WheelRailPair& pair = s1002_on_60e1();
  int compared = 0;
  double largest_spread = 0.0;
  for (int step = -16; step <= 8; ++step) {
    const double dy = step * 0.5e-3;
    const WheelRailContact c = solve_at(pair, dy);
    ASSERT_EQ(c.status, WheelRailStatus::ok) << "dy " << dy;
    ASSERT_EQ(c.patches.size(), 1u) << "dy " << dy;
    const WheelRailPatch& p = c.patches[0];
    ASSERT_LT(p.contact_angle, 0.2) << "dy " << dy;  // the tread
    const std::vector<double> gamma = strip_angles(pair, p);
    double mean = 0.0;
    for (std::size_t j = 0; j < gamma.size(); ++j)
      mean += p.kp.strips[j].line_load() * p.kp.ds * gamma[j];
    mean /= p.normal_force;
    double spread = 0.0, spread_O = 0.0;
    for (double g : gamma) {
      spread = std::max(spread, std::abs(g - mean));
      spread_O = std::max(spread_O, std::abs(g - p.contact_angle));
    }
    const double V = p.vertical_force / p.normal_force, L = p.lateral_force / p.normal_force;
    EXPECT_LE(std::abs(V - std::cos(mean)), 0.5 * spread * spread + kRoundOff) << "dy " << dy;
    EXPECT_LE(std::abs(L - std::sin(mean)), 0.5 * spread * spread + kRoundOff) << "dy " << dy;
    EXPECT_LE(
        std::abs(V - std::cos(p.contact_angle)),
        std::abs(std::sin(p.contact_angle)) * spread_O + 0.5 * spread_O * spread_O + kRoundOff)
        << "dy " << dy;
    EXPECT_LT(spread, 0.06) << "dy " << dy;
    largest_spread = std::max(largest_spread, spread);
    ++compared;
  }
  EXPECT_EQ(compared, 25);
  RecordProperty("largest_angle_spread_rad", std::to_string(largest_spread));
}

// A measured worn wheel (tests/data/measured) on 60E1: its fitted flank is wavy (slope waves of
// +-0.15 rad, 3 mm long) and steepest at a crest of 1.39 rad near its root, which the rail never
// reaches; the rail meets the flank tip-wards of it and the contact angle falls as the wheelset
// moves on (1.23 rad at 5.5 mm, 0.8 rad at 14 mm) with pmax up to 5.4 GPa: the flange climbs.
// None of these states is ok.
TEST(WheelRailPastFlange, MeasuredWornWheelClimbingItsRailIsNotOk) {
  profiles::LoadOptions options;
  options.read.body = profiles::Body::wheel;
  const WheelRailPair pair(
      profiles::load_profile(testing::test_data("measured/Car7216_0001r.whl"), options).profile,
      profiles::rail_60e1());
  int compared = 0;
  for (int step = 0; step <= 17; ++step) {
    const double dy = 5.5e-3 + step * 0.5e-3;
    const WheelRailContact c = solve_at(pair, dy);
    EXPECT_EQ(c.status, WheelRailStatus::past_flange) << "dy " << dy << ": " << c.message;
    ++compared;
  }
  EXPECT_EQ(compared, 18);
}

}  // namespace
}  // namespace wheelwear::contactgeom
