// `wheelwear route`: the vehicle on its route without wear, and the load collective it writes,
// which reads back as the very states the run would wear with.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "short_route.hpp"
#include "support/csv_table.hpp"
#include "support/run_command.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/vehicle/route.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace wheelwear::pipeline {
namespace {

namespace fs = std::filesystem;

class RouteCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wheelwear_route_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "route.toml") << kShortRoute;
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

std::string text_of(const fs::path& file) {
  std::stringstream s;
  s << std::ifstream(file).rdbuf();
  return s.str();
}

// Whether two numbers are the same double, NaN (an unset value) equal to NaN.
bool same(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

TEST_F(RouteCommandTest, WritesTheCollectiveTheRunWouldWearWith) {
  const fs::path csv = dir_ / "states.csv";
  const std::string base =
      "route --quasi-static --route " + (dir_ / "route.toml").string() + " -o " + csv.string();
  const testing::CommandResult r = testing::run_wheelwear(base + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(testing::json_number(r.out, "states"), 12.0);
  EXPECT_EQ(testing::json_number(r.out, "unconverged"), 0.0);

  // The same solve in this process: the built-in scene's profiles, vehicle and contact chain.
  const Scene scene = default_scene();
  VehicleRun run;
  run.vehicle = vehicle::default_vehicle();
  run.route = vehicle::read_route(dir_ / "route.toml");
  run.time_domain.enabled = false;
  run.critical_speed = false;
  const StateKernel kernel(scene);
  const profiles::Profile wheel =
      profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
  const VehicleCollective v = solve_vehicle_collective(run, kernel, {&wheel});

  // The file, read as a scene's collective, holds those states to the last bit.
  const Scene from_file =
      parse_scene("[load_collective]\nfile = \"" + csv.filename().string() + "\"\n", dir_);
  ASSERT_EQ(from_file.states.size(), v.states.size());
  int compared = 0;
  for (std::size_t i = 0; i < v.states.size(); ++i) {
    const WheelsetStateSpec &a = v.states[i], &b = from_file.states[i];
    EXPECT_EQ(b.label, a.label) << i;  // quoted where it holds commas (collective_csv)
    for (const auto& [x, y] : {std::pair{a.dy, b.dy},
                               {a.yaw, b.yaw},
                               {a.load_left, b.load_left},
                               {a.load_right, b.load_right},
                               {a.speed, b.speed},
                               {a.curve_radius, b.curve_radius},
                               {a.lateral_velocity, b.lateral_velocity},
                               {a.yaw_rate, b.yaw_rate},
                               {a.angular_velocity.value_or(NAN), b.angular_velocity.value_or(NAN)},
                               {a.roll.value_or(NAN), b.roll.value_or(NAN)},
                               {a.friction.value_or(NAN), b.friction.value_or(NAN)},
                               {a.friction_flange.value_or(NAN), b.friction_flange.value_or(NAN)},
                               {a.weight, b.weight}}) {
      EXPECT_TRUE(same(x, y)) << "state " << i << ": " << x << " against " << y;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 12 * 13);
  // The lubricated curve's gauge-face friction reaches the file.
  EXPECT_EQ(from_file.states[0].friction_flange.value_or(0.0), 0.1);

  // An existing file is kept unless --overwrite says otherwise.
  const std::string before = text_of(csv);
  const testing::CommandResult again = testing::run_wheelwear(base);
  EXPECT_NE(again.exit_code, 0);
  EXPECT_NE(again.err.find("--overwrite"), std::string::npos) << again.err;
  EXPECT_EQ(text_of(csv), before);
}

TEST_F(RouteCommandTest, SimulatesTheScenesTangentsAndTransitionsInTime) {
  std::ofstream(dir_ / "scene.toml")
      << "[vehicle]\nfile = \"default\"\n[route]\nfile = \"route.toml\"\n[time_domain]\n"
         "tangent_length_m = 20\nrun_in_m = 10\nsample_distance_m = 2\n";
  const testing::CommandResult r =
      testing::run_wheelwear("route " + (dir_ / "scene.toml").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(testing::json_number(r.out, "incomplete_pieces"), 0.0);
  // New S1002 on 60E1 1:40 with the built-in coach: 98.0 m/s, linearised about the centre with
  // the contact table the run builds and the scene's Hertz-calibrated normal method (95.3 m/s
  // with Kik-Piotrowski's; vehicle_stability_test.cpp: 95.5 m/s with it and the default table's
  // grid). 1 m/s: the table's interpolation and the search's 0.1 %.
  EXPECT_NEAR(testing::json_number(r.out, "critical_speed").value_or(0.0), 98.0, 1.0);
  // The curve's 4 states, and per wheelset 30-31 samples of the 60 m transition and 10-11 of
  // the tangent's 20 m at most 2 m apart (time_domain_run_test.cpp).
  const double states = testing::json_number(r.out, "states").value_or(-1.0);
  EXPECT_GE(states, 4.0 + 4.0 * (30.0 + 10.0));
  EXPECT_LE(states, 4.0 + 4.0 * (31.0 + 11.0));
  EXPECT_NE(r.out.find("\"pieces\": [{\"label\": \"section 2, transition"), std::string::npos)
      << r.out.substr(0, 400);
}

// A route given on the command line replaces the scene's, and with it the scene's warnings about
// its route (R 600 m without cant at 40 m/s: 0.41 m of cant deficiency, above the 0.3 m that
// warns, below the 0.8 m that would overturn the coach); the scene's other warnings stay (its
// 20 000 steps). `route` used to warn about the cant deficiency of a route it did not run.
TEST_F(RouteCommandTest, ARouteGivenOnTheCommandLineReplacesTheScenesWarnings) {
  std::ofstream(dir_ / "deficient.toml")
      << "[route]\nspeed_m_s = 40\n[[section]]\nkind = \"tangent\"\nlength_m = 300\n"
         "[[section]]\nkind = \"curve\"\nlength_m = 500\nradius_m = 600\ncant_m = 0\n";
  std::ofstream(dir_ / "straight.toml")
      << "[route]\nspeed_m_s = 40\n[[section]]\nkind = \"tangent\"\nlength_m = 300\n";
  std::ofstream(dir_ / "scene.toml")
      << "[run]\ndistance_m = 2e4\nstep_distance_m = 1\n[vehicle]\nfile = \"default\"\n"
         "critical_speed = false\n[route]\nfile = \"deficient.toml\"\n";
  const std::string base = "route " + (dir_ / "scene.toml").string() + " --quasi-static";
  const testing::CommandResult scenes = testing::run_wheelwear(base);
  EXPECT_EQ(scenes.exit_code, 0) << scenes.err;
  EXPECT_NE(scenes.err.find("cant deficiency"), std::string::npos) << scenes.err;
  EXPECT_NE(scenes.err.find("20000 steps"), std::string::npos) << scenes.err;
  const testing::CommandResult given =
      testing::run_wheelwear(base + " --route " + (dir_ / "straight.toml").string());
  EXPECT_EQ(given.exit_code, 0) << given.err;
  EXPECT_EQ(given.err.find("cant deficiency"), std::string::npos) << given.err;
  EXPECT_NE(given.err.find("20000 steps"), std::string::npos) << given.err;
}

// A route with a curve in which no balance exists is computed but not usable: its states are
// printed and written, and the command exits with 3 naming how many conditions did not
// converge (it exited with 0). The curve is that of exit_status_command_test.cpp's
// CurvingWithoutABalanceExitsWithThree: wheels without a flange (a cone of 1:40), R 300 m
// without cant at 30 m/s, friction 0.1. The scene gives the profiles alone: `route` takes the
// built-in coach where a scene names no vehicle (it was refused for having no collective).
TEST_F(RouteCommandTest, ARouteWithoutABalanceWritesItsStatesAndExitsWithThree) {
  std::string cone = "y_mm,z_mm\n";
  for (int y = -65; y <= 65; ++y)
    cone += std::to_string(y) + "," + std::to_string(-y / 40.0) + "\n";
  std::ofstream(dir_ / "cone.csv") << cone;
  std::ofstream(dir_ / "cone.toml") << "[wheel]\nprofile = \"cone.csv\"\nradius_m = 0.46\n"
                                       "[rail]\nprofile = \"60E1\"\ninclination = 0.025\n";
  std::ofstream(dir_ / "sharp.toml")
      << "[route]\nspeed_m_s = 30\nfriction = 0.1\n[[section]]\nkind = \"tangent\"\n"
         "length_m = 300\n[[section]]\nkind = \"curve\"\nlength_m = 500\nradius_m = 300\n"
         "cant_m = 0\n";
  const fs::path csv = dir_ / "states.csv";
  const testing::CommandResult r =
      testing::run_wheelwear("route " + (dir_ / "cone.toml").string() + " --quasi-static --route " +
                             (dir_ / "sharp.toml").string() + " -o " + csv.string() + " --json");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(testing::json_number(r.out, "unconverged"), 1.0) << r.out.substr(0, 300);
  EXPECT_NE(r.err.find("wheelwear: failed: 1 of 2 quasi-static conditions did not converge"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(fs::exists(csv));
}

// A measured wheel whose record is wavy on the scale of a millimetre (quasi_static_curving_test
// .cpp, AWavyMeasuredWheelFindsItsBalanceWhenFittedSmoother): with its fit smoothed over 2 mm
// ([wheel] smoothing_length_m) every condition of the built-in route converges (with the
// default 0.3 mm, 22 of 25 did not, in 56 s against 2 s).
// On the measured rail avg_HR.BAN as well, whose gauge face is steeper than the wheel's flank:
// its flank takes over from the tread where the roll's lever is short, and the R 500 m
// conditions found no balance until the wheel rested where both minima share its load (23 of
// 25 converged, in 7 s).
TEST_F(RouteCommandTest, AWavyMeasuredWheelFittedSmootherBalancesInEveryCondition) {
  for (const std::string rail : {std::string("60E1"), testing::test_data("measured/avg_HR.BAN")}) {
    std::ofstream(dir_ / "measured.toml", std::ios::trunc)
        << "[wheel]\nprofile = \"" << testing::test_data("measured/Car7216_0001r.whl")
        << "\"\nsmoothing_length_m = 2e-3\n[rail]\nprofile = \"" << rail
        << "\"\n[vehicle]\ncritical_speed = false\n";
    const testing::CommandResult r = testing::run_wheelwear(
        "route " + (dir_ / "measured.toml").string() + " --quasi-static --json");
    EXPECT_EQ(r.exit_code, 0) << rail << ": " << r.err;
    EXPECT_EQ(testing::json_number(r.out, "unconverged"), 0.0) << rail << ": " << r.err;
    // 4 wheelsets, 25 conditions
    EXPECT_EQ(testing::json_number(r.out, "states"), 25.0 * 4.0) << rail;
  }
}

// What reading a scene's profile file notices is the scene's warning, which every command the
// scene drives prints (it was dropped where the work read the profiles): here the wavy flank
// of that record at the default 0.3 mm fit, and nothing at 2 mm.
TEST_F(RouteCommandTest, AScenesProfileWarningsAreTheScenes) {
  const auto warnings_with = [&](const std::string& smoothing) {
    const std::string text = "[wheel]\nprofile = \"" +
                             testing::test_data("measured/Car7216_0001r.whl") + "\"\n" + smoothing +
                             "[rail]\nprofile = \"60E1\"\n";
    int wavy = 0;
    for (const std::string& w : parse_scene(text, dir_, {}, SceneUse::vehicle_solve).warnings)
      wavy += w.find("the flank is wavy") != std::string::npos;
    return wavy;
  };
  EXPECT_EQ(warnings_with(""), 1);
  EXPECT_EQ(warnings_with("smoothing_length_m = 2e-3\n"), 0);
}

TEST_F(RouteCommandTest, CollectiveCsvKeepsEveryLabelOneCellThatReadsBack) {
  std::vector<WheelsetStateSpec> states(3);
  const char* labels[] = {"curve, R 500\nleft", "#2 S-curve, wheelset 1", "  padded  "};
  for (std::size_t i = 0; i < states.size(); ++i) {
    states[i].label = labels[i];
    states[i].dy = 1e-3 / 3.0;
    states[i].load_left = states[i].load_right = 55e3;
    states[i].speed = 20.0;
    states[i].weight = 1.0 + static_cast<double>(i);
  }
  std::ofstream(dir_ / "labels.csv") << collective_csv(states);
  const Scene s = parse_scene("[load_collective]\nfile = \"labels.csv\"\n", dir_);
  // Every row came back (none read as a comment or split), with its label as written (a label
  // is one line: the line break reads as a blank) and its numbers.
  ASSERT_EQ(s.states.size(), 3u);
  EXPECT_EQ(s.states[0].label, "curve, R 500 left");
  EXPECT_EQ(s.states[1].label, "#2 S-curve, wheelset 1");
  EXPECT_EQ(s.states[2].label, "  padded  ");
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(s.states[i].dy, 1e-3 / 3.0);
    EXPECT_EQ(s.states[i].weight, 1.0 + static_cast<double>(i));
  }
}

}  // namespace
}  // namespace wheelwear::pipeline
