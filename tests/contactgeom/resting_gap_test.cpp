// Where a wheel of a wheelset rests when its gap has several minima (resting_gap.hpp): against
// the closed forms of equal Hertzian springs; a minimum on the tread, behind no ridge or steeper
// than the wheelset allows sharing nothing; and continuous as one minimum overtakes another, on
// sampled gaps as the roll's solve meets them.
#include "resting_gap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace wheelwear::contactgeom::detail {
namespace {

constexpr double a = kSharedApproach;
constexpr double none = std::numeric_limits<double>::infinity();  // no deeper minimum
// atan(D / r) of a 0.46 m wheel on standard gauge (D = 1.5 m between the taping points).
const double steepest = std::atan(1.5 / 0.46);

TEST(RestingGap, EqualMinimaShareTheLoadAsEqualSprings) {
  // n minima at the same depth: n (H - h)^(3/2) = a^(3/2), H - h = a n^(-2/3).
  int compared = 0;
  for (int n = 1; n <= 4; ++n) {
    const std::vector<RestingMinimum> minima(static_cast<std::size_t>(n), {-1e-4, none, 1.0});
    EXPECT_NEAR(resting_gap(minima), -1e-4 + a * (std::pow(n, -2.0 / 3.0) - 1.0), 1e-12) << n;
    ++compared;
  }
  // A second minimum d above the first with half a share: (H - h)^(3/2) + (H - h - d)^(3/2) / 2
  // = a^(3/2) at the answer.
  const double d = 0.3 * a;
  const double H = resting_gap({{0.0, none, 1.0}, {d, none, 0.5}}) + a;
  EXPECT_NEAR(std::pow(H, 1.5) + 0.5 * std::pow(H - d, 1.5), std::pow(a, 1.5),
              1e-10 * std::pow(a, 1.5));
  ++compared;
  // The lowest carries weight 1 whatever its own share and rise say.
  EXPECT_NEAR(resting_gap({{0.0, 0.0, 0.0}}), 0.0, 1e-12);
  ++compared;
  // Gaps far from the datum: the bisection ends (its bracket stops shrinking at rounding).
  EXPECT_NEAR(resting_gap({{0.3, none, 1.0}, {0.3 + 1e-6, none, 1.0}}), 0.3, a);
  ++compared;
  EXPECT_EQ(compared, 7);
}

TEST(RestingGap, TheRollsLeverAndTheRidgeSetAMinimumsShare) {
  // lever = 1 - tan(angle) / tan(steepest): no share from 0.6 (0.92 rad here), all below 0.3
  // (1.16 rad), tapering to none again over the last 0.05 before the steepest contact.
  EXPECT_NEAR(roll_lever(0.0, steepest), 1.0, 1e-15);
  EXPECT_NEAR(roll_lever(steepest, steepest), 0.0, 1e-12);
  EXPECT_EQ(lever_share(1.0), 0.0);
  EXPECT_EQ(lever_share(0.6), 0.0);
  EXPECT_NEAR(lever_share(0.45), 0.5, 1e-15);
  EXPECT_EQ(lever_share(0.3), 1.0);
  EXPECT_EQ(lever_share(0.05), 1.0);
  EXPECT_NEAR(lever_share(0.025), 0.5, 1e-15);
  EXPECT_EQ(lever_share(0.0), 0.0);
  // By the ridge: none behind no ridge, all behind one of the approach, the smoothstep between.
  EXPECT_EQ(resting_weight({0.0, 0.0, 1.0}), 0.0);
  EXPECT_EQ(resting_weight({0.0, 0.5 * a, 1.0}), 0.5);
  EXPECT_EQ(resting_weight({0.0, a, 1.0}), 1.0);
  EXPECT_EQ(resting_weight({0.0, a, 0.5}), 0.5);
}

// A sampled gap every 0.1 mm over 4 mm: a tread's basin (curvature 100 1/m, floor 0 at 1 mm)
// and a flank's (300 1/m, floor `flank` at 3 mm), the ridge between them near 2.3 mm; one
// window, or two split at 2 mm with the boundary sample in both (as the first touch samples
// windows that touch). Optionally a ripple at 0.2 mm, 20 um above the tread's floor behind a
// ridge of 4.5 um towards it.
struct SampledGap {
  GapSamples g;
  std::vector<double> angle;  // contact angle at each sample [rad]
  SampledGap(double flank, double flank_angle, bool windows, bool ripple = false) {
    g.dy = 0.1e-3;
    const auto sample = [&](double y, int window) {
      const double tread = 50.0 * (y - 1e-3) * (y - 1e-3);
      const double flank_basin = 150.0 * (y - 3e-3) * (y - 3e-3) + flank;
      const double ripple_basin = ripple ? 20e-6 + 2000.0 * (y - 0.2e-3) * (y - 0.2e-3) : none;
      g.y.push_back(y);
      g.h.push_back(std::min({tread, flank_basin, ripple_basin}));
      g.window.push_back(window);
      angle.push_back(y > 2e-3 ? flank_angle : 0.05);
    };
    for (int i = 0; i <= 40; ++i) {
      const double y = i * 1e-4;
      sample(y, windows && i > 20 ? 1 : 0);
      if (windows && i == 20) sample(y, 1);  // the boundary sample again, in the next window
    }
  }
  // The touch as the roll's solve finds it: the lowest sample.
  std::size_t touch() const {
    return static_cast<std::size_t>(std::min_element(g.h.begin(), g.h.end()) - g.h.begin());
  }
  double touch_gap() const { return g.h[touch()]; }
  double resting() const {
    return resting_gap(
        g, touch(), touch_gap(), steepest, [&](std::size_t j) { return angle[j]; },
        [&](std::size_t j) { return g.h[j]; });
  }
};

TEST(RestingGap, OnTheTreadOrBehindAGapTheTouchRestsAlone) {
  // Alone, bit for bit: a second basin 10 um up at the flange root (0.5 rad, lever 0.83),
  // whether the windows touch or not; steeper than the wheelset allows (1.3 rad > atan(D/r) =
  // 1.273); out of reach (60 um up); a ripple 20 um up on the tread (lever 0.98).
  for (const SampledGap& alone :
       {SampledGap(10e-6, 0.5, false), SampledGap(10e-6, 0.5, true), SampledGap(10e-6, 1.3, false),
        SampledGap(60e-6, 1.2, false), SampledGap(60e-6, 1.2, false, true)})
    EXPECT_EQ(alone.resting(), alone.touch_gap());
  // On a flank of 1.2 rad (lever 0.21), 10 um up behind a ridge 74 um above it (weight 1):
  // (H - 0)^(3/2) + (H - 10 um)^(3/2) = a^(3/2), the wheel sinking less than into one; the same
  // across touching windows.
  const SampledGap shared(10e-6, 1.2, false);
  const double H = shared.resting() + a;
  EXPECT_NEAR(std::pow(H, 1.5) + std::pow(H - 10e-6, 1.5), std::pow(a, 1.5),
              1e-9 * std::pow(a, 1.5));
  EXPECT_EQ(SampledGap(10e-6, 1.2, true).resting(), shared.resting());
}

TEST(RestingGap, MovesContinuouslyAsTheFlankOvertakesTheTread) {
  // The flank's floor descends from 60 um above the tread's to 60 um below it, in steps of
  // 0.05 um, on a flank of 1.2 rad; with and without touching windows, and with a ripple on
  // the tread's side (a third minimum, whose share follows the pair's lever whichever of the two
  // is the touch). The resting gap never rises, its steps stay within the floor's (a slope in
  // [0, 1]), and it ends at the flank's floor (the tread then 60 um up, out of reach).
  int compared = 0;
  for (const bool windows : {false, true})
    for (const bool ripple : {false, true}) {
      double previous = 0.0, largest = 0.0, last_touch = 0.0;
      const double step = 0.05e-6;
      for (int k = 0; k <= 2400; ++k) {
        const SampledGap gap(60e-6 - k * step, 1.2, windows, ripple);
        const double rest = gap.resting();
        last_touch = gap.touch_gap();
        if (k == 0) EXPECT_EQ(rest, 0.0);  // the tread's floor, alone
        if (k > 0) {
          EXPECT_LE(rest, previous + 1e-15) << k;
          largest = std::max(largest, previous - rest);
        }
        previous = rest;
      }
      EXPECT_LE(largest, step * (1.0 + 1e-6)) << windows << ripple;
      EXPECT_EQ(previous, last_touch) << windows << ripple;
      compared += 2;
    }
  EXPECT_EQ(compared, 8);
}

}  // namespace
}  // namespace wheelwear::contactgeom::detail
