// Tests of the Profile value type: frame conventions of normals and curvature, z(y), transforms.

#include "wheelwear/profiles/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

TEST(Profile, OutwardNormalsPointAtTheMatingBody) {
  const Profile wheel = s1002();
  const Profile rail = rail_60e1();
  // Wheel tread at the taping line: the rail is below (+z).
  const double s_tape = wheel.surface_at(0.0)->s;
  EXPECT_GT(wheel.normal(s_tape)[1], 0.99);
  // Wheel flange back (vertical face at y = -70 mm): the normal points away from the flange, -y.
  EXPECT_NEAR(wheel.normal(0.002)[0], -1.0, 1e-9);
  // Rail top: the wheel is above (-z).
  const double s_top = rail.surface_at(0.0)->s;
  EXPECT_LT(rail.normal(s_top)[1], -0.99);
  // Rail gauge face (-y side) faces the track centre, -y.
  EXPECT_LT(rail.normal(rail.surface_at(-0.0425)->s)[0], -0.9);
  for (double s = 0.0; s < wheel.length(); s += 0.01) {
    EXPECT_NEAR(wheel.normal(s).norm(), 1.0, 1e-12);
    EXPECT_NEAR(wheel.normal(s).dot(wheel.tangent(s)), 0.0, 1e-12);
  }
}

TEST(Profile, CurvatureIsPositiveWhereConvex) {
  const Profile wheel = s1002();
  const Profile rail = rail_60e1({0.0});
  // S1002 flange tip: R12 arc, convex (section G of EN 13715).
  EXPECT_NEAR(wheel.curvature(wheel.surface_at(-0.055)->s), 1.0 / 0.012, 1e-3 / 0.012);
  // S1002 flange root: R13 fillet, concave (section D).
  EXPECT_NEAR(wheel.curvature(wheel.surface_at(-0.0367)->s), -1.0 / 0.013, 1e-3 / 0.013);
  // 60E1 crown: R300, convex.
  EXPECT_NEAR(rail.curvature(rail.surface_at(0.0)->s), 1.0 / 0.3, 1e-3 / 0.3);
}

TEST(Profile, ZAtFollowsTheEnvelopeAtTheVerticalFlangeBack) {
  const Profile wheel = s1002();
  // 0.1 mm inside the back face the rail sees the back arc H (centre (-49.5, 9.519259302) mm,
  // R 20.5 mm), not the face above it. Its slope is 10 there, so the 1e-10 m lateral error of the
  // representation becomes 1e-9 m in z; at y = -70 mm itself the tangent is vertical and z(y)
  // has no useful precision.
  const double z_arc = 9.519259302e-3 + std::sqrt(0.0205 * 0.0205 - 0.0204 * 0.0204);
  EXPECT_NEAR(*wheel.z_at(-0.0699), z_arc, 1e-8);
  EXPECT_NEAR(wheel.position(0.0)[0], -0.070, 1e-12);
  EXPECT_NEAR(wheel.position(0.0)[1], 0.0, 1e-12);
  EXPECT_FALSE(wheel.z_at(-0.0701));
  EXPECT_NEAR(wheel.y_max(), 0.060, 1e-12);
}

TEST(Profile, TranslationMovesEverything) {
  const Profile rail = rail_60e1();
  const Profile moved = rail.translated(0.7175, 0.002);
  EXPECT_EQ(moved.length(), rail.length());
  for (double y = -0.03; y < 0.03; y += 0.001)
    EXPECT_NEAR(*moved.z_at(y + 0.7175), *rail.z_at(y) + 0.002, 1e-12);
  EXPECT_NEAR(moved.curvature(1e-2), rail.curvature(1e-2), 1e-9);
}

TEST(Profile, KeepsItsInfo) {
  const Profile wheel = s1002({.nominal_radius = 0.5, .side = Side::left});
  EXPECT_EQ(wheel.info().name, "S1002");
  EXPECT_EQ(wheel.body(), Body::wheel);
  EXPECT_EQ(wheel.side(), Side::left);
  EXPECT_EQ(wheel.info().nominal_radius, 0.5);
  EXPECT_THROW(Profile({Point(0, 0), Point(1e-3, 0), Point(2e-3, 0), Point(3e-3, 0)},
                       {"x", Body::rail, Side::right, -1.0}),
               InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
