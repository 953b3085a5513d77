// The same S1002 written with its lateral origin at the flange back (as MiniProf writes wheels)
// and at the taping line (tests/data/profiles/s1002_flange_back.whl, s1002_taping_line.whl):
// once loaded, the wheel sits at the same place on its rail, so every contact quantity agrees
// at every lateral shift. The reference is the other file's result.

#include <gtest/gtest.h>

#include <cmath>

#include "support/csv_table.hpp"
#include "wheelwear/contactgeom/kinematics.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"

namespace wheelwear::contactgeom {
namespace {

profiles::Profile wheel_file(const std::string& name) {
  profiles::LoadOptions options;  // automatic origin
  return profiles::load_profile(testing::test_data("profiles/" + name), options).profile;
}

TEST(WheelOriginPlacement, BothOriginsGiveTheSameContactAtEveryShift) {
  const profiles::Profile rail = profiles::rail_60e1({.inclination = std::atan(1.0 / 40.0)});
  const WheelRailPair back(wheel_file("s1002_flange_back.whl"), rail);
  const WheelRailPair tape(wheel_file("s1002_taping_line.whl"), rail);
  // The two files hold the same numbers 70 mm apart (8 decimals of mm: 1e-11 m), so the
  // loaded points agree to rounding and the contacts to the solver's 1e-9 load tolerance.
  EXPECT_NEAR(back.flange_back_y, tape.flange_back_y, 1e-9);
  const WheelsetMotion motion{30.0, 0.0, 0.0, 0.0, 0.75};
  int compared = 0;
  for (double dy = -0.008; dy <= 0.0105; dy += 0.0005) {
    const WheelsetPose pose{dy, 0.0, 2e-3};
    const WheelRailContact a = solve_wheel_rail(back, pose, 60e3);
    const WheelRailContact b = solve_wheel_rail(tape, pose, 60e3);
    ASSERT_EQ(a.status, b.status) << dy;
    ASSERT_EQ(a.patches.size(), b.patches.size()) << dy;
    EXPECT_NEAR(a.approach, b.approach, 1e-9) << dy;
    EXPECT_NEAR(a.lateral_force, b.lateral_force, 1e-9 * 60e3) << dy;
    for (std::size_t k = 0; k < a.patches.size(); ++k) {
      const WheelRailPatch& p = a.patches[k];
      const WheelRailPatch& q = b.patches[k];
      EXPECT_NEAR(p.measures.area, q.measures.area, 1e-9 * q.measures.area) << dy;
      EXPECT_NEAR(p.normal_force, q.normal_force, 1e-9 * q.normal_force) << dy;
      EXPECT_NEAR(p.y_wheel, q.y_wheel, 1e-9) << dy;
      EXPECT_NEAR(p.contact_angle, q.contact_angle, 1e-9) << dy;
      const auto u = kinematic_creepages(p, pose, motion, back.wheel_radius);
      const auto v = kinematic_creepages(q, pose, motion, tape.wheel_radius);
      EXPECT_NEAR(u.vx, v.vx, 1e-9) << dy;
      EXPECT_NEAR(u.vy, v.vy, 1e-9) << dy;
      EXPECT_NEAR(u.phi, v.phi, 1e-9) << dy;
      ++compared;
    }
  }
  EXPECT_GE(compared, 37);
}

// A measured, nearly new wheel (Car7216_0001r.whl, MiniProf: origin at the internal face) at the
// centred position rolls at its nominal radius: free rolling on it gives |vx| = |r_O / r0 - 1|
// of the order of 0.1 %, below 0.3 % (with the origin misread as the taping line it was 2.5 %).
TEST(WheelOriginPlacement, AMeasuredWheelRollsNearItsNominalRadiusWhenCentred) {
  profiles::LoadOptions options;
  options.read.body = profiles::Body::wheel;
  const profiles::Profile wheel =
      profiles::load_profile(testing::test_data("measured/Car7216_0001r.whl"), options).profile;
  profiles::LoadOptions rail_options;
  rail_options.read.body = profiles::Body::rail;
  const profiles::Profile measured_rail =
      profiles::load_profile(testing::test_data("measured/avg_HR.BAN"), rail_options).profile;
  const WheelsetMotion motion{30.0, 0.0, 0.0, 0.0, 0.75};
  int compared = 0;
  for (const profiles::Profile& rail :
       {profiles::rail_60e1({.inclination = std::atan(1.0 / 40.0)}), measured_rail}) {
    const WheelRailPair pair(wheel, rail);
    const WheelRailContact c = solve_wheel_rail(pair, WheelsetPose{}, 55e3);
    ASSERT_EQ(c.status, WheelRailStatus::ok) << c.message;
    for (const WheelRailPatch& p : c.patches) {
      EXPECT_LT(std::abs(kinematic_creepages(p, WheelsetPose{}, motion, pair.wheel_radius).vx),
                3e-3);
      ++compared;
    }
  }
  EXPECT_GE(compared, 2);
}

}  // namespace
}  // namespace wheelwear::contactgeom
