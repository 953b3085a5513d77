// Golden results of a small scene compared whole, and the main job's built-in default scene
// run for a wear step.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "support/csv_table.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/tangential/creep_table.hpp"

namespace wheelwear::pipeline {
namespace {

// Golden tolerances. The same build on the same CPU reproduces the file bit for bit (threads
// and resume tests above); these cover another compiler or CPU, whose floating-point
// contraction moves the last digits of iterative solves.
// Profile coordinates [m]: 1e-12 m, a thousandth of a nanometre, far below any wear depth.
constexpr double kGoldenLengthTolerance = 1e-12;
// Everything else, relative to the largest magnitude in the same array (so entries near zero
// are judged on the array's scale): 1e-8. Measured between builds of the same commit: native
// and portable at most 2.6e-10 (states/roll), -O1 and -O3 2.0e-9 (states/psi, the SDEC's
// orientation); profile coordinates 3.6e-13 m.
constexpr double kGoldenRelativeTolerance = 1e-8;
// The unsmoothed wear rate per 0.1 mm bin, relative to its peak: 1e-8. A bin at a patch's edge
// takes cells whose centres move across the bin border with the last digits of the patch's
// width; measured 2.7e-9 between a native and a portable build.
constexpr double kGoldenWearRateTolerance = 1e-8;

bool is_profile_length(const std::string& name) {
  for (const char* suffix : {"/y", "/z", "/wear_rate/s"})
    if (name.size() >= std::string_view(suffix).size() &&
        name.compare(name.size() - std::string_view(suffix).size(), std::string::npos, suffix) ==
            0 &&
        name.rfind("wheel", 0) == 0)
      return true;
  return false;
}

// Golden results of the small scene: tests/data/pipeline/golden_small_run.h5 is the results
// file of this scene, written by this test with WHEELWEAR_UPDATE_GOLDEN=1 (see
// docs/developing.md) and checked then by the physical tests above (worn area against the
// accumulated wear, conicity against the cone). Every array of every step is compared whole:
// the same datasets, shapes and NaN pattern, values within the tolerances above.
TEST_F(WearRunTest, SmallSceneMatchesGoldenResults) {
  const fs::path out = dir_ / "golden.h5";
  run(small_scene(30e3, 10e3, 1e-3), out);
  const std::string golden_path = testing::test_data("pipeline/golden_small_run.h5");
  if (std::getenv("WHEELWEAR_UPDATE_GOLDEN")) {
    fs::copy_file(out, golden_path, fs::copy_options::overwrite_existing);
    GTEST_SKIP() << "golden results rewritten: " << golden_path;
  }
  const ResultsFile file = ResultsFile::read(out);
  const ResultsFile golden = ResultsFile::read(golden_path);
  ASSERT_EQ(file.completed_steps(), golden.completed_steps());
  EXPECT_EQ(file.format_version(), golden.format_version());
  std::size_t arrays = 0, values = 0;
  // The collective as the run resolved it: the same states, to the last bit (it is read, not
  // computed).
  const std::vector<std::string> collective = golden.array_names("/load_collective");
  ASSERT_EQ(file.array_names("/load_collective"), collective);
  for (const std::string& name : collective) {
    const auto expected = golden.read_array("/load_collective/" + name);
    const auto actual = file.read_array("/load_collective/" + name);
    ASSERT_EQ(actual.size(), expected.size()) << name;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      if (!(std::isnan(expected[i]) && std::isnan(actual[i]))) {
        EXPECT_EQ(actual[i], expected[i]) << name << '[' << i << ']';
      }
    }
    ++arrays;
  }
  EXPECT_EQ(file.scene_text(), golden.scene_text());
  for (int step = 0; step < golden.completed_steps(); ++step) {
    const std::vector<std::string> names = golden.step_array_names(step);
    ASSERT_EQ(file.step_array_names(step), names) << "step " << step;
    for (const std::string& name : names) {
      const auto expected = golden.read_step_array(step, name);
      const auto actual = file.read_step_array(step, name);
      ASSERT_EQ(actual.size(), expected.size()) << "step " << step << ' ' << name;
      double scale = 0.0;
      for (double v : expected)
        if (std::isfinite(v)) scale = std::max(scale, std::abs(v));
      const bool wear_rate = name.find("/wear_rate/depth") != std::string::npos;
      const double tolerance = is_profile_length(name) ? kGoldenLengthTolerance
                               : wear_rate             ? kGoldenWearRateTolerance * scale
                                                       : kGoldenRelativeTolerance * scale;
      for (std::size_t i = 0; i < expected.size(); ++i) {
        if (std::isnan(expected[i])) {
          EXPECT_TRUE(std::isnan(actual[i])) << "step " << step << ' ' << name << '[' << i << ']';
          continue;
        }
        EXPECT_NEAR(actual[i], expected[i], tolerance)
            << "step " << step << ' ' << name << '[' << i << ']';
        ++values;
      }
      ++arrays;
    }
  }
  // Three steps of about 60 arrays: a comparison of fewer means the file lost its content.
  EXPECT_GT(arrays, 100u);
  EXPECT_GT(values, 10000u);
  RecordProperty("golden_arrays", static_cast<int>(arrays));
  RecordProperty("golden_values", static_cast<int>(values));
}

// The main job: the built-in default scene, the vehicle on its route, runs a wear step end to
// end (as scripts/run-default.sh runs it, shortened to one step), and its worn cross-section equals
// the applied depth integrated along the profile (as
// WornAreaEqualsAccumulatedWearAndGrowsMonotonically checks on the small scene).
TEST_F(WearRunTest, DefaultSceneRunsAWearStep) {
  Scene scene = default_scene();
  // One step of 1000 km (the vehicle solved once on the new profiles; step control may split
  // it): at least two profiles, before and after.
  scene.distance = scene.step_distance = 1e6;
  const fs::path out = dir_ / "default.h5";
  const RunSummary summary = run_scene(scene, default_scene_text(), {}, true, out, {});
  EXPECT_GE(summary.steps, 1);
  const ResultsFile file = ResultsFile::read(out);
  ASSERT_GE(file.completed_steps(), 2);
  EXPECT_EQ(file.format_version(), kFormatVersion);
  // Which book of tables the run had (creep_table_data_test checks the hash against the file).
  EXPECT_EQ(file.root_attribute("creep_table_sha256"), tangential::creep_table_sha256());
  // On the new profiles no state of the vehicle falls in a load jump (the contact regions'
  // loads are continuous where they join), climbs or runs past the flange, or exceeds Nadal's
  // limit, and hardly any distance is dropped.
  EXPECT_LT(file.read_step_array(0, "dropped_patches_weight").at(0), 0.01);
  EXPECT_EQ(file.read_step_array(0, "load_jump_contacts").at(0), 0.0);
  EXPECT_EQ(file.read_step_array(0, "nadal_contacts").at(0), 0.0);
  EXPECT_EQ(file.read_step_array(0, "climbing_contacts").at(0), 0.0);
  const auto y = file.read_step_array(0, "wheel/wear_step/y");
  const auto depth = file.read_step_array(0, "wheel/wear_step/depth");
  const profiles::Profile before(
      points(file.read_step_array(0, "wheel/y"), file.read_step_array(0, "wheel/z")),
      {"step", profiles::Body::wheel});
  double applied = 0.0;
  for (std::size_t i = 0; i + 1 < y.size(); ++i)
    applied += 0.5 * (depth[i] + depth[i + 1]) * arc_between(before, y[i], y[i + 1]);
  ASSERT_GT(applied, 0.0);
  const double area =
      area_between(file.read_step_array(0, "wheel/y"), file.read_step_array(0, "wheel/z"),
                   file.read_step_array(1, "wheel/y"), file.read_step_array(1, "wheel/z"));
  // As in the small scene's test: curvature of the normal offset, the flange back and the
  // re-interpolated ends stay within 1 %.
  EXPECT_NEAR(area, applied, 0.01 * applied);
}

}  // namespace
}  // namespace wheelwear::pipeline
