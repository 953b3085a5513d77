// A rigid wheelset on its track: symmetry at the centred position, the roll against the
// geometry of the two contact points, mirrored states, and prescribed lateral forces.

#include "wheelwear/contactgeom/wheelset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/reference_profiles.hpp"
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

WheelsetOnTrack track() {
  return {s1002_on_60e1(), s1002_on_60e1()};
}

WheelsetState loaded(double dy) {
  WheelsetState s;
  s.dy = dy;
  s.vertical_force_left = 55e3;
  s.vertical_force_right = 55e3;
  return s;
}

// Both wheels of a wheelset worn as in tests/data/profiles/`file`, on 60E1 1:40.
WheelsetOnTrack worn_on_60e1(const std::string& file) {
  const WheelRailPair pair(testing::worn_wheel(file),
                           profiles::rail_60e1({.inclination = std::atan(1.0 / 40.0)}));
  return {pair, pair};
}

// The patch whose O is where the undeformed surfaces touch first: the lowest vertical gap at O
// (KpPatch::h_O is the gap along the contact normal, the vertical one times cos(angle)).
const WheelRailPatch& touching_patch(const WheelRailContact& c) {
  std::size_t best = 0;
  auto vertical_gap = [&](std::size_t k) {
    return c.patches[k].kp.h_O / std::cos(c.patches[k].contact_angle);
  };
  for (std::size_t k = 1; k < c.patches.size(); ++k)
    if (vertical_gap(k) < vertical_gap(best)) best = k;
  return c.patches[best];
}

// The roll from the two contact points alone: a rigid wheelset touching both rails has its axle
// at distance R (the rolling radius) from each contact point O, perpendicular to the axle. In a
// track frame with Y to the left and Z down, O lies on the rail surface (the gap is zero there)
// and the axle's foot A = O - R (-sin(roll), cos(roll)); the axle's slope through the two feet
// is the roll. The roll enters A only at second order (R (1 - cos) and a common lateral shift
// R sin), so the relation checks the solved roll, not itself. A rail whose head took up a
// prescribed lateral force sits displaced by -shift.
double roll_from_contact_points(const WheelRailPair& pair, const WheelsetContact& w) {
  const double y_gauge = profiles::gauge_point(pair.rail, pair.gauge_depth).point.x();
  const double z_top = profiles::top_of_rail(pair.rail).point.y();
  auto foot = [&](const WheelRailPatch& p, double side, double shift) {
    const double y_O = -p.y_rail;  // rail profile frame, + towards the field side
    const double Y = side * (0.5 * pair.gauge + (y_O - y_gauge) - shift);
    const double Z = pair.rail.surface_at(y_O)->z - z_top;
    return std::make_pair(Y + p.rolling_radius * std::sin(w.roll),
                          Z - p.rolling_radius * std::cos(w.roll));
  };
  const auto l = foot(touching_patch(w.left), 1.0, w.left_shift);
  const auto r = foot(touching_patch(w.right), -1.0, w.right_shift);
  return std::atan2(l.second - r.second, l.first - r.first);
}

TEST(Wheelset, CentredSymmetricWheelsetDoesNotRollAndHasEqualContacts) {
  const WheelsetContact w = solve_wheelset(track(), loaded(0.0));
  ASSERT_TRUE(w.roll_converged) << w.message;
  // Both sides run the same operations on the same numbers: exact.
  EXPECT_EQ(w.roll, 0.0);
  EXPECT_EQ(w.left_pose.dy, 0.0);
  EXPECT_EQ(w.right_pose.dy, 0.0);
  ASSERT_EQ(w.left.status, WheelRailStatus::ok);
  ASSERT_EQ(w.left.patches.size(), w.right.patches.size());
  for (std::size_t k = 0; k < w.left.patches.size(); ++k) {
    EXPECT_EQ(w.left.patches[k].normal_force, w.right.patches[k].normal_force);
    EXPECT_EQ(w.left.patches[k].y_rail, w.right.patches[k].y_rail);
    EXPECT_EQ(w.left.patches[k].measures.area, w.right.patches[k].measures.area);
  }
  EXPECT_EQ(w.left.lateral_force, w.right.lateral_force);
  // The centre sits a wheel radius above the taping points, which sit where the wheels first
  // touch: the rail's top plus the first touch's gap below the wheel profile's datum (on the
  // tread no other minimum shares the load: WheelRailTouch::resting_gap is the gap).
  const WheelRailPair& pair = s1002_on_60e1();
  const double z_tape = pair.wheel.surface_at(0.0)->z;
  const double z_top = profiles::top_of_rail(pair.rail).point.y();
  EXPECT_NEAR(w.centre_height,
              pair.wheel_radius - (z_tape + first_touch(pair, w.left_pose).gap - z_top), 1e-15);
}

// Tread (1, 3 mm), two-point contact near 5 mm, flange root (6 mm) and flange (7 mm, where the
// roll of 6 mrad moves the left wheel 3 mm further onto its flange).
class WheelsetRoll : public ::testing::TestWithParam<double> {};

TEST_P(WheelsetRoll, AgreesWithTheGeometryOfTheContactPoints) {
  const double dy = GetParam();
  const WheelsetContact w = solve_wheelset(track(), loaded(dy));
  ASSERT_TRUE(w.roll_converged) << w.message;
  ASSERT_FALSE(w.left.patches.empty());
  ASSERT_FALSE(w.right.patches.empty());
  // Towards the left flange the left wheel runs on a larger radius and rises.
  EXPECT_LT(w.roll, 0.0);
  EXPECT_GT(touching_patch(w.left).rolling_radius, touching_patch(w.right).rolling_radius);
  // The per-wheel poses are the rigid body's (wheelset.hpp).
  const WheelRailPair& pair = s1002_on_60e1();
  const double y_tape = 0.5 * pair.back_to_back - pair.flange_back_y;
  EXPECT_NEAR(w.left_pose.dy,
              dy + (std::cos(w.roll) - 1.0) * y_tape - std::sin(w.roll) * pair.wheel_radius, 1e-15);
  EXPECT_EQ(w.left_pose.roll, w.roll);
  EXPECT_EQ(w.right_pose.roll, -w.roll);
  // The loaded patch's O and the first touch the roll was solved for are located by parabolas
  // through the same 0.1 mm samples (one on the normal gap, one on the vertical); the axle
  // foot's height is stationary in O, where the gap is minimal, so their small difference
  // enters at second order. 5e-8 rad is 75 nm of height over the 1.5 m lever; the roll
  // iteration's own residual is 1e-11 m.
  EXPECT_NEAR(w.roll, roll_from_contact_points(pair, w), 5e-8) << "dy " << dy;
}

INSTANTIATE_TEST_SUITE_P(TreadToFlange, WheelsetRoll,
                         ::testing::Values(1e-3, 3e-3, 5e-3, 6e-3, 7e-3));

TEST(Wheelset, MirroredStateGivesMirroredResult) {
  WheelsetState a = loaded(3.5e-3);
  a.vertical_force_left = 60e3;
  a.vertical_force_right = 48e3;
  a.yaw = 2e-3;
  WheelsetState b = a;
  b.dy = -a.dy;
  b.yaw = -a.yaw;
  std::swap(b.vertical_force_left, b.vertical_force_right);
  const WheelsetContact wa = solve_wheelset(track(), a);
  const WheelsetContact wb = solve_wheelset(track(), b);
  ASSERT_TRUE(wa.roll_converged && wb.roll_converged);
  // The roll iteration stops at |residual| <= 1e-11 m, 7e-12 rad over the 1.5 m lever; the
  // contacts change by far less than 1e-9 of their values for such a roll difference.
  EXPECT_NEAR(wb.roll, -wa.roll, 1e-11);
  EXPECT_NEAR(wb.left_pose.dy, wa.right_pose.dy, 1e-12);
  EXPECT_NEAR(wb.right_pose.dy, wa.left_pose.dy, 1e-12);
  EXPECT_EQ(wb.left_pose.yaw, wa.right_pose.yaw);
  auto same = [](const WheelRailContact& x, const WheelRailContact& y) {
    ASSERT_EQ(x.patches.size(), y.patches.size());
    EXPECT_NEAR(x.vertical_force, y.vertical_force, 1e-9 * y.vertical_force);
    EXPECT_NEAR(x.lateral_force, y.lateral_force, 1e-9 * y.vertical_force);
    for (std::size_t k = 0; k < x.patches.size(); ++k) {
      EXPECT_NEAR(x.patches[k].y_rail, y.patches[k].y_rail, 1e-12);
      EXPECT_NEAR(x.patches[k].contact_angle, y.patches[k].contact_angle, 1e-12);
    }
  };
  same(wb.left, wa.right);
  same(wb.right, wa.left);
}

// Near the centred position the new S1002's gap on 60E1 is almost flat across a 20 mm patch,
// with two minima 10 mm apart whose depths cross at dy = 0.21 mm. Taken as the lowest of them,
// O jumped by 10 mm there within 1 um of shift (and with it the rolling radius, the SDEC's shape
// number and a wheel's lateral creep force by 1.5 kN). Blended by depth, O moves continuously:
// the largest move per 1 um step stays below a tenth of that jump (measured: 11 mm over the
// sweep, at most 0.09 mm per um).
TEST(Wheelset, InitialContactPointMovesContinuouslyWhereTwoMinimaCross) {
  const WheelsetOnTrack t = track();
  double previous = std::nan(""), largest = 0.0, lowest = 1.0, highest = -1.0;
  int compared = 0;
  for (int step = 0; step <= 300; ++step) {
    const WheelsetContact c = solve_wheelset(t, loaded(0.05e-3 + step * 1e-6));
    ASSERT_EQ(c.left.patches.size(), 1u);
    const double y_O = c.left.patches[0].y_rail;
    lowest = std::min(lowest, y_O);
    highest = std::max(highest, y_O);
    if (std::isfinite(previous)) {
      largest = std::max(largest, std::abs(y_O - previous));
      ++compared;
    }
    previous = y_O;
  }
  EXPECT_EQ(compared, 300);
  EXPECT_GT(highest - lowest, 5e-3);  // O does cross the patch within the sweep
  EXPECT_LT(largest, 1e-3) << "largest move of O per um of shift";
}

// A worn wheel whose flank wore to 1.46 rad (tests/data/profiles/s1002_worn_33200km.csv), past
// atan(D / r) = 1.27 rad: lifting that wheel by the roll pushes its flank into the rail faster
// than it rises, so no roll puts it on its flank continuously. The roll of the lowest touch
// jumped at dy = 6.467 mm from -0.42 to -6.0 mrad (the wheel 4.5 mm up its flank) and the left
// wheel's lateral force from 13 to 107 kN within 1.5 um. Resting on its tread, the flank met
// by the approach, the wheel's lateral force rises continuously onto the flank: at most a
// tenth of that jump per um, while it more than triples over the sweep.
TEST(Wheelset, ASteepWornFlankTakesItsLoadContinuously) {
  const WheelsetOnTrack t = worn_on_60e1("s1002_worn_33200km.csv");
  double previous_roll = std::nan(""), previous_Y = 0.0, first_Y = 0.0, last_Y = 0.0;
  double largest_roll = 0.0, largest_Y = 0.0;
  int compared = 0;
  for (int step = 0; step <= 100; ++step) {
    const WheelsetContact c = solve_wheelset(t, loaded(6.42e-3 + step * 1e-6));
    ASSERT_TRUE(c.roll_converged) << c.message;
    const double Y = c.left.lateral_force;
    if (step == 0) first_Y = Y;
    last_Y = Y;
    if (std::isfinite(previous_roll)) {
      largest_roll = std::max(largest_roll, std::abs(c.roll - previous_roll));
      largest_Y = std::max(largest_Y, std::abs(Y - previous_Y));
      ++compared;
    }
    previous_roll = c.roll;
    previous_Y = Y;
  }
  EXPECT_EQ(compared, 100);
  EXPECT_LT(largest_roll, 1e-5);  // the jump was 5.6e-3 rad
  EXPECT_LT(largest_Y, 9.4e3);    // the jump was 94 kN
  EXPECT_GT(last_Y, 3.0 * first_Y);
}

// The default scene's wheel after 67 900 km (tests/data/profiles/s1002_worn_67900km.csv): its
// flange root worn to a 10 deg shelf, its flank above it to 79 deg. The flank's gap dips between
// two points of the coarse scan (1 mm apart) and far below both: the vertical gap closes by
// 6 mm per mm of shift there. Seen only once a coarse point fell into the dip, the flank took
// 19 kN at once (dy 6.509 mm, within 0.01 um), and the curves R 700-1500 m found no balance on
// this wheel. The scan now follows the gap's slopes into such a dip: the flank loads from zero,
// as a scan fine enough to see the dip at every shift (0.2 mm) has it.
TEST(Wheelset, AFlankDipBetweenTheCoarseScansPointsLoadsContinuously) {
  const WheelsetOnTrack t = worn_on_60e1("s1002_worn_67900km.csv");
  WheelRailOptions fine;
  fine.scan_spacing = 0.2e-3;
  double previous_Y = std::nan(""), largest_step = 0.0, largest_miss = 0.0;
  int one_patch = 0, on_flank = 0, compared = 0;
  for (int step = 0; step <= 80; ++step) {
    const WheelsetState state = loaded(6.45e-3 + step * 1e-6);
    const WheelsetContact c = solve_wheelset(t, state);
    const WheelsetContact f = solve_wheelset(t, state, fine);
    const double Y = c.left.lateral_force;
    one_patch += c.left.patches.size() == 1 ? 1 : 0;
    on_flank += c.left.patches.size() == 2 && c.left.patches.back().contact_angle > 1.35 ? 1 : 0;
    if (std::isfinite(previous_Y)) largest_step = std::max(largest_step, std::abs(Y - previous_Y));
    largest_miss = std::max(largest_miss, std::abs(Y - f.left.lateral_force));
    previous_Y = Y;
    ++compared;
  }
  EXPECT_EQ(compared, 81);
  // The sweep crosses the flank's onset (6.476 mm) and the shift at which a coarse point fell
  // into the dip (about 6.51 mm), where the flank's load jumped.
  EXPECT_GT(one_patch, 3);
  EXPECT_GT(on_flank, 40);
  // Measured: at most 1.3 kN per um of shift, where the jump was 19 kN.
  EXPECT_LT(largest_step, 2.5e3);
  // The same strips sampled once the scan sees the dip: to rounding (measured 0.002 N).
  EXPECT_LT(largest_miss, 1.0);
}

// A measured wheel on a measured rail (tests/data/measured: MiniProf Car7216_0001r.whl fitted
// over 2 mm, on avg_HR.BAN as it lies in its file), the rail's gauge face steeper than the
// wheel's flank (80 against 74 deg): the flank's minimum overtakes the tread's at a contact
// angle of 1.2 rad, where the lever r tan(angle) of a rolled wheel nearly equals the distance D
// between the taping points and the flank's height hardly changes with the roll. Resting at the
// lower of the two minima, the wheelset's roll ran away by 2.3e-5 rad within 5 nm of shift,
// and the wheel's lateral force jumped across the balance the leading wheelset of R 500 m needs
// (the curving found none; the runaway lay at 5.2285 mm). Resting where both share its load,
// the roll turns from the tread's rate (7.5e-8 rad per um) to the flank's over 5.211-5.229 mm:
// over 5 nm steps through 5.205-5.235 mm it moves at most at the rate it keeps once the flank
// carries the wheel (2.15e-5 rad per um over 5.232-5.25 mm; bound 2.2e-5 with half again as
// margin), and by 1.6e-4 rad in all.
TEST(Wheelset, AMeasuredFlankTakesOverFromTheTreadWithoutARunawayRoll) {
  WheelRailPair pair(
      testing::test_profile("measured/Car7216_0001r.whl", profiles::Body::wheel, 2e-3),
      testing::test_profile("measured/avg_HR.BAN", profiles::Body::rail));
  pair.wheel_radius = 0.46;
  const WheelsetOnTrack t{pair, pair};
  double previous = std::nan(""), previous_step = std::nan(""), first = 0.0, last = 0.0;
  double largest_step = 0.0, largest_change = 0.0;
  int compared = 0;
  constexpr double kStep = 5e-9;  // [m]
  for (int step = 0; step <= 6000; ++step) {
    WheelsetState s;
    s.dy = 5.205e-3 + step * kStep;
    s.yaw = 5.13e-3;  // the leading wheelset's yaw and loads in R 500 m
    s.vertical_force_left = 55.3e3;
    s.vertical_force_right = 53.8e3;
    const WheelsetContact c = solve_wheelset(t, s);
    ASSERT_TRUE(c.roll_converged) << c.message;
    if (step == 0) first = c.roll;
    last = c.roll;
    if (std::isfinite(previous)) {
      const double roll_step = c.roll - previous;
      largest_step = std::max(largest_step, std::abs(roll_step));
      if (std::isfinite(previous_step))
        largest_change = std::max(largest_change, std::abs(roll_step - previous_step));
      previous_step = roll_step;
      ++compared;
    }
    previous = c.roll;
  }
  RecordProperty("largest_roll_step_nrad", std::to_string(largest_step * 1e9));
  RecordProperty("roll_change_urad", std::to_string((last - first) * 1e6));
  RecordProperty("largest_step_change_nrad", std::to_string(largest_change * 1e9));
  EXPECT_EQ(compared, 6000);
  EXPECT_LT(largest_step, 1.5 * 2.2e-5 * kStep * 1e6);  // the runaway: 2.3e-5 rad in one step
  // And smoothly: a jump of the roll shows as a change of its step; the takeover's own curvature
  // changes it by at most 24 nrad (where the flank's sharing ends, 5.229 mm).
  EXPECT_LT(largest_change, 40e-9);
  EXPECT_LT(last - first, -1e-4);  // the flank does take over within the sweep
}

TEST(WheelsetInput, RejectsBadStatesAndMismatchedPairs) {
  EXPECT_THROW(solve_wheelset(track(), loaded(std::nan(""))), InputError);
  WheelsetState no_load = loaded(0.0);
  no_load.vertical_force_right = 0.0;
  EXPECT_THROW(solve_wheelset(track(), no_load), InputError);
  WheelsetOnTrack narrow = track();
  narrow.right.back_to_back = 1.357;
  EXPECT_THROW(solve_wheelset(narrow, loaded(0.0)), InputError);
}

// A prescribed lateral force: the solved contact carries both forces to the solvers' tolerances
// (Fz: the load iteration's 1e-9 relative; Fy: lateral_tolerance Fz = 0.055 N).
TEST(WheelRailLateral, MatchesBothForcesOnTheFlange) {
  const WheelRailPair& pair = s1002_on_60e1();
  WheelsetPose pose;
  pose.dy = 6e-3;  // flange root: about 21 kN of lateral force at 55 kN
  for (double target : {12e3, 25e3, 40e3}) {
    const WheelRailLateral r = solve_wheel_rail_lateral(pair, pose, 55e3, target);
    ASSERT_EQ(r.fit, LateralFit::matched) << target << ": " << r.message;
    EXPECT_NEAR(r.contact.lateral_force, target, 1e-6 * 55e3) << target;
    EXPECT_NEAR(r.contact.vertical_force, 55e3, 1e-3) << target;
    EXPECT_EQ(r.pose.dy, pose.dy + r.shift);
    // Less force than at 6 mm: away from the flange; more: towards it.
    EXPECT_EQ(r.shift > 0.0, target > 21e3) << target;
  }
  // Past 52 kN the contact moves from the flange root onto the flank (over the rail's concave
  // stretch). Projected with one angle at O, the lateral force jumped there from 52 to 150 kN;
  // summed strip by strip with each strip's angle it rises steeply but continuously (the patch
  // spans root and flank), so 60 and 100 kN are met too.
  for (double target : {60e3, 100e3}) {
    const WheelRailLateral r = solve_wheel_rail_lateral(pair, pose, 55e3, target);
    ASSERT_EQ(r.fit, LateralFit::matched) << target << ": " << r.message;
    EXPECT_NEAR(r.contact.lateral_force, target, 1e-6 * 55e3) << target;
    EXPECT_NEAR(r.contact.vertical_force, 55e3, 1e-3) << target;
  }
}

// From two-point contact (4.8 mm towards the flange) over the flange root onto the flank (7 mm)
// the lateral force rises with the shift, which the bracketed solve relies on. On the straight
// flank (beyond 6.8 mm) the contact angle is the flank's and Fy = Fz tan(angle) stays flat: there
// the locating of O on the 0.1 mm samples moves it by up to 1e-4 relative, allowed. (Where the
// flange root's region first appears, 4.6 to 4.75 mm, it merges with the tread's and the
// Kik-Piotrowski force dips: the method's known jump, wheel_rail.hpp.)
TEST(WheelRailLateral, LateralForceRisesWithTheShiftAcrossFlangeContact) {
  const WheelRailPair& pair = s1002_on_60e1();
  double previous = -1e300;
  int compared = 0;
  for (int step = 0; step <= 44; ++step) {
    WheelsetPose pose;
    pose.dy = 4.8e-3 + step * 0.05e-3;
    const WheelRailContact c = solve_wheel_rail(pair, pose, 55e3);
    ASSERT_NE(c.status, WheelRailStatus::not_converged) << pose.dy;
    if (c.status == WheelRailStatus::load_jump) continue;  // the load itself is missed there
    EXPECT_GE(c.lateral_force, previous * (1.0 - 1e-4)) << "dy " << pose.dy;
    previous = c.lateral_force;
    ++compared;
  }
  EXPECT_GE(compared, 40);
}

TEST(WheelRailLateral, KeepsThePositionBelowTheTreadsForce) {
  const WheelRailPair& pair = s1002_on_60e1();
  WheelsetPose pose;
  pose.dy = 2e-3;  // tread contact, 4.4 kN lateral at 55 kN
  const WheelRailContact tread = solve_wheel_rail(pair, pose, 55e3);
  const WheelRailLateral r = solve_wheel_rail_lateral(pair, pose, 55e3, 1e3);
  EXPECT_EQ(r.fit, LateralFit::kept_position);
  EXPECT_EQ(r.shift, 0.0);
  EXPECT_EQ(r.pose.dy, pose.dy);
  EXPECT_EQ(r.contact.lateral_force, tread.lateral_force);
  // More than the tread gives: the wheel moves onto its flange root.
  const WheelRailLateral up = solve_wheel_rail_lateral(pair, pose, 55e3, 15e3);
  ASSERT_EQ(up.fit, LateralFit::matched) << up.message;
  EXPECT_GT(up.shift, 0.0);
  EXPECT_NEAR(up.contact.lateral_force, 15e3, 1e-6 * 55e3);
}

TEST(WheelRailLateral, StopsWhereTheFlangeUnloads) {
  // On the flange, asking for less than the tread gives: the wheel backs off until the flange
  // carries nothing, and stays there.
  const WheelRailPair& pair = s1002_on_60e1();
  WheelsetPose pose;
  pose.dy = 6.5e-3;
  const WheelRailLateral r = solve_wheel_rail_lateral(pair, pose, 55e3, 100.0);
  ASSERT_EQ(r.fit, LateralFit::flange_unloaded) << r.message;
  EXPECT_LT(r.shift, 0.0);
  for (const WheelRailPatch& p : r.contact.patches) EXPECT_LE(p.contact_angle, 0.2);
  // 10 um closer to the flange, the flange carries load again.
  WheelsetPose closer = r.pose;
  closer.dy += 10e-6;
  const WheelRailContact c = solve_wheel_rail(pair, closer, 55e3);
  double steepest = 0.0;
  for (const WheelRailPatch& p : c.patches) steepest = std::max(steepest, p.contact_angle);
  EXPECT_GT(steepest, 0.2);
}

TEST(Wheelset, PrescribedLateralForceMovesOnlyThatWheel) {
  WheelsetState s = loaded(6.5e-3);
  s.lateral_force_left = 20e3;
  const WheelsetContact w = solve_wheelset(track(), s);
  ASSERT_TRUE(w.roll_converged) << w.message;
  ASSERT_EQ(w.left_fit, LateralFit::matched) << w.message;
  EXPECT_EQ(w.right_fit, LateralFit::not_prescribed);
  EXPECT_LT(w.left_shift, 0.0);  // 20 kN is less than the flange takes at 6.5 mm
  EXPECT_EQ(w.right_shift, 0.0);
  EXPECT_NEAR(w.left.lateral_force, 20e3, 1e-6 * 55e3);
  EXPECT_NEAR(w.left.vertical_force, 55e3, 1e-3);
  // The right wheel sits where the rigid wheelset puts it.
  const WheelRailPair& pair = s1002_on_60e1();
  const double y_tape = 0.5 * pair.back_to_back - pair.flange_back_y;
  EXPECT_NEAR(w.right_pose.dy,
              -s.dy + (std::cos(w.roll) - 1.0) * y_tape + std::sin(w.roll) * pair.wheel_radius,
              1e-15);
  // Both wheels still touch their rails with the roll the contact points give (5e-8 rad, as
  // in WheelsetRoll).
  EXPECT_NEAR(w.roll, roll_from_contact_points(pair, w), 5e-8);
}

// The roll depends on dy and yaw only: a solve for other loads that takes the roll found by an
// earlier one skips the roll iteration and gives the contacts a full solve gives, bit for bit.
TEST(Wheelset, KnownRollGivesTheFullSolvesContacts) {
  int compared = 0;
  for (double dy : {0.0, 4.8e-3, 6.5e-3}) {  // tread, two-point and flange contact
    WheelsetState first = loaded(dy);
    first.yaw = 1.5e-3;
    const WheelsetContact earlier = solve_wheelset(track(), first);
    ASSERT_TRUE(earlier.known_roll.has_value()) << dy;
    WheelsetState other = first;
    other.vertical_force_left = 62e3;
    other.vertical_force_right = 47e3;
    const WheelsetContact full = solve_wheelset(track(), other);
    other.known_roll = earlier.known_roll;
    const WheelsetContact reused = solve_wheelset(track(), other);
    EXPECT_EQ(reused.touch_evaluations, 0) << dy;
    EXPECT_GT(full.touch_evaluations, 0) << dy;
    EXPECT_EQ(reused.roll, full.roll) << dy;
    EXPECT_EQ(reused.centre_height, full.centre_height) << dy;
    EXPECT_EQ(reused.roll_converged, full.roll_converged) << dy;
    for (const auto& [a, b] : {std::pair{&reused.left, &full.left}, {&reused.right, &full.right}}) {
      ASSERT_EQ(a->patches.size(), b->patches.size()) << dy;
      EXPECT_EQ(a->vertical_force, b->vertical_force) << dy;
      EXPECT_EQ(a->lateral_force, b->lateral_force) << dy;
      for (std::size_t k = 0; k < a->patches.size(); ++k) {
        EXPECT_EQ(a->patches[k].normal_force, b->patches[k].normal_force) << dy;
        EXPECT_EQ(a->patches[k].y_rail, b->patches[k].y_rail) << dy;
        compared += 2;
      }
      compared += 2;
    }
  }
  EXPECT_GE(compared, 20);
  // A roll found at another shift or yaw is not taken: the roll is solved.
  WheelsetState moved = loaded(5e-3);
  moved.yaw = 1.5e-3;
  const WheelsetContact at_5mm = solve_wheelset(track(), moved);
  moved.known_roll = solve_wheelset(track(), loaded(4.8e-3)).known_roll;
  const WheelsetContact not_reused = solve_wheelset(track(), moved);
  EXPECT_GT(not_reused.touch_evaluations, 0);
  EXPECT_EQ(not_reused.roll, at_5mm.roll);
  // A prescribed lateral force moves the wheels and so the roll: a known roll is not taken,
  // and none is offered for reuse.
  WheelsetState pushed = loaded(6.5e-3);
  pushed.lateral_force_left = 20e3;
  const WheelsetContact pushed_alone = solve_wheelset(track(), pushed);
  EXPECT_FALSE(pushed_alone.known_roll.has_value());
  pushed.known_roll = solve_wheelset(track(), loaded(6.5e-3)).known_roll;
  const WheelsetContact pushed_offered = solve_wheelset(track(), pushed);
  EXPECT_EQ(pushed_offered.roll, pushed_alone.roll);
  EXPECT_EQ(pushed_offered.left_shift, pushed_alone.left_shift);
  // A roll that is not a number is refused.
  WheelsetState bad = loaded(0.0);
  bad.known_roll = KnownRoll{0.0, 0.0, std::nan(""), 0.0, true};
  EXPECT_THROW(solve_wheelset(track(), bad), InputError);
}

}  // namespace
}  // namespace wheelwear::contactgeom
