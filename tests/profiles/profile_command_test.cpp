// Tests of `wheelwear profile` through the built executable.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "support/run_command.hpp"
#include "test_support.hpp"
#include "wheelwear/profiles/columns_format.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::profiles {
namespace {

// Single-quoted for the shell (built piece by piece: GCC 12 warns falsely on "'" + std::string).
std::string quoted(const std::filesystem::path& path) {
  std::string out(1, '\'');
  out += path.string();
  out += '\'';
  return out;
}

struct CliRun {
  int status = -1;
  std::string out, err;
};

// Through the shared runner, whose capture files are per process: ctest runs these tests in
// parallel.
CliRun run(const std::string& arguments) {
  const auto r = wheelwear::testing::run_wheelwear("profile " + arguments);
  return {r.exit_code, r.out, r.err};
}

using wheelwear::testing::json_number;

TEST(ProfileCommand, HelpNamesTheOptions) {
  const CliRun r = run("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* option : {"--wheel", "--rail", "--out", "--info", "--json", "--spacing",
                             "--smoothing", "--unit", "--inclination", "--flange-height"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

TEST(ProfileCommand, S1002JsonHasShSdQrInMetres) {
  const CliRun r = run("--wheel S1002 --info --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(*json_number(r.out, "Sh"), 0.028, 1e-6);
  EXPECT_NEAR(*json_number(r.out, "Sd"), 0.0325, 1e-6);
  EXPECT_NEAR(*json_number(r.out, "qR"), 0.0108, 0.05e-3);
  EXPECT_NEAR(*json_number(r.out, "y_min"), -0.070, 1e-6);
  EXPECT_NEAR(*json_number(r.out, "y_max"), 0.060, 1e-9);
  EXPECT_EQ(*json_number(r.out, "points_dropped"), 0.0);
  // Variants: the parameters come back as asked for.
  const CliRun v = run("--wheel s1002 --flange-height 0.030 --flange-thickness 0.030 --json");
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_NEAR(*json_number(v.out, "Sh"), 0.030, 1e-6);
  EXPECT_NEAR(*json_number(v.out, "Sd"), 0.030, 1e-6);
}

TEST(ProfileCommand, WritesAResampledCsvInMillimetres) {
  const auto dir = testing::scratch_dir();
  const auto out = dir / "rail.csv";
  const CliRun r = run("--rail 60E1 --inclination 1:20 --spacing 0.0005 --out " + quoted(out));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = testing::read_text(out);
  EXPECT_NE(text.find("y_mm,z_mm"), std::string::npos);
  EXPECT_NE(text.find("# body: rail"), std::string::npos);
  const RawProfile back = parse_columns(text, out.string());
  EXPECT_EQ(back.body, Body::rail);
  ASSERT_GT(back.points.size(), 250u);  // 132 mm of head at <= 0.5 mm
  for (std::size_t i = 1; i < back.points.size(); ++i)
    ASSERT_LE((back.points[i] - back.points[i - 1]).norm(), 0.5e-3 + 1e-9);
  EXPECT_NEAR(back.points.front()[1], 0.0375 + 0.0372 * std::sin(std::atan(0.05)), 0.5e-3);
}

TEST(ProfileCommand, SummarisesMeasuredFiles) {
  const CliRun wheel = run("--wheel " + quoted(testing::measured_wheel_file()) + " --json");
  ASSERT_EQ(wheel.status, 0) << wheel.err;
  EXPECT_EQ(*json_number(wheel.out, "points_read"), 645.0);
  EXPECT_EQ(*json_number(wheel.out, "points_dropped"), 2.0);
  EXPECT_TRUE(json_number(wheel.out, "Sh"));
  const CliRun rail = run("--rail " + quoted(testing::measured_rail_file()) + " --info");
  ASSERT_EQ(rail.status, 0) << rail.err;
  EXPECT_NE(rail.out.find("gauge pt"), std::string::npos) << rail.out;
  EXPECT_EQ(rail.out.find("Sh"), std::string::npos);
}

TEST(ProfileCommand, SameFileInMillimetresAndMetresGivesTheSameJson) {
  const auto dir = testing::scratch_dir();
  const PointList points = s1002_points({.point_spacing = 0.2e-3});
  write_csv(dir / "mm.csv", points, {.unit = LengthUnit::millimetre});
  write_csv(dir / "m.csv", points, {.unit = LengthUnit::metre});
  const CliRun mm = run("--wheel " + quoted(dir / "mm.csv") + " --json");
  const CliRun m = run("--wheel " + quoted(dir / "m.csv") + " --json");
  ASSERT_EQ(mm.status, 0) << mm.err;
  ASSERT_EQ(m.status, 0) << m.err;
  for (const char* key : {"Sh", "Sd", "qR", "y_min", "y_max", "length"})
    EXPECT_NEAR(*json_number(mm.out, key), *json_number(m.out, key), 1e-13) << key;
}

TEST(ProfileCommand, BadInputFailsClearlyAndLeavesTheOutputAlone) {
  const auto dir = testing::scratch_dir();
  const auto out = dir / "kept.csv";
  testing::write_text(out, "previous result\n");
  testing::write_text(dir / "bad.csv", "y,z\n1,2\n3,nan\n4,5\n");
  const CliRun bad = run("--rail " + quoted(dir / "bad.csv") + " --out " + quoted(out));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("bad.csv:3: z = nan: not a finite number"), std::string::npos) << bad.err;
  EXPECT_EQ(testing::read_text(out), "previous result\n");
  for (const std::string& args :
       {std::string("--wheel S1002 --rail 60E1"), std::string(""),
        "--wheel " + quoted(dir / "absent.prw"),
        "--rail " + quoted(testing::measured_rail_file()) + " --flange-height 0.03",
        std::string("--rail 60E1 --inclination 1:30"), std::string("--wheel S1002 --spacing 0"),
        std::string("--wheel S1002 --flange-thickness 0.034")}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_NE(r.err.find("wheelwear: error: "), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_EQ(testing::read_text(out), "previous result\n");
}

}  // namespace
}  // namespace wheelwear::profiles
