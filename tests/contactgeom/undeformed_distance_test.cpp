// The undeformed distance over the track plane: a circle's sag along x, the gap that
// first_touch() minimises at x = 0, the lead of a yawed wheel's contact point, and the lateral
// creepage of the rigid slip there.

#include "wheelwear/contactgeom/undeformed_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "wheelwear/contactgeom/kinematics.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::contactgeom {
namespace {

const WheelRailPair& s1002_on_60e1() {
  static const WheelRailPair pair(profiles::s1002(), profiles::rail_60e1());
  return pair;
}

// The rail-frame y of the wheel profile's y = 0 at lateral shift dy (wheel_rail.hpp's placement).
double taping_point_y(const WheelRailPair& pair, double dy) {
  return profiles::gauge_point(pair.rail, pair.gauge_depth).point.x() -
         0.5 * (pair.gauge - pair.back_to_back) - pair.flange_back_y + dy;
}

// Without roll and yaw each cross-section of the wheel along x is a circle of the rolling radius
// R: the distance grows by its sag R - sqrt(R^2 - x^2). Newton's method meets the point to
// 1e-14 m; the sag is exact to round-off.
TEST(UndeformedDistance, GrowsByTheWheelsSagAlongX) {
  const WheelRailPair& pair = s1002_on_60e1();
  WheelsetPose pose;
  pose.dy = 3e-3;
  const double z_tape = pair.wheel.surface_at(0.0)->z;
  for (double y : {-0.02, -0.005, 0.0, 0.01}) {
    const auto h0 = undeformed_distance(pair, pose, 0.0, y);
    ASSERT_TRUE(h0.has_value()) << y;
    const double eta = y - taping_point_y(pair, pose.dy);
    const double R = pair.wheel_radius + pair.wheel.surface_at(eta)->z - z_tape;
    for (double x : {-0.012, -0.003, 0.005, 0.02}) {
      const auto h = undeformed_distance(pair, pose, x, y);
      ASSERT_TRUE(h.has_value()) << x << " " << y;
      EXPECT_NEAR(*h - *h0, R - std::sqrt(R * R - x * x), 1e-13) << x << " " << y;
    }
  }
}

// At x = 0 it is the gap first_touch() minimises, the roll included: at the touch point it
// equals the touch's gap, which a parabola through the 0.1 mm samples gives to its
// third-order error, below 1e-9 m for the flange root's gap (4.5e-10 m measured).
TEST(UndeformedDistance, AtTheAxleIsTheGapOfFirstTouch) {
  const WheelRailPair& pair = s1002_on_60e1();
  for (double roll : {0.0, -2e-3}) {
    for (double dy : {0.0, 4e-3, 6e-3}) {
      WheelsetPose pose;
      pose.dy = dy;
      pose.roll = roll;
      const WheelRailTouch t = first_touch(pair, pose);
      ASSERT_TRUE(t.found);
      const auto h = undeformed_distance(pair, pose, 0.0, -t.y_rail);
      ASSERT_TRUE(h.has_value());
      EXPECT_NEAR(*h, t.gap, 1e-9) << roll << " " << dy;
    }
  }
}

// The x of the least distance at lateral position y [m] (golden section to 1e-9 m over +-5 cm).
double lowest_x(const WheelRailPair& pair, const WheelsetPose& pose, double y) {
  double a = -0.05, b = 0.05;
  const double r = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 120; ++i) {
    const double c = b - r * (b - a), d = a + r * (b - a);
    if (*undeformed_distance(pair, pose, c, y) < *undeformed_distance(pair, pose, d, y))
      b = d;
    else
      a = c;
  }
  return 0.5 * (a + b);
}

// A yawed wheel touches ahead of or behind its axle: the yawed axle crosses the wheel's
// lateral coordinate eta at x = -yaw eta, and along its own rolling direction X the height of
// the wheel at fixed y is z(eta - yaw X) - X^2/(2R), highest at X* = -R yaw dz/dy (the lead of
// the contact point); so x* = -yaw (eta + R dz/dy) to first order in yaw. The golden-section
// minimum over x agrees within the second-order terms, of relative order yaw dz/dy (2e-3 at
// 5 mrad on the flange root, dz/dy = 0.4): 0.5 %, plus 0.1 um for the search (6e-4 measured).
TEST(UndeformedDistance, YawMovesTheLowestPointAlongX) {
  const WheelRailPair& pair = s1002_on_60e1();
  const double z_tape = pair.wheel.surface_at(0.0)->z;
  WheelsetPose pose;
  pose.dy = 5.5e-3;
  pose.yaw = 5e-3;
  for (double eta : {-0.03, -0.025, 0.0, 0.02}) {
    const double y = eta + taping_point_y(pair, pose.dy);
    const auto w = pair.wheel.surface_at(eta);
    const double R = pair.wheel_radius + w->z - z_tape;
    const double expected = -pose.yaw * (eta + R * w->dz_dy);
    const double x_min = lowest_x(pair, pose, y);
    EXPECT_NEAR(x_min, expected, 5e-3 * std::abs(expected) + 1e-7) << eta;
  }
}

// kinematic_creepages' lateral creepage of a yawed, freely rolling wheel at the contact point
// (SlipPoint::contact_point) is the rigid slip at the point where it touches its rail, found here
// from the wheel's surface, not from the formula's lead. There, X* (found) ahead of where the yawed
// axle crosses the wheel's plane at O's eta, the wheel's spin omega moves its material vertically
// by omega X* (z down) besides the yaw's lateral slip -yaw omega r (y towards the field side):
// along the rail's tangent (1, k)/|(1, k)| in (y, z), k = dz/dy at O, that is (-yaw omega r + k
// omega X*) / sqrt(1 + k^2), in creepage units of the wheel's surface speed omega r, and + towards
// the gauge side (-y). On the tread, the flange root and a new S1002's flank (contact angles below
// 0.1, about 0.5 and above 1.1 rad), yaw 2 mrad: equal within 1 % (second order in yaw k: 0.6 % on
// the flank; 0.1 % measured).
TEST(UndeformedDistance, YawsLateralCreepageIsTheSlipAtTheLeadingContactPoint) {
  const WheelRailPair& pair = s1002_on_60e1();
  struct Place {
    double dy, angle_min, angle_max;  // [m], [rad]
  };
  for (const Place& at : {Place{0.0, 0.0, 0.1}, Place{6.2e-3, 0.3, 0.7}, Place{7.5e-3, 1.1, 1.3}}) {
    const double dy = at.dy;
    WheelsetPose pose;
    pose.dy = dy;
    pose.yaw = 2e-3;
    const WheelRailContact c = solve_wheel_rail(pair, pose, 55e3);
    ASSERT_EQ(c.status, WheelRailStatus::ok) << dy;
    const WheelRailPatch& patch = c.patches.at(0);
    EXPECT_GT(patch.contact_angle, at.angle_min) << dy;
    EXPECT_LT(patch.contact_angle, at.angle_max) << dy;
    const double y_O = -patch.y_rail, eta = -patch.y_wheel;
    const double X = lowest_x(pair, pose, y_O) + pose.yaw * eta;
    const double k = pair.wheel.surface_at(eta)->dz_dy;
    const double r = patch.rolling_radius;
    const double slip = -(-pose.yaw * r + k * X) / (r * std::sqrt(1.0 + k * k));
    WheelsetMotion motion;
    motion.speed = 30.0;
    motion.slip_point = SlipPoint::contact_point;
    const Creepages v = kinematic_creepages(patch, pose, motion, pair.wheel_radius);
    // The code's creepage takes the wheel's forward speed V over the rolling speed where the
    // slip above takes the surface speed omega r: the same up to vx.
    EXPECT_NEAR(v.vy, slip * (1.0 + 0.5 * v.vx), 0.01 * std::abs(slip)) << dy;
    // The axle plane's projection is cos^2(angle) of it (8.5 times less on the flank).
    motion.slip_point = SlipPoint::axle_plane;
    const double projected = kinematic_creepages(patch, pose, motion, pair.wheel_radius).vy;
    EXPECT_NEAR(projected, v.vy * std::pow(std::cos(patch.contact_angle), 2), 1e-12) << dy;
  }
}

TEST(UndeformedDistance, RejectsBadInputAndAnswersNothingOffTheProfiles) {
  const WheelRailPair& pair = s1002_on_60e1();
  EXPECT_THROW(undeformed_distance(pair, {}, std::nan(""), 0.0), InputError);
  EXPECT_FALSE(undeformed_distance(pair, {}, 0.0, 1.0).has_value());  // off the rail
  EXPECT_FALSE(undeformed_distance(pair, {}, 0.4, 0.0).has_value());  // past 45 deg of wheel
}

}  // namespace
}  // namespace wheelwear::contactgeom
