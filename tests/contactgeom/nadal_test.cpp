// Nadal's flange-climb criterion: the track-plane forces against CONTACT's wheel totals (set d of
// tests/data/contact), the limit against its closed form, and the verdict on CONTACT's cases.

#include "wheelwear/contactgeom/nadal.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/contact_cases.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

namespace contact = testing::contact;

// One patch as CONTACT reports it: its normal force and contact angle (the lateral creep force is
// passed beside it).
WheelRailContact single_patch(double normal_force, double angle) {
  WheelRailContact c;
  c.status = WheelRailStatus::ok;
  WheelRailPatch& p = c.patches.emplace_back();
  p.normal_force = normal_force;
  p.contact_angle = angle;
  c.vertical_force = normal_force * std::cos(angle);
  c.lateral_force = normal_force * std::sin(angle);
  return c;
}

TEST(Nadal, TrackPlaneForcesMatchContactsTotals) {
  // CONTACT's patch forces act on the rail in the patch's (x, s, n) frame: on the wheel the
  // normal force is FN and the lateral creep force -FS. Projected with the reference angle they
  // must give CONTACT's track-frame totals (FY on the rail = -Y, FZ = Q) to 0.5 % of Q: CONTACT
  // sums element by element over a planar patch whose angle spreads around the reference angle
  // (the flange case, 1.8 mm wide on a 1.2 rad flank, is the widest spread).
  int compared = 0;
  for (const contact::WheelRailCase& c : contact::wheel_rail_cases()) {
    const WheelRailContact w = single_patch(c.FN, c.delta_cp);
    const TrackPlaneForces f = track_plane_forces(w, std::vector<double>{-c.FS});
    EXPECT_NEAR(f.Y, -c.FY_track, 0.005 * c.FZ_track) << "y_ws " << c.y_ws_mm;
    EXPECT_NEAR(f.Q, c.FZ_track, 0.005 * c.FZ_track) << "y_ws " << c.y_ws_mm;
    compared += 2;
  }
  EXPECT_EQ(compared, 20);
}

TEST(Nadal, LimitIsTheClosedForm) {
  // (tan d - mu)/(1 + mu tan d) = tan(d - atan mu): the friction angle subtracted from delta.
  int compared = 0;
  for (double delta : {0.4, 0.8, 1.2053, 1.3})
    for (double mu : {0.0, 0.2, 0.35}) {
      const NadalCheck n = nadal_check(single_patch(50e3, delta), mu);
      EXPECT_NEAR(n.limit, std::tan(delta - std::atan(mu)), 1e-14) << delta << " " << mu;
      EXPECT_EQ(n.delta, delta);
      ++compared;
    }
  EXPECT_EQ(compared, 12);
}

TEST(Nadal, ContactsFlangeCaseExceedsTheLimitAndItsTreadCasesDoNot) {
  // CONTACT's y_ws = -8 mm: the flange carries the whole 55 kN, Y/Q = 137.2/55 = 2.49 against a
  // limit tan(1.2053 - atan 0.35) = 1.18: a position-prescribed state beyond the limit. The flange
  // root (y_ws = -6 mm, 0.37 rad: Y/Q 0.36 against its own limit 0.04) and the tread cases are
  // not flank contact: the criterion does not apply there.
  int flagged = 0, tread = 0;
  for (const contact::WheelRailCase& c : contact::wheel_rail_cases()) {
    const NadalCheck n = nadal_check(single_patch(c.FN, c.delta_cp), c.mu,
                                     TrackPlaneForces{-c.FY_track, c.FZ_track});
    EXPECT_NEAR(n.Y_over_Q, -c.FY_track / c.FZ_track, 1e-15);
    if (c.y_ws_mm == -8) {
      EXPECT_TRUE(n.exceeded);
      EXPECT_NEAR(n.Y_over_Q, 2.49, 0.01);
      EXPECT_NEAR(n.limit, 1.18, 0.01);
      ++flagged;
    }
    if (c.y_ws_mm > -8) {
      EXPECT_FALSE(n.applies) << c.y_ws_mm;
      EXPECT_FALSE(n.exceeded) << c.y_ws_mm;
      ++tread;
    }
  }
  EXPECT_EQ(flagged, 1);
  EXPECT_EQ(tread, 9);
}

TEST(Nadal, DeltaComesFromPatchesCarryingTenPercent) {
  // A tread patch at 0.02 rad with 50 kN and a flange touch at 1.2 rad: with 4 kN (7.4 %) it
  // does not set delta, with 6 kN (10.7 %) it does.
  for (const auto& [flange_load, expected_delta] : {std::pair{4e3, 0.02}, std::pair{6e3, 1.2}}) {
    WheelRailContact c = single_patch(50e3, 0.02);
    WheelRailPatch& f = c.patches.emplace_back();
    f.normal_force = flange_load;
    f.contact_angle = 1.2;
    c.vertical_force += flange_load * std::cos(1.2);
    c.lateral_force += flange_load * std::sin(1.2);
    EXPECT_EQ(nadal_check(c, 0.3).delta, expected_delta);
  }
}

TEST(Nadal, BadInputIsRefused) {
  const WheelRailContact c = single_patch(50e3, 1.0);
  EXPECT_THROW(nadal_check(c, -0.1), InputError);
  EXPECT_THROW(nadal_check(c, std::nan("")), InputError);
  EXPECT_THROW(track_plane_forces(c, std::vector<double>{1.0, 2.0}), InputError);
  const NadalCheck none = nadal_check(WheelRailContact{}, 0.3);
  EXPECT_FALSE(none.exceeded);
  EXPECT_EQ(none.delta, 0.0);
}

}  // namespace
}  // namespace wheelwear::contactgeom
