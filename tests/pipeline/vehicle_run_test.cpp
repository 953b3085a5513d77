// A run driven by the vehicle on its route: the route's running conditions, the states the
// vehicle makes (the kernel meets the vehicle's forces and free rolling), the scene's keys, the
// results' records and a resume identical to an uninterrupted run.

#include "wheelwear/pipeline/vehicle_run.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>

#include "short_route.hpp"
#include "vehicle_record.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::pipeline {
namespace {

// Without `time_domain` keys every section is solved quasi-statically; the critical speed only
// when asked.
std::string vehicle_scene(double distance, double step, double resolve_depth,
                          const std::string& time_domain = "enabled = false\n",
                          bool critical_speed = false) {
  return "[contact]\ngrid_nx = 12\ngrid_ny = 12\n[run]\ndistance_m = " + std::to_string(distance) +
         "\nstep_distance_m = " + std::to_string(step) +
         "\nmax_depth_step_m = 1e-3\n[vehicle]\nfile = \"default\"\nresolve_depth_m = " +
         std::to_string(resolve_depth) +
         "\ncritical_speed = " + (critical_speed ? "true" : "false") +
         "\n[route]\nfile = \"route.toml\"\n[time_domain]\n" + time_domain;
}

TEST(RouteCases, DefaultRouteKeepsEverySectionsShare) {
  const vehicle::Route route = vehicle::default_route();
  const std::vector<RouteCase> cases = route_cases(route);
  // data/routes/default.toml: one tangent case (its five tangents), ten curves (five radii,
  // both hands) and fourteen transitions of distinct end values.
  ASSERT_EQ(cases.size(), 25u);
  double total = 0.0;
  for (const RouteCase& c : cases) total += c.share;
  EXPECT_NEAR(total, 1.0, 1e-12);  // the route's length, up to rounding
  // The route file's table: 54320 m of tangent, 3000 m of the lubricated R 500 m of 100 km.
  EXPECT_EQ(cases[0].curve.running.curve_radius, 0.0);
  EXPECT_NEAR(cases[0].share, 0.5432, 1e-12);
  int lubricated = 0;
  for (const RouteCase& c : cases) {
    if (c.curve.running.rail_friction().flange != 0.1) continue;
    ++lubricated;
    EXPECT_EQ(c.curve.running.curve_radius, 500.0);
    EXPECT_NEAR(c.share, 0.03, 1e-12);
    EXPECT_EQ(c.curve.running.friction, 0.3);
  }
  EXPECT_EQ(lubricated, 1);
}

// The wear kernel's forces at the vehicle's states against the vehicle's own, with `slack` [N]
// added to the tolerances of the direct solve (the contact table's miss); `braking` [N] per axle
// on the route's curve (all four axles of the built-in coach are powered).
// With `kernel_on_table` the kernel interpolates the vehicle's own tables, as a run's step does
// ([vehicle] wear_from_table).
void expect_kernel_meets_vehicle(bool contact_table, double slack, double braking = 0.0,
                                 bool kernel_on_table = false) {
  Scene scene = parse_scene(
      "[load_collective]\n[[load_collective.state]]\naxle_load_N = 1e5\n"
      "speed_m_s = 40\n",
      {});
  VehicleRun run = short_route_run();
  run.route.sections.front().traction_N = braking;
  run.contact_table = contact_table;
  const StateKernel kernel(scene);
  const profiles::Profile wheel = profiles::wheel_profile("S1002", 0.46, {});
  const VehicleCollective v = solve_vehicle_collective(run, kernel, {&wheel});
  ASSERT_EQ(v.cases.size(), 3u);
  ASSERT_EQ(v.states.size(), 12u);
  EXPECT_EQ(v.unconverged, 0);
  const contactgeom::WheelsetOnTrack track{kernel.pair(wheel), kernel.pair(wheel)};
  int compared = 0;
  for (std::size_t i = 0; i < v.states.size(); ++i) {
    const WheelsetStateSpec& s = v.states[i];
    // A quarter of its case's share of the route per wheelset.
    EXPECT_NEAR(s.weight, (std::array{0.5, 0.03, 0.47})[i / 4] / 4.0, 1e-15);
    const vehicle::CurvingWheelset& w = v.curving[i / 4].wheelsets[i % 4];
    bool interpolated = false;
    const contactgeom::WheelsetContact contact = kernel.contact(
        track, s, kernel_on_table ? v.contact_tables.at({0, 0}).get() : nullptr, &interpolated);
    EXPECT_EQ(interpolated, kernel_on_table);
    double torque = 0.0, scale = 0.0;
    for (int side = 0; side < 2; ++side) {
      const WheelOutcome out = kernel.wheel(contact, side, s, wheel);
      ASSERT_TRUE(out.usable());
      const contactgeom::WheelRailContact& c = side == 0 ? contact.left : contact.right;
      ASSERT_EQ(out.patches.size(), c.patches.size());
      double Fx = 0.0;
      for (std::size_t p = 0; p < out.patches.size(); ++p) {
        const tangential::CreepForces& f = out.patches[p].solution.forces;
        Fx += f.Fx;
        torque += f.Fx * c.patches[p].rolling_radius -
                  f.Mz.value_or(0.0) * std::sin(c.patches[p].contact_angle);
        scale += std::abs(f.Fx) * c.patches[p].rolling_radius;
      }
      // The same contact (solved for the vertical force the vehicle's contact carried) and the
      // same creepages: the kernel's force is the vehicle's, up to the normal solve's load
      // tolerance (1e-9) carried through the creep force.
      EXPECT_NEAR(Fx, w.forces.wheels[static_cast<std::size_t>(side)].Fx,
                  1e-6 * 55e3 + 1e-3 + slack);
      ++compared;
    }
    // Free rolling (or the brake's torque F r0 in the curve): the axle torque within the curving
    // solver's tolerance of 1e-7 of the sum of |Fx| r (1e-6 as the equilibrium test states it),
    // plus what the load tolerance carries.
    const double drive = i / 4 == 0 ? braking * 0.46 : 0.0;
    EXPECT_LE(std::abs(torque - drive), 1e-6 * scale + (1e-3 + slack) * 0.46) << s.label;
  }
  EXPECT_EQ(compared, 24);
}

TEST(VehicleCollective, KernelMeetsTheVehiclesForcesAndFreeRolling) {
  expect_kernel_meets_vehicle(false, 0.0);
}

// Braking in the curve: the states carry the braked axles' spin, so the wear's creep forces brake
// as the vehicle's do.
TEST(VehicleCollective, KernelMeetsTheVehiclesForcesUnderBraking) {
  expect_kernel_meets_vehicle(false, 0.0, -10e3);
}

TEST(VehicleCollective, KernelMeetsTheTabulatedVehiclesForces) {
  // The vehicle's forces from its contact table, the kernel's from direct solves: they differ by
  // the table's miss in the patches' rolling radii (1 um: a creepage of 2e-6, ~40 N of Fx) and
  // shapes (a miss of 2e-4 in an SDEC's b and psi moves Fx by ~80 N through the spin's coupling
  // into Fx, measured on the tread at R 6000 m; shapes are not refined for): 120 N.
  expect_kernel_meets_vehicle(true, 120.0);
}

// On the vehicle's own tables the kernel's contact is the one the vehicle's balance was found
// with: its forces meet the vehicle's to the direct solve's tolerances, without the table's miss.
TEST(VehicleCollective, KernelOnTheVehiclesTablesMeetsItsForces) {
  expect_kernel_meets_vehicle(true, 0.0, 0.0, true);
}

TEST(VehicleScene, KeysAndTheirErrors) {
  const std::string route = "[route]\nfile = \"default\"\n";
  const Scene s =
      parse_scene("[vehicle]\nfile = \"default\"\nwheelsets = \"leading\"\n" + route, {});
  ASSERT_TRUE(s.vehicle_run);
  EXPECT_TRUE(s.states.empty());
  EXPECT_EQ(s.vehicle_run->worn_wheelsets(), (std::vector<int>{0, 2}));
  EXPECT_EQ(s.vehicle_run->resolve_depth, 0.05e-3);
  EXPECT_TRUE(s.vehicle_run->contact_table);
  EXPECT_FALSE(parse_scene("[vehicle]\nfile = \"default\"\ncontact_table = false\n" + route, {})
                   .vehicle_run->contact_table);
  EXPECT_EQ(s.vehicle_run->route.sections.size(), 29u);
  EXPECT_FALSE(s.vehicle_run->time_domain.redraw);
  EXPECT_TRUE(
      parse_scene("[vehicle]\nfile = \"default\"\n" + route + "[time_domain]\nredraw = true\n", {})
          .vehicle_run->time_domain.redraw);
  const auto message = [](const std::string& text) {
    try {
      parse_scene(text, {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("[vehicle]\nfile = \"default\"\n").find("[route] file is missing"),
            std::string::npos);
  EXPECT_NE(message("[vehicle]\nfile = \"nope.toml\"\n" + route).find("no such file"),
            std::string::npos);
  EXPECT_NE(
      message("[vehicle]\nfile = \"default\"\nwheelsets = \"first\"\n" + route).find("use all"),
      std::string::npos);
  EXPECT_NE(message("[vehicle]\nfile = \"default\"\nresolve_depth_m = -1\n" + route)
                .find("resolve_depth_m"),
            std::string::npos);
  EXPECT_NE(message("[vehicle]\nfile = \"default\"\n" + route +
                    "[[load_collective.state]]\naxle_load_N = 1e5\nspeed_m_s = 40\n")
                .find("give one"),
            std::string::npos);
  EXPECT_NE(message("title = \"x\"\n").find("[vehicle] file"), std::string::npos);
  EXPECT_NE(message("[vehicle]\nfile = \"default\"\n" + route + "[time_domain]\nredraw = 1\n")
                .find("redraw"),
            std::string::npos);
}

class VehicleRunTest : public WearRunTest {
 protected:
  // Runs `text` into `killed`, interrupted after its second step (step 1), then resumes it.
  void interrupted_then_resumed(const std::string& text, const fs::path& killed) {
    RunOptions stop;
    stop.progress = [](const RunProgress& p) {
      if (p.step == 1) throw std::runtime_error("interrupted");
    };
    EXPECT_THROW(run_scene(parse_scene(text, dir_), text, dir_, false, killed, stop),
                 std::runtime_error);
    ASSERT_EQ(ResultsFile::read(killed).completed_steps(), 2);
    resume_run(killed, {});
  }
  // Runs `text` into `killed` as interrupted_then_resumed does, and compares every array of its
  // three steps with `reference`'s.
  void expect_resumed_identically(const std::string& text, const fs::path& killed,
                                  const ResultsFile& reference) {
    interrupted_then_resumed(text, killed);
    ASSERT_FALSE(HasFatalFailure());
    const ResultsFile res = ResultsFile::read(killed);
    ASSERT_EQ(res.completed_steps(), 3);
    int compared = 0;
    for (int step = 0; step < 3; ++step) {
      expect_same_arrays(reference, res, step, "", compared);
      ASSERT_FALSE(HasFatalFailure());
    }
    EXPECT_GT(compared, 1000);
  }
};

TEST_F(VehicleRunTest, RecordsTheVehicleAndResumesToIdenticalResults) {
  write("route.toml", kShortRoute);
  // Solved at every step (resolve depth 0), three steps of 1 km; the transition and a short
  // stretch of the tangent simulated in time, sampled every 2 m.
  const std::string text = vehicle_scene(
      2e3, 1e3, 0.0, "tangent_length_m = 20\nrun_in_m = 10\nsample_distance_m = 2\n", true);
  const fs::path reference = dir_ / "reference.h5", killed = dir_ / "killed.h5";
  run(text, reference);
  const ResultsFile ref = ResultsFile::read(reference);
  ASSERT_EQ(ref.completed_steps(), 3);
  for (int step = 0; step < 3; ++step) {
    EXPECT_EQ(ref.read_step_array(step, "vehicle/solved").at(0), 1.0);
    // The curve, and the tangent that starts the tangent's piece (the transition's starts in
    // the curve): 2 cases x 4 wheelsets.
    EXPECT_EQ(ref.read_step_array(step, "vehicle/cases/dy").size(), 8u);
    EXPECT_EQ(ref.read_step_array(step, "vehicle/cases/Q").size(), 16u);
    EXPECT_EQ(ref.read_step_array(step, "vehicle/pieces/completed"),
              (std::vector<double>{1.0, 1.0}));
    // Searched at every solve, from the last solve's on: 98.0 m/s on the new profiles as
    // `wheelwear route` finds it (route_command_test.cpp), moving little over 2 km of wear.
    EXPECT_NEAR(ref.read_step_array(step, "vehicle/critical_speed").at(0), 98.0, 1.0) << step;
    // Every wheelset through the 60 m transition at most 2 m apart: 30 or 31 samples, as the
    // car body's spacing (81.5 m over 41 intervals) falls on the stretch; the tangent's 20 m
    // (41.5 m over 21 intervals): 10 or 11.
    const auto samples = ref.read_step_array(step, "vehicle/pieces/samples");
    ASSERT_EQ(samples.size(), 8u);
    double sampled = 0.0;
    for (std::size_t k = 0; k < 8; ++k) {
      EXPECT_GE(samples[k], k < 4 ? 30.0 : 10.0) << k;
      EXPECT_LE(samples[k], k < 4 ? 31.0 : 11.0) << k;
      sampled += samples[k];
    }
    const auto weight = ref.read_step_array(step, "collective/weight");
    ASSERT_EQ(static_cast<double>(weight.size()), 4.0 + sampled);
    double total = 0.0;
    for (double w : weight) total += w;
    EXPECT_NEAR(total, 1.0, 1e-12);
  }

  expect_resumed_identically(text, killed, ref);
}

// [time_domain] redraw: every solve draws its own track. Draw 0 is the plan's (a run without
// redraw makes the same first step); later solves run the pieces over other tracks, so the
// pieces' states differ from the fixed track's on the same profiles; and a killed run resumes to
// the same file, each solve's track fixed by its step.
TEST_F(VehicleRunTest, RedrawnTracksDifferAtEverySolveAndResumeIdentically) {
  write("route.toml", kShortRoute);
  const std::string pieces = "tangent_length_m = 20\nrun_in_m = 10\nsample_distance_m = 2\n";
  const std::string text = vehicle_scene(2e3, 1e3, 0.0, pieces + "redraw = true\n");
  const fs::path fixed = dir_ / "fixed.h5", redrawn = dir_ / "redrawn.h5";
  const fs::path killed = dir_ / "killed.h5";
  run(vehicle_scene(2e3, 1e3, 0.0, pieces), fixed);
  run(text, redrawn);
  const ResultsFile a = ResultsFile::read(fixed), b = ResultsFile::read(redrawn);
  ASSERT_EQ(b.completed_steps(), 3);
  // Step 0: the same track, the same states and wear.
  EXPECT_EQ(a.read_step_array(0, "collective/dy_m"), b.read_step_array(0, "collective/dy_m"));
  EXPECT_EQ(a.read_step_array(1, "wheel/z"), b.read_step_array(1, "wheel/z"));
  // Step 1, on the same profiles: the curve's four states alike, the pieces' states not.
  const auto dy_a = a.read_step_array(1, "collective/dy_m");
  const auto dy_b = b.read_step_array(1, "collective/dy_m");
  ASSERT_EQ(dy_a.size(), dy_b.size());
  int differ = 0;
  for (std::size_t i = 0; i < dy_a.size(); ++i) {
    if (i < 4)
      EXPECT_EQ(dy_a[i], dy_b[i]) << i;
    else if (dy_a[i] != dy_b[i])
      ++differ;
  }
  EXPECT_GT(differ, static_cast<int>(dy_a.size() - 4) / 2);

  expect_resumed_identically(text, killed, b);
}

TEST(RedrawPieces, DrawZeroIsThePlansAndNoTwoDrawsShareATrack) {
  VehicleRun run = short_route_run();
  run.time_domain.enabled = true;
  run.direction = RunningDirection::both;
  const RoutePlan plan = route_plan(run);
  ASSERT_GE(plan.pieces.size(), 4u);  // both ways
  std::vector<DynamicPiece> pieces = plan.pieces;
  redraw_pieces(pieces, run, 0);
  std::set<std::uint64_t> seeds;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    EXPECT_EQ(pieces[i].seed, plan.pieces[i].seed) << i;
    seeds.insert(pieces[i].seed);
  }
  for (std::uint64_t draw = 1; draw <= 3; ++draw) {
    pieces = plan.pieces;
    redraw_pieces(pieces, run, draw);
    for (const DynamicPiece& p : pieces) seeds.insert(p.seed);
  }
  EXPECT_EQ(seeds.size(), 4 * plan.pieces.size());
}

TEST_F(VehicleRunTest, ResolvesOnlyOnceTheWearReachesTheDepth) {
  write("route.toml", kShortRoute);
  // 1e-3 m (the largest depth accepted) is not reached in 2 km: the vehicle is solved once.
  const fs::path out = dir_ / "run.h5";
  run(vehicle_scene(2e3, 1e3, 1e-3), out);
  const ResultsFile file = ResultsFile::read(out);
  ASSERT_EQ(file.completed_steps(), 3);
  EXPECT_EQ(file.read_step_array(0, "vehicle/solved").at(0), 1.0);
  // Its states are worn on the tables it ran on at the step it was solved, solved directly on
  // the worn profiles after: 9 distinct contacts of 12 states (the four centred wheelsets of the
  // tangent share one).
  EXPECT_EQ(file.read_step_array(0, "table_contacts").at(0), 9.0);
  double depth = 0.0;
  for (int step = 1; step < 3; ++step) {
    EXPECT_EQ(file.read_step_array(step, "vehicle/solved").at(0), 0.0);
    EXPECT_EQ(file.read_step_array(step, "table_contacts").at(0), 0.0);
    // The same states as the solve of step 0.
    EXPECT_EQ(file.read_step_array(step, "collective/dy_m"),
              file.read_step_array(0, "collective/dy_m"));
    const double d = file.read_step_array(step, "vehicle/depth_since_solve").at(0);
    EXPECT_GE(d, depth);
    depth = d;
  }
  EXPECT_LT(depth, 1e-3);

  // A depth of 1 nm is reached by every step's wear: solved again at every step.
  const fs::path often = dir_ / "often.h5";
  run(vehicle_scene(2e3, 1e3, 1e-9), often);
  const ResultsFile again = ResultsFile::read(often);
  for (int step = 0; step < 3; ++step)
    EXPECT_EQ(again.read_step_array(step, "vehicle/solved").at(0), 1.0) << step;
}

TEST_F(VehicleRunTest, ResumedBetweenSolvesKeepsThePiecesAndTheCriticalSpeed) {
  write("route.toml", kShortRoute);
  // Solved once (1 mm of wear is not reached in 2 km): a run resumed after step 1 records the
  // pieces and the critical speed of that one solve, read back from the file, until its end.
  const std::string text = vehicle_scene(
      2e3, 1e3, 1e-3, "tangent_length_m = 20\nrun_in_m = 10\nsample_distance_m = 2\n", true);
  const fs::path reference = dir_ / "reference.h5", killed = dir_ / "killed.h5";
  run(text, reference);
  interrupted_then_resumed(text, killed);
  ASSERT_FALSE(HasFatalFailure());
  const ResultsFile ref = ResultsFile::read(reference), res = ResultsFile::read(killed);
  ASSERT_EQ(res.completed_steps(), 3);
  int compared = 0;
  for (int step = 0; step < 3; ++step) {
    EXPECT_EQ(ref.read_step_array(step, "vehicle/solved").at(0), step == 0 ? 1.0 : 0.0);
    expect_same_arrays(ref, res, step, "vehicle/", compared);
    ASSERT_FALSE(HasFatalFailure());
    for (const char* text_name :
         {"vehicle/pieces/label", "vehicle/pieces/message", "vehicle/critical_speed_note"}) {
      const std::string path = ResultsFile::step_group(step) + "/" + text_name;
      EXPECT_EQ(ref.read_text(path), res.read_text(path)) << path;
      ++compared;
    }
  }
  EXPECT_GT(compared, 200);
}

// A resumed run rebuilds each case's solution from the step's record, and a case that keeps
// that solution at the next solve makes its states from it: they must be the states the
// uninterrupted run makes (the vertical forces the contact was solved for, the roll), not
// zero loads.
TEST_F(VehicleRunTest, RecordedCasesMakeTheSameStatesAsTheSolvedOnes) {
  const Scene scene = parse_scene(
      "[contact]\ngrid_nx = 12\ngrid_ny = 12\n[load_collective]\n[[load_collective.state]]\n"
      "axle_load_N = 1e5\nspeed_m_s = 40\n",
      {});
  const VehicleRun run = short_route_run();
  const StateKernel kernel(scene);
  const profiles::Profile wheel = profiles::wheel_profile("S1002", 0.46, {});
  const VehicleCollective v = solve_vehicle_collective(run, kernel, {&wheel});
  GroupRecord g;
  detail::add_vehicle_cases(g, v);
  ResultsFile file = ResultsFile::create(dir_ / "cases.h5", "", false);
  file.append_step(g);
  const std::vector<vehicle::VehicleCurving> read =
      detail::read_vehicle_cases(file, 0, v.cases.size());
  int compared = 0;
  for (std::size_t i = 0; i < v.cases.size(); ++i) {
    for (int k = 0; k < vehicle::kWheelsets; ++k) {
      const WheelsetStateSpec a = wheelset_state(v.cases[i], v.curving[i], k, 1.0);
      const WheelsetStateSpec b = wheelset_state(v.cases[i], read[i], k, 1.0);
      EXPECT_EQ(b.load_left, a.load_left);
      EXPECT_EQ(b.load_right, a.load_right);
      EXPECT_EQ(b.roll, a.roll);
      EXPECT_EQ(b.dy, a.dy);
      EXPECT_EQ(b.yaw, a.yaw);
      EXPECT_EQ(b.angular_velocity, a.angular_velocity);
      EXPECT_GT(b.load_left, 0.0);
      compared += 6;
    }
  }
  EXPECT_EQ(compared, 72);
}

}  // namespace
}  // namespace wheelwear::pipeline
