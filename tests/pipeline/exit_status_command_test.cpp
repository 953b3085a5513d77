// One set of exit statuses for every command (docs/cli.md, "Exit status"), one rule for every
// output file, the program's version on the command line and in the results file, and the
// run's summary.

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>

#include "support/csv_table.hpp"
#include "support/run_command.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/pipeline/results_file.hpp"

namespace wheelwear::pipeline {
namespace {

using testing::run_wheelwear;

const std::regex kVersion(
    R"(wheelwear [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{12}(-modified)?|unknown)\))");

TEST(ExitStatus, VersionAndHelpSucceed) {
  const auto version = run_wheelwear("--version");
  EXPECT_EQ(version.exit_code, 0) << version.err;
  EXPECT_TRUE(std::regex_search(version.out, kVersion)) << version.out;
  EXPECT_EQ(run_wheelwear("--help").exit_code, 0);
  EXPECT_EQ(run_wheelwear("run --help").exit_code, 0);
}

// Every parse error is bad usage: status 2, `wheelwear: error:` and the hint.
TEST(ExitStatus, EveryParseErrorIsBadUsage) {
  int compared = 0;
  for (const char* args : {"", "contact --dy", "creep --a abc", "run --bogus",
                           "contact --dy 0 --load 55000 --gauge-side up", "nosuch",
                           // creepages without the tangential problem they belong to
                           "contact --dy 0 --load 55000 --vx 1e-3"}) {
    const auto r = run_wheelwear(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("wheelwear: ", 0), 0u) << args << ": " << r.err;
    ++compared;
  }
  EXPECT_EQ(compared, 7);
}

class OutputRule : public WearRunTest {};

// A rail's inclination is 1:N or a slope everywhere: contact --incl 1:40 and 0.025 are one
// angle, so one contact to the last digit.
TEST(Inclination, OneInFortyIsTheSlopeOfOneFortieth) {
  const std::string args = "contact --dy 0.003 --load 55000 --json --incl ";
  const auto ratio = run_wheelwear(args + "1:40");
  const auto slope = run_wheelwear(args + "0.025");
  ASSERT_EQ(ratio.exit_code, 0) << ratio.err;
  EXPECT_EQ(ratio.out, slope.out);
  const auto mistyped = run_wheelwear(args + "40");
  EXPECT_EQ(mistyped.exit_code, 2);
  EXPECT_NE(mistyped.err.find("--incl 40: give 1:N"), std::string::npos) << mistyped.err;
}

// Computed but no usable answer: a curve in which no balance exists prints its last iterate and
// exits with 3. Wheels without a flange (a cone of 1:40) at 3.0 m/s^2 of uncompensated lateral
// acceleration (R 300 m, 30 m/s, no cant) with friction 0.1: the rails can push the vehicle
// inwards by at most about 0.1 g through the creep forces and 0.025 g through the cone.
TEST_F(OutputRule, CurvingWithoutABalanceExitsWithThree) {
  std::string cone = "y_mm,z_mm\n";
  for (int y = -65; y <= 65; ++y)
    cone += std::to_string(y) + "," + std::to_string(-y / 40.0) + "\n";
  write("cone.csv", cone);
  write("cone.toml", "[wheel]\nprofile = \"" + (dir_ / "cone.csv").string() +
                         "\"\nradius_m = 0.46\n[rail]\nprofile = \"60E1\"\ninclination = "
                         "0.025\n[[load_collective.state]]\naxle_load_N = 1e5\nspeed_m_s = 30\n");
  const auto r = run_wheelwear("curving " + (dir_ / "cone.toml").string() +
                               " --radius 300 --cant 0 --speed 30 --friction 0.1 --json");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.out.find("\"converged\": false"), std::string::npos) << r.out.substr(0, 200);
  EXPECT_NE(r.err.find("wheelwear: failed: curving did not converge"), std::string::npos) << r.err;
}

// A curve whose unbalanced lateral acceleration would lift the centred vehicle's inner wheels
// (R 300 m, no cant, 40 m/s: 0.815 m of cant deficiency, 5.3 m/s^2) has no balance to solve:
// `curving` and a run on a route with it are refused as bad input (status 2) with the curve, its
// cant deficiency and the fix named, and the run before its results file is created. The
// -2.4 kN is the centred coach's inner wheel load, W/2 - (moment of the weights' and the
// centrifugal forces about the rail) / (2 x 0.75 m), printed by the vehicle library's wheel_loads.
TEST_F(OutputRule, AnOverturningCurveIsRefusedBeforeAnythingIsWritten) {
  const auto c = run_wheelwear("curving --radius 300 --cant 0 --speed 40");
  EXPECT_EQ(c.exit_code, 2) << c.err;
  EXPECT_NE(c.err.find("the vehicle overturns in this curve: at R 300 m, cant 0 m and 40 m/s "
                       "(cant deficiency 0.815 m) its right wheels carry -2.4 kN"),
            std::string::npos)
      << c.err;
  // Traction beyond a powered axle's adhesion (0.3 x 109.7 kN) is refused the same way.
  const auto t = run_wheelwear("curving --radius 1000 --cant 0.1 --speed 33 --traction 1e5");
  EXPECT_EQ(t.exit_code, 2) << t.err;
  EXPECT_NE(t.err.find("traction of 100.0 kN per powered axle is beyond the adhesion of "
                       "wheelset 1"),
            std::string::npos)
      << t.err;
  write("fast.toml",
        "[route]\nspeed_m_s = 40\n[[section]]\nkind = \"tangent\"\nlength_m = 300\n"
        "[[section]]\nkind = \"curve\"\nlength_m = 500\nradius_m = 300\ncant_m = 0\n"
        "name = \"R300 too fast\"\n");
  write("scene.toml", "[vehicle]\nfile = \"default\"\n[route]\nfile = \"" +
                          (dir_ / "fast.toml").string() + "\"\n[time_domain]\nenabled = false\n");
  const auto r =
      run_wheelwear("run " + (dir_ / "scene.toml").string() + " -o " + (dir_ / "out.h5").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("route condition \"R300 too fast\": the vehicle overturns"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("wheelwear: warning: "), std::string::npos) << r.err;  // above 0.3 m
  EXPECT_FALSE(fs::exists(dir_ / "out.h5"));
}

// A results file HDF5 cannot read is named with HDF5's own reason and the fix, where it said
// only "H5Fopen failed": an empty file and a text file have no signature, a copy cut short is
// truncated (its size against the size it records). Nothing is written to them.
TEST_F(OutputRule, ADamagedResultsFileIsRefusedWithHdf5sReason) {
  run(small_scene(1e3, 1e3, 1e-3), dir_ / "whole.h5");
  fs::copy_file(dir_ / "whole.h5", dir_ / "cut.h5");
  fs::resize_file(dir_ / "cut.h5", fs::file_size(dir_ / "whole.h5") / 3);
  write("empty.h5", "");
  write("text.h5", "hello\n");
  int compared = 0;
  for (const auto& [name, reason] : {std::pair{"cut.h5", "truncated file: eof = "},
                                     {"empty.h5", "file signature not found"},
                                     {"text.h5", "file signature not found"}}) {
    const auto size = fs::file_size(dir_ / name);
    const auto r = run_wheelwear("run --resume " + (dir_ / name).string());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(std::string("unreadable HDF5 (") + reason), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("copy it again, or start a new run with -o"), std::string::npos) << r.err;
    EXPECT_EQ(fs::file_size(dir_ / name), size) << name;
    compared += 4;
  }
  EXPECT_EQ(compared, 12);
}

// sum_Y of `curving --json` is the rails' lateral force on the wheelset (+ left), Y_right - Y_left
// as the results file's vehicle/cases/sum_Y: zero for the symmetric vehicle centred on tangent
// track (where Y_left + Y_right, what it was, is twice a wheel's gravitational Y, 1.6 kN).
TEST_F(OutputRule, CurvingsSumYIsTheWheelsetsLateralForce) {
  const auto r = run_wheelwear("curving --radius 0 --cant 0 --speed 30 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::regex sum_y(R"re("sum_Y": ([-+0-9.eE]+))re");
  int compared = 0;
  for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), sum_y);
       it != std::sregex_iterator(); ++it) {
    EXPECT_NEAR(std::stod((*it)[1].str()), 0.0, 1e-6) << r.out.substr(0, 300);
    ++compared;
  }
  EXPECT_EQ(compared, 4);
}

std::string text_of(const fs::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// An existing file is replaced only with --overwrite, and no folder is made for an output.
TEST_F(OutputRule, ExistingFilesNeedOverwriteAndNoFolderIsMade) {
  const fs::path profile = dir_ / "wheel.csv", map = dir_ / "map.csv";
  ASSERT_EQ(run_wheelwear("profile --wheel S1002 --out " + profile.string()).exit_code, 0);
  ASSERT_EQ(run_wheelwear("wear --dy 0.002 --load 55000 --map " + map.string()).exit_code, 0);
  const std::string profile_text = text_of(profile), map_text = text_of(map);
  // Refused, the file as it was.
  for (const auto& [args, flag] :
       {std::pair{"profile --wheel S1002 --spacing 1e-3 --out " + profile.string(), "--out"},
        std::pair{"wear --dy 0.003 --load 55000 --map " + map.string(), "--map"}}) {
    const auto r = run_wheelwear(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find(std::string(flag) + " "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("pass --overwrite"), std::string::npos) << r.err;
  }
  EXPECT_EQ(text_of(profile), profile_text);
  EXPECT_EQ(text_of(map), map_text);
  // Replaced with --overwrite.
  ASSERT_EQ(
      run_wheelwear("profile --wheel S1002 --spacing 1e-3 --overwrite --out " + profile.string())
          .exit_code,
      0);
  EXPECT_NE(text_of(profile), profile_text);
  // No folder made: a missing one is bad input, and nothing is left behind.
  const fs::path missing = dir_ / "missing";
  for (const std::string& args :
       {"profile --wheel S1002 --out " + (missing / "wheel.csv").string(),
        "run --export-default-scene " + (missing / "scene").string(),
        "curving --export-default-vehicle " + (missing / "vehicle").string()}) {
    const auto r = run_wheelwear(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(missing)) << args;
  }
  // The exported folder itself may be new when its parent is there.
  EXPECT_EQ(run_wheelwear("run --export-default-scene " + (dir_ / "scene").string()).exit_code, 0);
  EXPECT_TRUE(fs::exists(dir_ / "scene" / "default.toml"));
}

// The program and its commit go into /run_info/program (outside the steps, which stay equal
// across builds).
TEST_F(OutputRule, TheResultsFileRecordsTheProgram) {
  write("scene.toml", small_scene(10e3, 10e3, 1e-3));
  const fs::path out = dir_ / "run.h5";
  const auto r = run_wheelwear("run -q " + (dir_ / "scene.toml").string() + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto program = ResultsFile::read(out).read_text("/run_info/program");
  ASSERT_TRUE(program);
  EXPECT_TRUE(std::regex_match(*program, kVersion)) << *program;
}

// The summary prints each EN 15313 parameter's change in a column of its own, to 0.1 um: a
// short run's change (micrometres) is far below the values' own last digit.
TEST_F(OutputRule, TheSummaryShowsEachParametersChange) {
  write("scene.toml", small_scene(10e3, 10e3, 1e-3));
  const fs::path out = dir_ / "run.h5";
  const auto r = run_wheelwear("run -q " + (dir_ / "scene.toml").string() + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ResultsFile file = ResultsFile::read(out);
  const int last = file.completed_steps() - 1;
  int compared = 0;
  for (const char* name : {"Sh", "Sd", "qR"}) {
    const std::regex line("  " + std::string(name) +
                          R"( \[mm\] +([0-9.]+) +([0-9.]+) +([+-][0-9.]+))");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, line)) << name << "\n" << r.out;
    const double change = (file.read_step_array(last, std::string("wheel/") + name).at(0) -
                           file.read_step_array(0, std::string("wheel/") + name).at(0)) *
                          1e3;
    EXPECT_NEAR(std::stod(m[3].str()), change, 0.6e-4) << name;  // printed to 1e-4 mm
    ++compared;
  }
  EXPECT_EQ(compared, 3);
}

}  // namespace
}  // namespace wheelwear::pipeline
