// Where a wheel rests when its gap has several minima (resting_gap.hpp): against the closed forms
// of equal Hertzian springs, continuous as one minimum overtakes another, and a minimum sharing
// nothing behind no ridge (a ripple) or where the roll's lever is long (the tread).
#include "resting_gap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace wheelwear::contactgeom::detail {
namespace {

constexpr double a = kSharedApproach;
constexpr double separate = std::numeric_limits<double>::infinity();  // another region

TEST(RestingGap, AMinimumOutOfReachLeavesTheTouchsGap) {
  // Bit for bit: the single-basin result is unchanged.
  EXPECT_EQ(resting_gap(3e-4, {}), 3e-4);
  EXPECT_EQ(resting_gap(3e-4, {{3e-4 + a, separate}, {3e-4 + 2.0 * a, separate}}), 3e-4);
  // Within reach but behind no ridge (born on a slope): no share.
  EXPECT_EQ(resting_gap(3e-4, {{3e-4 + 0.1 * a, 0.0}}), 3e-4);
}

TEST(RestingGap, EqualMinimaShareTheLoadAsEqualSprings) {
  // n minima at the same depth: n (H - h)^(3/2) = a^(3/2), H - h = a n^(-2/3).
  int compared = 0;
  for (int n = 2; n <= 4; ++n) {
    const std::vector<RestingMinimum> others(static_cast<std::size_t>(n - 1), {-1e-4, separate});
    EXPECT_NEAR(resting_gap(-1e-4, others), -1e-4 + a * (std::pow(n, -2.0 / 3.0) - 1.0), 1e-11 * a)
        << n;
    ++compared;
  }
  // Two minima d apart, the second behind a ridge of half the approach (weight 1/2):
  // (H - h)^(3/2) + (H - h - d)^(3/2) / 2 = a^(3/2) holds at the answer.
  const double d = 0.3 * a;
  const double H = resting_gap(0.0, {{d, 0.5 * a}}) + a;
  EXPECT_NEAR(std::pow(H, 1.5) + 0.5 * std::pow(H - d, 1.5), std::pow(a, 1.5),
              1e-10 * std::pow(a, 1.5));
  EXPECT_EQ(compared + 1, 4);
}

TEST(RestingGap, MovesSmoothlyAsASecondMinimumOvertakesTheFirst) {
  // Two regions (a tread and a flank): the flank's minimum descends from 1.5 a above the tread's
  // to 1.5 a below it in steps of a/1000, the lower one being the touch. The resting gap starts
  // at the tread's, ends at the flank's, never rises, and its slope (against the flank's depth)
  // stays within [0, 1] and changes by at most a few per cent per step: no jump, no kink, also
  // where the touch changes hands.
  double previous = 0.0, previous_slope = 0.0, largest_slope_change = 0.0;
  int compared = 0;
  for (int k = 0; k <= 3000; ++k) {
    const double flank = 1.5 * a - k * a / 1000.0;
    const double rest =
        flank < 0.0 ? resting_gap(flank, {{0.0, separate}}) : resting_gap(0.0, {{flank, separate}});
    if (k == 0) EXPECT_EQ(rest, 0.0);
    if (k > 0) {
      const double slope = (previous - rest) / (a / 1000.0);
      EXPECT_GE(slope, -1e-6);
      EXPECT_LE(slope, 1.0 + 1e-6);
      if (k > 1)
        largest_slope_change = std::max(largest_slope_change, std::abs(slope - previous_slope));
      previous_slope = slope;
      ++compared;
    }
    previous = rest;
  }
  EXPECT_NEAR(previous, -1.5 * a, 1e-12);
  EXPECT_LT(largest_slope_change, 0.05);
  EXPECT_EQ(compared, 3000);
}

TEST(RestingGap, TheRollsLeverSetsWhetherAMinimumShares) {
  // lever = 1 - tan(angle) / tan(atan(D / r)): none from 0.6 (1.0 rad for a 0.46 m wheel on
  // standard gauge), all below 0.3 (1.16 rad), the smoothstep between.
  EXPECT_EQ(lever_share(1.0), 0.0);
  EXPECT_EQ(lever_share(0.6), 0.0);
  EXPECT_NEAR(lever_share(0.45), 0.5, 1e-15);
  EXPECT_EQ(lever_share(0.3), 1.0);
  EXPECT_EQ(lever_share(0.0), 1.0);
  // A minimum with no share leaves the touch's gap; half a share, half a spring.
  EXPECT_EQ(resting_gap(0.0, {{0.0, separate, 0.0}}), 0.0);
  const double H = resting_gap(0.0, {{0.0, separate, 0.5}}) + a;
  EXPECT_NEAR(1.5 * std::pow(H, 1.5), std::pow(a, 1.5), 1e-10 * std::pow(a, 1.5));
}

TEST(RestingGap, ARidgeBetweenTwoMinimaSetsTheirShare) {
  // A ripple beside the touch, as deep as it: no share behind no ridge, a full one behind a
  // ridge of the approach, and in between rising smoothly (the weight's smoothstep).
  EXPECT_EQ(resting_weight(0.0), 0.0);
  EXPECT_EQ(resting_weight(a), 1.0);
  EXPECT_EQ(resting_weight(0.5 * a), 0.5);
  const double alone = resting_gap(0.0, {});
  const double shared = resting_gap(0.0, {{0.0, separate}});
  const double half = resting_gap(0.0, {{0.0, 0.5 * a}});
  EXPECT_EQ(alone, 0.0);
  EXPECT_LT(shared, half);
  EXPECT_LT(half, alone);
}

}  // namespace
}  // namespace wheelwear::contactgeom::detail
