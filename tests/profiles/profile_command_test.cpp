// Tests of `wheelwear profile` through the built executable.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

#include "support/run_command.hpp"
#include "test_support.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/columns_format.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/track.hpp"

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
  for (const char* option :
       {"--wheel", "--rail", "--out", "--info", "--json", "--spacing", "--smoothing", "--unit",
        "--inclination", "--flange-height", "--crop-depth", "--gauge-side"})
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

TEST(ProfileCommand, WheelOriginIsChosenAndReported) {
  const std::string file = quoted(testing::data_path("profiles/s1002_flange_back.whl"));
  const CliRun automatic = run("--wheel " + file + " --origin auto --json");
  ASSERT_EQ(automatic.status, 0) << automatic.err;
  EXPECT_NE(automatic.out.find("\"origin\": \"internal-face\""), std::string::npos)
      << automatic.out;
  EXPECT_NEAR(*json_number(automatic.out, "origin_shift"), -0.070, 1e-15);
  EXPECT_NEAR(*json_number(automatic.out, "y_min"), -0.070, 2e-6);
  const CliRun info =
      run("--wheel " + file + " --origin internal-face --taping-line-distance 0.072 --info");
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_NE(info.out.find("origin     internal-face: as set"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("moved by -72.000 mm"), std::string::npos) << info.out;
  const CliRun rail = run("--rail 60E1 --origin auto");
  EXPECT_EQ(rail.status, 2);
  EXPECT_NE(rail.err.find("--origin applies to wheel files only"), std::string::npos) << rail.err;
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
  // With --overwrite, so that the bad profile is what is refused.
  const CliRun bad = run("--rail " + quoted(dir / "bad.csv") + " --overwrite --out " + quoted(out));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("bad.csv:3: z = nan: not a finite number"), std::string::npos) << bad.err;
  EXPECT_EQ(testing::read_text(out), "previous result\n");
  for (const std::string& args :
       {std::string("--wheel S1002 --rail 60E1"), std::string(""),
        "--wheel " + quoted(dir / "absent.prw"),
        "--rail " + quoted(testing::measured_rail_file()) + " --flange-height 0.03",
        std::string("--rail 60E1 --inclination 40"), std::string("--wheel S1002 --spacing 0"),
        std::string("--wheel S1002 --flange-thickness 0.034")}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_NE(r.err.find("wheelwear: error: "), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_EQ(testing::read_text(out), "previous result\n");
}

// The small files of tests/data/profiles (tests/data/README.md, real_rail_files_test.cpp).
std::filesystem::path profile_file(const std::string& name) {
  return testing::data_path("profiles/" + name);
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(ProfileCommand, ReportsTheReadingTheCropAndTheirWarnings) {
  const auto undercut = profile_file("rail_deep_undercut.ban");
  const CliRun info = run("--rail " + quoted(undercut) + " --info");
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_TRUE(has(info.out,
                  "points     kept 38 of 38 points; cropped 13 below 25 mm; 51 read, 0 merged, 0 "
                  "dropped\n"
                  "crop       cropped 13 points deeper than 25 mm below the top of rail (gauge "
                  "side 13, lines 44 ... 56; down to 35.4 mm)\n"
                  "crop       needed: whole, the profile was refused: " +
                      undercut.string() +
                      ":52: X = 46.7400, Y = -32.4000 after X = 47.3400, Y = -30.0000 at line 49"))
      << info.out;
  const CliRun json = run("--rail " + quoted(undercut) + " --json");
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_EQ(*json_number(json.out, "points_read"), 51.0);
  EXPECT_EQ(*json_number(json.out, "points_cropped"), 13.0);
  EXPECT_EQ(*json_number(json.out, "points_kept"), 38.0);
  EXPECT_EQ(*json_number(json.out, "crop_depth"), 0.025);
  // Not cropped, it is refused with the real cause.
  const CliRun whole = run("--rail " + quoted(undercut) + " --crop-depth 0");
  EXPECT_EQ(whole.status, 2);
  EXPECT_EQ(whole.err.rfind("wheelwear: error: " + undercut.string() +
                                ":52: X = 46.7400, Y = -32.4000 after X = 47.3400, Y = -30.0000 at "
                                "line 49: the points go back 0.6 mm across the profile",
                            0),
            0u)
      << whole.err;

  const auto comments = profile_file("rail_trailing_comments.ban");
  const CliRun read = run("--rail " + quoted(comments) + " --info");
  ASSERT_EQ(read.status, 0) << read.err;
  EXPECT_TRUE(has(read.out, "\nread       " + comments.string() +
                                ":15: 4 point rows carry text after their numbers, read as a "
                                "comment (after \", %, ! or #)\n"))
      << read.out;

  const auto count = profile_file("rail_count_off_by_one.ban");
  const std::string warning = count.string() +
                              ":3: the header declares XYPoints=39 but 38 points were read; "
                              "accepted (off by one), check that no point is missing";
  const auto out = testing::scratch_dir() / "rail.csv";
  const CliRun written = run("--rail " + quoted(count) + " --out " + quoted(out));
  ASSERT_EQ(written.status, 0) << written.err;
  EXPECT_EQ(written.err, "wheelwear: warning: " + warning + "\n");
  const CliRun counted = run("--rail " + quoted(count) + " --json");
  ASSERT_EQ(counted.status, 0) << counted.err;
  EXPECT_TRUE(has(counted.out, "\"warnings\": [\"" + warning + "\"]")) << counted.out;
  const CliRun summary = run("--rail " + quoted(count) + " --info");
  EXPECT_TRUE(has(summary.out, "\nwarning    " + warning + "\n")) << summary.out;
}

TEST(ProfileCommand, TheGaugeSideSetsAMirroredSwitchRailRight) {
  // 60E1 at 1:40 measured deeper on its field side (real_rail_files_test.cpp): automatically
  // mirrored, and the estimated inclination says so.
  const auto path = profile_file("switch_rail_field_side_deeper.ban");
  const double incl = std::atan(1.0 / 40.0);
  const CliRun automatic = run("--rail " + quoted(path) + " --json");
  ASSERT_EQ(automatic.status, 0) << automatic.err;
  EXPECT_NEAR(*json_number(automatic.out, "inclination"), -incl, 1e-3);
  EXPECT_TRUE(has(automatic.out, "(--gauge-side right, ")) << automatic.out;
  const CliRun right = run("--rail " + quoted(path) + " --gauge-side right --json");
  ASSERT_EQ(right.status, 0) << right.err;
  EXPECT_NEAR(*json_number(right.out, "inclination"), incl, 1e-3);
  EXPECT_TRUE(has(right.out, "\"warnings\": []")) << right.out;
  // Its gauge point is the generated rail's (the file keeps the origin at the top).
  const ProfilePoint gauge = gauge_point(rail_60e1({.inclination = incl}));
  EXPECT_NEAR(*json_number(right.out, "gauge_point_y"), gauge.point[0], 0.01e-3);
  EXPECT_NEAR(*json_number(right.out, "gauge_point_z"), gauge.point[1], 0.01e-3);
  // Set to the side the file says, left keeps it as it is, without a warning.
  const CliRun left = run("--rail " + quoted(path) + " --gauge-side left --json");
  ASSERT_EQ(left.status, 0) << left.err;
  EXPECT_NEAR(*json_number(left.out, "inclination"), -incl, 1e-3);
  EXPECT_TRUE(has(left.out, "\"warnings\": []")) << left.out;
}

TEST(ProfileCommand, WarnsOfARailWithoutAGaugePointAndOfALevelRail) {
  const auto shallow = profile_file("rail_shallow_gauge_side.ban");
  const CliRun r = run("--rail " + quoted(shallow) + " --info");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(has(r.out, "\ngauge pt   none: the gauge side does not reach 14 mm below the top\n"))
      << r.out;
  EXPECT_TRUE(has(r.out, "\nwarning    " + shallow.string() +
                             ":78: no gauge point: the gauge side (the profile's -y end, the "
                             "file's larger lateral values) reaches 9.6 mm below the top of rail"))
      << r.out;
  // 60E1 written upright looks level; written at 1:40 it does not.
  const auto dir = testing::scratch_dir();
  write_csv(dir / "upright.csv", rail_60e1_points({.inclination = 0.0}), {.body = Body::rail});
  write_csv(dir / "canted.csv", rail_60e1_points(), {.body = Body::rail});
  const CliRun level = run("--rail " + quoted(dir / "upright.csv") + " --info");
  ASSERT_EQ(level.status, 0) << level.err;
  EXPECT_TRUE(has(level.out, "\nincl.      level (0.0000 rad), estimated from the crown\n"))
      << level.out;
  EXPECT_TRUE(has(level.out, "\nwarning    " + (dir / "upright.csv").string() +
                                 ": the rail looks level (estimated inclination below 1:10000, "
                                 "less than 1:200). Measured rails usually carry their "
                                 "inclination, but `contact --incl` defaults to 0 for files"))
      << level.out;
  const CliRun canted = run("--rail " + quoted(dir / "canted.csv") + " --json");
  ASSERT_EQ(canted.status, 0) << canted.err;
  EXPECT_NEAR(*json_number(canted.out, "inclination"), std::atan(1.0 / 40.0), 1e-3);
  EXPECT_TRUE(has(canted.out, "\"warnings\": []")) << canted.out;
  // The built-in 60E1 is generated, not measured: no warning.
  const CliRun builtin = run("--rail 60E1 --inclination none --info");
  EXPECT_FALSE(has(builtin.out, "warning")) << builtin.out;
}

TEST(ProfileCommand, RefusesMptFilesAndARailGivenAsAWheelByName) {
  const auto mpt = profile_file("miniprof_multi_profile.mpt");
  const CliRun r = run("--rail " + quoted(mpt));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "wheelwear: error: " + mpt.string() +
                       ": MiniProf .mpt files are not supported; export .whl/.ban from MiniProf\n");
  const auto prr = profile_file("simpack_rail_type0.prr");
  const CliRun wheel = run("--wheel " + quoted(prr));
  EXPECT_EQ(wheel.status, 2);
  EXPECT_EQ(wheel.err, "wheelwear: error: " + prr.string() +
                           ":4: the file says it is a rail profile (type = 0), but a wheel "
                           "profile is expected here; give a wheel profile file\n");
  const std::pair<std::string, std::string> refused[] = {
      {"--wheel S1002 --gauge-side left", "--gauge-side applies to rail files only"},
      {"--rail 60E1 --crop-depth 0.03", "--crop-depth applies to rail files only"},
      {"--rail " + quoted(prr) + " --crop-depth 0.01", "rail crop depth [m] = 0.01"},
  };
  for (const auto& [args, message] : refused) {
    const CliRun bad = run(args);
    EXPECT_EQ(bad.status, 2) << args;
    EXPECT_TRUE(has(bad.err, "wheelwear: error: " + message)) << args << "\n" << bad.err;
  }
  // A value outside the option's choices is refused by the parser, with the same status.
  const CliRun parse = run("--rail " + quoted(prr) + " --gauge-side up");
  EXPECT_EQ(parse.status, 2);
  EXPECT_TRUE(has(parse.err, "wheelwear: error: --gauge-side")) << parse.err;
}

}  // namespace
}  // namespace wheelwear::profiles
