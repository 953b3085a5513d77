// Real rail files and the formats around them: each small file in tests/data/profiles carries one
// cause a real file showed (tests/data/README.md), and its test asserts the cleaned result against
// a file without that cause (rail_base.ban, the same rows) or the standard profile it was made
// from, and the exact report or message.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <string>

#include "real_rail_support.hpp"
#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/columns_format.hpp"
#include "wheelwear/profiles/miniprof_format.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/simpack_format.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::profiles {
namespace {

using namespace real_rail;

// rail_base.ban holds 38 rows of the measured avg_HR.BAN (every fourth of lines 53 ... 197, and
// 199), in MiniProf rail axes: X towards the gauge face, Y up, mm.
TEST(RealRailFiles, TheBaseRailReadsItsRowsInSiUnits) {
  const RawProfile raw = read_profile_file(rail_file("rail_base.ban"));
  ASSERT_EQ(raw.points.size(), 38u);
  EXPECT_EQ(raw.lines.front(), 6);
  EXPECT_EQ(raw.lines.back(), 43);
  EXPECT_EQ(raw.points.front(), Point(-11.73 * 1e-3, -1.52 * 1e-3));  // "-11.7300 -1.5200"
  EXPECT_EQ(raw.points.back(), Point(46.59 * 1e-3, -25.42 * 1e-3));   // "46.5900 -25.4200"
  EXPECT_TRUE(raw.repairs.empty());
  const LoadedProfile rail = load_profile(rail_file("rail_base.ban"));
  EXPECT_EQ(rail.cleaning.kept_points, 38u);  // rows 2 mm apart: nothing to merge or drop
  EXPECT_EQ(rail.cleaning.crop.cropped(), 0u);
  EXPECT_TRUE(rail.cleaning.warnings.empty());
}

TEST(RealRailFiles, TrailingCommentsOnRowsAreReadAsComments) {
  const auto path = rail_file("rail_trailing_comments.ban");
  const LoadedProfile rail = load_profile(path);
  const LoadedProfile base = load_profile(rail_file("rail_base.ban"));
  EXPECT_GT(expect_same_profile(rail, base, 0), 38u);
  ASSERT_EQ(rail.cleaning.reading.size(), 1u);
  const ReadRepair& repair = rail.cleaning.reading.front();
  EXPECT_EQ(repair.name, "trailing_comments");
  EXPECT_EQ(repair.count, 4u);
  EXPECT_EQ(repair.lines, (std::vector<int>{15, 21, 29, 37}));  // '"', '%', '!', '#'
  EXPECT_FALSE(repair.warning);
  EXPECT_EQ(repair.message, path.string() +
                                ":15: 4 point rows carry text after their numbers, read as a "
                                "comment (after \", %, ! or #)");
  EXPECT_TRUE(rail.cleaning.warnings.empty());
  EXPECT_NE(rail.cleaning.summary().find("; read: trailing_comments 4"), std::string::npos)
      << rail.cleaning.summary();
}

// Words after a full row without a comment character (one of CONTACT's measured rails ends with
// "add point to extend gauge face"): the numbers are read as CONTACT reads them, with a warning.
TEST(RealRailFiles, WordsAfterARowWithoutACommentCharacterAreReadWithAWarning) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "wheelwear_rail_words.ban";
  {
    std::ifstream in(rail_file("rail_base.ban"));
    std::ofstream out(path);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number)
      out << line << (number == 42 ? "      add point to extend gauge face" : "") << '\n';
  }
  const LoadedProfile rail = load_profile(path);
  EXPECT_GT(expect_same_profile(rail, load_profile(rail_file("rail_base.ban")), 0), 38u);
  ASSERT_EQ(rail.cleaning.reading.size(), 1u);
  const ReadRepair& repair = rail.cleaning.reading.front();
  EXPECT_EQ(repair.name, "trailing_text");
  EXPECT_EQ(repair.lines, (std::vector<int>{42}));
  EXPECT_TRUE(repair.warning);
  ASSERT_EQ(rail.cleaning.warnings.size(), 1u);
  EXPECT_NE(rail.cleaning.warnings[0].find(":42: 1 point rows carry words after their numbers"),
            std::string::npos)
      << rail.cleaning.warnings[0];
  // Words that do not follow a full row are still refused.
  {
    std::ofstream out(path);
    out << "XYPoints=2\nColumnDef=X,Y\n\n1.0 2.0\n3.0 add\n";
  }
  LoadOptions rail_file_options;
  rail_file_options.read.body = Body::rail;
  EXPECT_NE(
      error_of([&] { load_profile(path, rail_file_options); }).find("is not a row of numbers"),
      std::string::npos);
  std::filesystem::remove(path);
}

TEST(RealRailFiles, APointCountOffByOneIsAcceptedWithAWarning) {
  const auto path = rail_file("rail_count_off_by_one.ban");  // XYPoints=39, 38 rows
  const LoadedProfile rail = load_profile(path);
  EXPECT_GT(expect_same_profile(rail, load_profile(rail_file("rail_base.ban")), 0), 38u);
  const std::string expected = path.string() +
                               ":3: the header declares XYPoints=39 but 38 points were read; "
                               "accepted (off by one), check that no point is missing";
  ASSERT_EQ(rail.cleaning.reading.size(), 1u);
  EXPECT_EQ(rail.cleaning.reading.front().name, "point_count");
  EXPECT_TRUE(rail.cleaning.reading.front().warning);
  EXPECT_EQ(rail.cleaning.reading.front().message, expected);
  EXPECT_EQ(rail.cleaning.warnings, std::vector<std::string>{expected});
}

TEST(RealRailFiles, ALargerCountMismatchIsAnErrorNamingBothCounts) {
  const auto path = rail_file("rail_count_off_by_three.ban");  // XYPoints=41, 38 rows
  EXPECT_EQ(error_of([&] { load_profile(path); }),
            path.string() +
                ": the header declares XYPoints=41 but 38 points were read (truncated or damaged "
                "file?)");
}

TEST(RealRailFiles, PointsRightAfterTheHeaderAreRead) {
  const auto path = rail_file("rail_no_blank_line.ban");
  const LoadedProfile rail = load_profile(path);
  // The same rows, one line earlier.
  EXPECT_GT(expect_same_profile(rail, load_profile(rail_file("rail_base.ban")), -1), 38u);
  ASSERT_EQ(rail.cleaning.reading.size(), 1u);
  EXPECT_EQ(rail.cleaning.reading.front().name, "no_blank_line");
  EXPECT_EQ(rail.cleaning.reading.front().message,
            path.string() +
                ":5: the points follow the header without an empty line; this line is taken as "
                "the first point");
  // Text that is no row of numbers still is an error before the points.
  EXPECT_EQ(error_of([] {
              parse_miniprof("XYPoints=2\nstray header text\n1 2\n3 4\n", "x.ban", ".ban");
            }),
            "x.ban:2: \"stray header text\" is neither a key=value header line nor a point row");
}

// rail_deep_undercut.ban: rail_base.ban with its gauge face continued from 25.4 to 35.6 mm below
// the file's Y = 0 (13 rows, lines 44 ... 56), receding by 0.6 mm from X = 47.34 at Y = -30 (line
// 49) to X = 46.74 at Y = -32.4 (line 52).
TEST(RealRailFiles, ADeepUndercutIsCroppedAwayAndReported) {
  const auto path = rail_file("rail_deep_undercut.ban");
  const LoadedProfile rail = load_profile(path);
  EXPECT_EQ(rail.points_read, 51u);
  // Everything deeper than 25 mm below the top (Y = -0.21) goes but line 43 (Y = -25.42, 25.21
  // mm deep), which keeps the profile reaching 25 mm: what is left is rail_base.ban.
  EXPECT_GT(expect_same_profile(rail, load_profile(rail_file("rail_base.ban")), 0), 38u);
  const CropReport& crop = rail.cleaning.crop;
  EXPECT_EQ(crop.depth, 0.025);
  EXPECT_EQ(crop.gauge_side, 13u);
  EXPECT_EQ(crop.field_side, 0u);
  EXPECT_EQ(crop.gauge_lines, std::make_pair(44, 56));
  EXPECT_NEAR(crop.top, 0.21e-3, 1e-15);
  EXPECT_NEAR(crop.deepest, (35.6 - 0.21) * 1e-3, 1e-15);
  EXPECT_EQ(crop.summary(),
            "cropped 13 points deeper than 25 mm below the top of rail (gauge side 13, lines "
            "44 ... 56; down to 35.4 mm)");
  // Why: whole, the profile fails the order check, which names the lines in file order with the
  // values as the file writes them (the reader mirrored and reversed the points).
  const std::string whole =
      path.string() +
      ":52: X = 46.7400, Y = -32.4000 after X = 47.3400, Y = -30.0000 at line 49: the points go "
      "back 0.6 mm across the profile (values as written in the file, mm); a rail profile must "
      "run monotonically in y (points out of order?). Both points lie 29.79 mm or more below the "
      "top of rail, deeper than the gauge point: a gauge face that recedes there (an undercut) "
      "is cut off by cropping the rail at a smaller depth (LoadOptions::crop_depth, profile "
      "--crop-depth)";
  EXPECT_EQ(crop.reason, whole);
  LoadOptions never;
  never.crop_depth = 0.0;
  EXPECT_EQ(error_of([&] { load_profile(path, never); }), whole);
  // Cropped at 33 mm (33.21 mm below Y = 0), the undercut stays (lines 55, 56: Y = -34.8,
  // -35.6 are cropped; line 54, Y = -34.0, is kept), and is shadowed as under a lip: the rows
  // that recede behind X = 47.34 (line 49) are removed, lines 50 ... 54 (X 47.10 ... 46.74), and
  // the face continues vertically below line 49 to the deepest of them (Y = -34.0).
  LoadOptions deeper;
  deeper.crop_depth = 0.033;
  const LoadedProfile shadowed = load_profile(path, deeper);
  EXPECT_EQ(shadowed.cleaning.crop.cropped(), 2u);
  const LipReport& lip = shadowed.cleaning.lip;
  EXPECT_EQ(lip.hidden, 5u);
  EXPECT_EQ(lip.lines, std::make_pair(50, 54));
  EXPECT_NEAR(lip.edge_depth, (30.0 - 0.21) * 1e-3, 1e-15);
  EXPECT_NEAR(lip.deepest, (34.0 - 0.21) * 1e-3, 1e-15);
  EXPECT_EQ(lip.reason, whole + " (also after " + shadowed.cleaning.crop.summary() + ")");
  // The gauge face below the edge is the vertical X = 47.34 mm (in the profile frame -y), to
  // the 10 um the fit's smoothing (0.3 mm) overshoots at the edge's corner.
  EXPECT_NEAR(shadowed.profile.y_min(), -47.34e-3, 10e-6);
}

// A measured rail whose gauge face has a gap in the data below the gauge point (a roller
// measured in one MiniProf file jumps from 17 to 30 mm deep): rail_deep_undercut.ban with
// rows 43 ... 47 (25.4 ... 28.5 mm deep) removed, so its deep rows start 30 mm down, 4.6 mm
// below the last row above 25 mm. The crop drops them all (the deepest kept would lie across
// the gap, 2 mm or more below the depth) and the rail loads as rail_base.ban without its row 43.
TEST(RealRailFiles, ACropDropsDeepPointsBeyondAGapInTheData) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "wheelwear_rail_deep_gap.ban";
  {
    std::ifstream in(rail_file("rail_deep_undercut.ban"));
    std::ofstream out(path);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number)
      if (number < 43 || number > 47) out << (number == 3 ? "XYPoints=46" : line) << '\n';
  }
  const LoadedProfile rail = load_profile(path);
  EXPECT_EQ(rail.points_read, 46u);
  const CropReport& crop = rail.cleaning.crop;
  EXPECT_EQ(crop.gauge_side, 9u);  // every row 30 mm deep and more
  EXPECT_EQ(crop.gauge_lines, std::make_pair(43, 51));
  EXPECT_NEAR(gauge_point(rail.profile).point[1] - top_of_rail(rail.profile).point[1], 0.014,
              1e-12);  // the profile still reaches the gauge point
  std::filesystem::remove(path);
}

TEST(RealRailFiles, CroppingEveryRailIsAnOptionAndTheDepthIsChecked) {
  // The base rail is accepted whole, so by default nothing is cropped; cropping it at 20 mm
  // removes the rows deeper than 20.21 mm below Y = 0: lines 42 and 43 (23.92, 25.42) but the
  // first, line 41 (21.21).
  LoadOptions always;
  always.crop_always = true;
  always.crop_depth = 0.020;
  const LoadedProfile rail = load_profile(rail_file("rail_base.ban"), always);
  EXPECT_EQ(rail.cleaning.crop.gauge_side, 2u);
  EXPECT_EQ(rail.cleaning.crop.gauge_lines, std::make_pair(42, 43));
  EXPECT_EQ(rail.points.points.size(), 36u);
  EXPECT_EQ(rail.points.lines.front(), 41);  // the profile's -y end: the deepest row kept
  for (double depth : {0.010, -0.025, 0.5})
    EXPECT_EQ(error_of([&] {
                LoadOptions bad;
                bad.crop_depth = depth;
                load_profile(rail_file("rail_base.ban"), bad);
              }).rfind("rail crop depth [m] = ", 0),
              0u)
        << depth;
  // Wheels are never cropped: S1002 reaches 40 mm below its taping line.
  RawProfile wheel;
  wheel.source = "S1002";
  wheel.body = Body::wheel;
  wheel.points = s1002_points();
  LoadOptions wheel_options;
  wheel_options.crop_always = true;
  EXPECT_EQ(prepare_profile(wheel, wheel_options).cleaning.kept_points, wheel.points.size());
}

TEST(RealRailFiles, NoAcceptedContactLiesDeeperThanTheDefaultCrop) {
  // S1002 lowered onto 60E1 (upright, 1:40, 1:20) at lateral offsets from -10 to +10 mm: the
  // first touch (the smallest vertical gap z_rail - z_wheel) lies less than 12 mm below the top
  // of rail, well above the default crop depth.
  const Profile wheel = s1002();
  std::size_t compared = 0;
  for (double inclination : {0.0, std::atan(1.0 / 40.0), std::atan(1.0 / 20.0)}) {
    const Profile rail = rail_60e1({.inclination = inclination});
    const double top = top_of_rail(rail).point[1];
    for (int k = -20; k <= 20; ++k) {
      const double dy = 0.5e-3 * k;
      double gap = INFINITY, depth = 0.0;
      for (double y = rail.y_min(); y <= rail.y_max(); y += 0.02e-3) {
        const auto zr = rail.z_at(y), zw = wheel.z_at(y - dy);
        if (!zr || !zw || *zr - *zw >= gap) continue;
        gap = *zr - *zw;
        depth = *zr - top;
      }
      EXPECT_LT(depth, 0.012) << inclination << " " << dy;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 3u * 41u);
  EXPECT_GT(LoadOptions{}.crop_depth, 0.012);
}

TEST(RealRailFiles, MessagesQuoteTheWholeLineAndNameLinesInFileOrder) {
  const std::string row = "44.6300 -12.8800 -1.2788 0.00664896624107642   worn gauge face, see";
  ASSERT_GT(row.size(), 60u);
  EXPECT_EQ(
      error_of([&] { parse_miniprof("XYPoints=2\n\n1 2\n" + row + "\n", "long.ban", ".ban"); }),
      "long.ban:4: \"" + row +
          "\" is not a row of numbers (text after \", %, ! or # is a comment)");
  const std::string very_long = "1 2 -" + std::string(300, 'x');  // not words: refused
  EXPECT_EQ(error_of([&] {
              parse_miniprof("XYPoints=2\n\n1 2\n" + very_long + "\n", "long.ban", ".ban");
            }),
            "long.ban:4: \"" + very_long.substr(0, 200) +
                "...\" is not a row of numbers (text after \", %, ! or # is a comment)");
  // A gap in a MiniProf rail, whose rows the reader reverses: the lines come in file order.
  std::string text = testing::read_text(rail_file("rail_base.ban"));
  const auto from = text.find("24.3100 -1.5600\n"), to = text.find("36.6800 -4.9300\n");
  text.erase(from, to - from);  // lines 24 ... 30 (X 24.31 ... 34.97)
  text.replace(text.find("XYPoints=38"), 11, "XYPoints=31");
  // From (22.33, -1.27) at line 23 to (36.68, -4.93), now at line 24: hypot(14.35, 3.66).
  EXPECT_EQ(error_of([&] { prepare_profile(parse_miniprof(text, "gap.ban", ".ban")); }),
            "gap.ban: gap of 14.8094 mm between the points of lines 23 and 24 exceeds the 5 mm "
            "limit (missing data?)");
}

}  // namespace
}  // namespace wheelwear::profiles

namespace wheelwear::profiles {
namespace {

// CONTACT's averaged low rail: its gauge face recedes 0.6 mm under a lip from 12 mm below the
// top (above the gauge point) and its field side under another; the words after its last row and
// its point count one off are read with warnings. It loads with the lips shadowed and its gauge
// point on the lip's edge.
TEST(MeasuredRails, ALippedLowRailLoadsWithItsLipsShadowed) {
  const LoadedProfile rail = load_profile(testing::data_path("measured/avg_low2.ban"));
  const LipReport& lip = rail.cleaning.lip;
  EXPECT_GT(lip.hidden, 0u);
  EXPECT_LT(lip.edge_depth, 0.014);  // the gauge face recedes above the gauge point
  EXPECT_NE(lip.reason.find("the points go back"), std::string::npos) << lip.reason;
  std::vector<std::string> repairs;
  for (const ReadRepair& r : rail.cleaning.reading) repairs.push_back(r.name);
  EXPECT_NE(std::find(repairs.begin(), repairs.end(), "trailing_text"), repairs.end());
  EXPECT_NE(std::find(repairs.begin(), repairs.end(), "point_count"), repairs.end());
  // The gauge point lies on the vertical below the edge: its y is the edge's.
  const double gauge_y = gauge_point(rail.profile).point[0];
  EXPECT_NEAR(gauge_y, rail.profile.y_min(), 10e-6);  // the fit's rounding at the corner
}

// The roller's gauge face jumps from 17 to 30 mm deep: the crop drops the deep rows beyond the
// gap and the rest loads.
TEST(MeasuredRails, ARollerWithAGapLowOnItsFaceLoadsCropped) {
  const LoadedProfile roller =
      load_profile(testing::data_path("measured/left-roller-v1-pre-dry.ban"));
  EXPECT_EQ(roller.cleaning.crop.gauge_side, 6u);
  EXPECT_EQ(roller.cleaning.crop.gauge_lines, std::make_pair(36, 41));
  EXPECT_EQ(roller.cleaning.lip.hidden, 0u);
  EXPECT_NO_THROW(gauge_point(roller.profile));
}

}  // namespace
}  // namespace wheelwear::profiles
