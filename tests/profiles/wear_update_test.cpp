// Tests of applying a wear-depth distribution along the normal.

#include "wheelwear/profiles/wear_update.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

// A rail crown that is one circular arc, radius R, centre (0, R) below the top (z down).
Profile arc_rail(double R) {
  PointList points;
  for (int k = -300; k <= 300; ++k) {
    const double phi = k * std::numbers::pi / 900.0;  // +-60 deg
    points.emplace_back(R * std::sin(phi), R - R * std::cos(phi));
  }
  return Profile(points, {"arc", Body::rail, Side::right, 0.0}, {0.0, 0.1e-3});
}

TEST(WearUpdate, ZeroDepthChangesNothing) {
  const Profile wheel = s1002();
  const Profile same = apply_wear(wheel, {{-0.07, 0.06}, {0.0, 0.0}});
  // The unmoved knots are interpolated again with arc length recomputed: the curve moves by the
  // interpolation error near curvature jumps (up to 3e-8 m at the S1002 flange joints), no more.
  EXPECT_NEAR(same.length(), wheel.length(), 2e-9);
  for (double y = -0.0699; y < 0.06; y += 0.5e-3) ASSERT_NEAR(*same.z_at(y), *wheel.z_at(y), 3e-8);
}

TEST(WearUpdate, RepeatedUpdatesDoNotDriftWhereNothingWears) {
  // The wear loop rebuilds the profile many times. Knots sit at exact multiples of the spacing,
  // so an unworn stretch before the worn one keeps its knots and does not creep.
  const Profile wheel = s1002();
  Profile current = wheel;
  for (int step = 0; step < 50; ++step)
    current = apply_wear(current, {{0.0, 0.01, 0.02, 0.03}, {0.0, 2e-6, 2e-6, 0.0}});
  double drift = 0.0;
  for (double y = -0.0699; y < -0.005; y += 0.1e-3)
    drift = std::max(drift, std::abs(*current.z_at(y) - *wheel.z_at(y)));
  std::printf("50 rebuilds: largest change of the unworn flange %.3g m\n", drift);
  EXPECT_LT(drift, 1e-8);
  // Where it wore, 50 x 2 um.
  const double slope = wheel.surface_at(0.015)->dz_dy;
  EXPECT_NEAR(*wheel.z_at(0.015) - *current.z_at(0.015), 1e-4 * std::sqrt(1.0 + slope * slope),
              2e-7);
}

TEST(WearUpdate, UniformDepthOnAnArcGivesTheConcentricArc) {
  // Offsetting a circle inwards by d gives the concentric circle of radius R - d (closed form).
  const double R = 0.013, d = 1e-3;
  const Profile worn = apply_wear(arc_rail(R), {{-0.02, 0.02}, {d, d}});
  EXPECT_NEAR(*worn.z_at(0.0), d, 1e-9);
  for (double s = 0.002; s < worn.length() - 0.002; s += 0.5e-3) {
    ASSERT_NEAR((worn.position(s) - Point(0.0, R)).norm(), R - d, 1e-9);
    ASSERT_NEAR(worn.curvature(s) * (R - d), 1.0, 1e-4);
  }
}

TEST(WearUpdate, TreadWearLowersTheTreadAndLeavesTheFlangeAlone) {
  const Profile wheel = s1002();
  const double d = 0.5e-3;
  // Full depth from -20 to 50 mm, ramps of 10 mm to zero on either side.
  const Profile worn = apply_wear(wheel, {{-0.03, -0.02, 0.05, 0.06}, {0.0, d, d, 0.0}});
  // Wheel material is above the profile (z down): wear moves the tread up by d / cos(slope).
  const double slope = wheel.surface_at(0.0)->dz_dy;
  EXPECT_NEAR(*worn.z_at(0.0), *wheel.z_at(0.0) - d * std::sqrt(1.0 + slope * slope), 1e-8);
  for (double y = -0.0699; y < -0.035; y += 0.5e-3)
    ASSERT_NEAR(*worn.z_at(y), *wheel.z_at(y), 3e-8) << y;  // re-interpolation only
  // The vertical flange back does not face the rail: it stays where it was.
  EXPECT_NEAR(worn.y_min(), wheel.y_min(), 1e-8);
}

TEST(WearUpdate, LocalDepthIsAppliedAlongTheNormal) {
  const Profile wheel = s1002();
  WearDepth wear;
  for (double y = -0.02; y <= 0.02; y += 0.25e-3) {
    wear.y.push_back(y);
    wear.depth.push_back(0.2e-3 * std::exp(-(y / 5e-3) * (y / 5e-3)));
  }
  const Profile worn = apply_wear(wheel, wear);
  const double slope = wheel.surface_at(0.0)->dz_dy;
  const double change = *wheel.z_at(0.0) - *worn.z_at(0.0);
  // The 0.5 mm depth smoothing barely touches a 5 mm wide bump: within 1%.
  EXPECT_NEAR(change, 0.2e-3 * std::sqrt(1.0 + slope * slope), 0.01 * 0.2e-3);
}

TEST(WearUpdate, RefusesAStepDeeperThanTheLocalRadius) {
  // A ridge of radius 1 mm between flat stretches, worn 3 mm deep: the offset folds over itself.
  PointList points;
  for (int i = 0; i <= 190; ++i) points.emplace_back(-0.02 + 1e-4 * i, 0.0);
  for (int k = 1; k < 30; ++k) {
    const double a = std::numbers::pi * (1.0 - k / 30.0);
    points.emplace_back(1e-3 * std::cos(a), -1e-3 * std::sin(a));
  }
  for (int i = 0; i <= 190; ++i) points.emplace_back(0.001 + 1e-4 * i, 0.0);
  const Profile rail(points, {"ridge", Body::rail, Side::right, 0.0}, {0.0, 0.1e-3});
  try {
    apply_wear(rail, {{-0.03, 0.03}, {3e-3, 3e-3}});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("crosses itself"), std::string::npos) << e.what();
  }
}

TEST(WearUpdate, ValidatesTheDepthTable) {
  const Profile wheel = s1002();
  EXPECT_THROW(apply_wear(wheel, {{0.0}, {0.0}}), InputError);
  EXPECT_THROW(apply_wear(wheel, {{0.0, 0.0}, {0.0, 0.0}}), InputError);
  EXPECT_THROW(apply_wear(wheel, {{0.0, 0.01}, {-1e-4, 0.0}}), InputError);
  EXPECT_THROW(apply_wear(wheel, {{0.0, 0.01}, {0.02, 0.0}}), InputError);
  EXPECT_THROW(apply_wear(wheel, {{0.0, 0.01}, {0.0, NAN}}), InputError);
  EXPECT_THROW(apply_wear(wheel, {{0.0, 0.01}, {0.0, 0.0}}, {-1.0}), InputError);
  const WearDepth table{{0.0, 0.01}, {1e-4, 3e-4}};
  EXPECT_DOUBLE_EQ(table.at(0.005), 2e-4);
  EXPECT_EQ(table.at(-0.001), 0.0);
  EXPECT_EQ(table.at(0.011), 0.0);
}

}  // namespace
}  // namespace wheelwear::profiles
