// In-service limits in a run: recorded every step, and with [limits] stop the run ends at the
// first step whose profile reaches one, its earlier steps unchanged.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/input_errors.hpp"
#include "support/run_command.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/wear_run.hpp"

namespace wheelwear::pipeline {
namespace {

using testing::contains;
using testing::error_of;

// A TOML number that reads back as `value` exactly.
std::string exact(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

double at(const ResultsFile& file, int step, const std::string& name) {
  return file.read_step_array(step, name).at(0);
}

TEST_F(WearRunTest, StopsAtTheFirstStepThatReachesALimit) {
  const std::string base = small_scene(1e6, 250e3, 1e-3);
  const fs::path free_run = dir_ / "free.h5";
  run(base, free_run);
  const ResultsFile reference = ResultsFile::read(free_run);
  const int last = reference.completed_steps() - 1;
  ASSERT_GE(last, 3);
  // Without a [limits] table the limits are EN 15313's for the S1002's 0.92 m wheel.
  EXPECT_EQ(at(reference, 0, "limits/Sd_min"), 22e-3);
  EXPECT_EQ(at(reference, 0, "limits/Sh_max"), 36e-3);
  EXPECT_EQ(at(reference, 0, "limits/qR_min"), 6.5e-3);
  // Tread wear raises the flange height step by step; a bound between steps 2 and 3 is reached
  // at step 3.
  const double sh2 = at(reference, 2, "wheel/Sh"), sh3 = at(reference, 3, "wheel/Sh");
  ASSERT_GT(sh3, sh2);
  const double bound = 0.5 * (sh2 + sh3);
  const std::string limits = "[limits]\nSh_max_m = " + exact(bound) + "\n";
  const std::string watched = base + limits, stopping = base + limits + "stop = true\n";

  const fs::path watched_run = dir_ / "watched.h5", stopped_run = dir_ / "stopped.h5";
  run(watched, watched_run);
  run(stopping, stopped_run);
  const ResultsFile w = ResultsFile::read(watched_run), s = ResultsFile::read(stopped_run);
  // Watching changes nothing of the wear: the run goes the whole distance.
  ASSERT_EQ(w.completed_steps(), reference.completed_steps());
  for (int step = 0; step <= last; ++step) {
    EXPECT_EQ(at(w, step, "wheel/Sh"), at(reference, step, "wheel/Sh")) << step;
    EXPECT_EQ(at(w, step, "wheel/limits_reached"), step >= 3 ? 1.0 : 0.0) << step;
    EXPECT_EQ(at(w, step, "limits/stopped"), 0.0) << step;
  }
  // Stopping ends the run at step 3 with no further distance, its steps those of the free run.
  ASSERT_EQ(s.completed_steps(), 4);
  for (int step = 0; step <= 3; ++step) {
    EXPECT_EQ(at(s, step, "wheel/Sh"), at(reference, step, "wheel/Sh")) << step;
    EXPECT_EQ(at(s, step, "distance"), at(reference, step, "distance")) << step;
    EXPECT_EQ(at(s, step, "limits/stopped"), step == 3 ? 1.0 : 0.0) << step;
  }
  EXPECT_EQ(at(s, 3, "step_distance"), 0.0);
  // The command reports the same step and what was reached.
  const fs::path scene = write("stopping.toml", stopping);
  const testing::CommandResult cli = testing::run_wheelwear(
      "run " + scene.string() + " -q --json -o " + (dir_ / "cli.h5").string());
  ASSERT_EQ(cli.exit_code, 0) << cli.err;
  EXPECT_EQ(testing::json_number(cli.out, "limit_step"), 3.0);
  EXPECT_TRUE(contains(cli.out, "\"limit_reached\": \"wheel Sh ")) << cli.out;
  EXPECT_TRUE(contains(cli.out, "\"stopped_at_limit\": true")) << cli.out;
  EXPECT_EQ(at(s, 3, "limits/Sh_max"), bound);
}

TEST(SceneLimits, RefuseValuesOutOfRangeNamingTheKey) {
  const std::string state =
      "[[load_collective.state]]\ndy_m = 0.001\naxle_load_N = 110e3\nspeed_m_s = 40\n";
  const std::string message =
      error_of([&] { parse_scene("[limits]\nSd_min_m = -0.022\n" + state, "."); });
  EXPECT_TRUE(contains(message, "Sd_min_m")) << message;
  EXPECT_TRUE(contains(message, "line 2")) << message;
  const std::string unknown =
      error_of([&] { parse_scene("[limits]\nSd_min = 0.022\n" + state, "."); });
  EXPECT_TRUE(contains(unknown, "Sd_min")) << unknown;
  const Scene scene = parse_scene("[limits]\nqR_min_m = 7e-3\nstop = true\n" + state, ".");
  EXPECT_TRUE(scene.limits.stop);
  const profiles::WheelLimits resolved = scene.limits.resolve(0.80);
  EXPECT_EQ(resolved.qR_min, 7e-3);
  EXPECT_EQ(resolved.Sd_min, 25e-3);  // unset: EN 15313's for a 0.80 m wheel
  // A wheel smaller than the standard covers watches only what the scene sets.
  const profiles::WheelLimits small = scene.limits.resolve(0.30);
  EXPECT_EQ(small.qR_min, 7e-3);
  EXPECT_TRUE(std::isnan(small.Sd_min));
  EXPECT_TRUE(std::isnan(small.Sh_max));
}

}  // namespace
}  // namespace wheelwear::pipeline
