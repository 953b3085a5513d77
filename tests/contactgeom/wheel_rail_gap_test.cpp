// The gap's placement of the wheel on its rail: the rail's gauge point and top, kept for the
// rails seen last, are the profile module's for every rail and gauge depth asked.

#include "wheel_rail_gap.hpp"

#include <gtest/gtest.h>

#include <utility>

#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::contactgeom::detail {
namespace {

TEST(WheelRailGap, GaugePointFollowsEveryChangeOfTheRail) {
  const WheelRailPair a(profiles::s1002(), profiles::rail_60e1());
  WheelRailPair moved = a;
  moved.rail = a.rail.translated(1e-3, 0.0);  // same parametrisation, other coefficients
  WheelRailPair deeper = a;
  deeper.gauge_depth = 0.016;
  // Three rails in turn, twice: more than the cache holds, and each answer exactly the one
  // profiles::gauge_point gives.
  for (int round = 0; round < 2; ++round) {
    for (const WheelRailPair* p : {&a, &std::as_const(moved), &std::as_const(deeper), &a}) {
      EXPECT_EQ(rail_gauge_y(*p), profiles::gauge_point(p->rail, p->gauge_depth).point.x());
      EXPECT_EQ(rail_datum(*p).top_z, profiles::top_of_rail(p->rail).point.y());
    }
  }
  // The translation moves it by the translation, to round-off.
  EXPECT_NEAR(rail_gauge_y(moved) - rail_gauge_y(a), 1e-3, 1e-15);
}

TEST(WheelRailGap, WalkedGapIsTheLookedUpGap) {
  const WheelRailPair pair(profiles::s1002(), profiles::rail_60e1());
  const WheelRailOptions options;
  for (double roll : {0.0, -2e-3}) {
    WheelsetPose pose;
    pose.dy = 3e-3;
    pose.roll = roll;
    const WheelRailGap gap(pair, pose, options, rail_gauge_y(pair));
    // The lookup maps a rolled point by Newton's method to 1e-13 m (wheel_at); the walk solves
    // on the rolled curve to 1e-15 m.
    for (double y = -0.03; y <= 0.01; y += 0.1e-3) {
      const auto walked = gap.walked_gap(y);
      const auto looked_up = gap.gap(y);
      ASSERT_EQ(walked.has_value(), looked_up.has_value()) << y;
      if (walked) {
        EXPECT_NEAR(walked->h, looked_up->h, 2e-13) << y;
      }
    }
    EXPECT_TRUE(gap.close_walks());
  }
}

}  // namespace
}  // namespace wheelwear::contactgeom::detail
