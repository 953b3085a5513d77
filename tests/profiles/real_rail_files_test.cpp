// Real rail files and the formats around them: each small file in tests/data/profiles carries one
// cause a real file showed (tests/data/README.md), and its test asserts the cleaned result against
// a file without that cause (rail_base.ban, the same rows) or the standard profile it was made
// from, and the exact report or message.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

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

using testing::data_path;

std::filesystem::path rail_file(const std::string& name) {
  return data_path("profiles/" + name);
}

std::string error_of(const std::function<void()>& run) {
  try {
    run();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

LoadOptions as_rail() {
  LoadOptions options;
  options.read.body = Body::rail;
  return options;
}

// Same points and lines, and the same fitted curve, bit for bit; returns the points compared.
std::size_t expect_same_profile(const LoadedProfile& a, const LoadedProfile& b, int line_shift) {
  EXPECT_EQ(a.points.points.size(), b.points.points.size());
  std::size_t compared = 0;
  for (std::size_t i = 0; i < std::min(a.points.points.size(), b.points.points.size()); ++i) {
    EXPECT_EQ(a.points.points[i], b.points.points[i]) << i;
    EXPECT_EQ(a.points.lines[i], b.points.lines[i] + line_shift) << i;
    ++compared;
  }
  const PointList ka = a.profile.knot_points(), kb = b.profile.knot_points();
  EXPECT_EQ(ka.size(), kb.size());
  for (std::size_t i = 0; i < std::min(ka.size(), kb.size()); ++i, ++compared)
    EXPECT_EQ(ka[i], kb[i]) << "knot " << i;
  return compared;
}

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
  // Cropped at 33 mm (33.21 mm below Y = 0), the undercut stays: the same error, and the crop
  // that did not help (lines 55, 56: Y = -34.8, -35.6; line 54, Y = -34.0, is kept).
  LoadOptions deeper;
  deeper.crop_depth = 0.033;
  EXPECT_EQ(error_of([&] { load_profile(path, deeper); }),
            whole +
                " (also after cropped 2 points deeper than 33 mm below the top of rail (gauge "
                "side 2, lines 55 ... 56; down to 35.4 mm))");
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
  const std::string very_long = "1 2 " + std::string(300, 'x');
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

TEST(RealRailFiles, EveryFormatReadsTrailingCommentsOnRows) {
  // Plain columns: comments after numbers are cut and reported; the header stays a header.
  const RawProfile columns = parse_columns(
      "y,z\n1.5,2.5 % a\n3.5,4.5\n5.5,6.5 ! b\n7.5,8.5 \" c\n9.5,10.5 # d\n", "c.csv");
  ASSERT_EQ(columns.points.size(), 5u);
  EXPECT_EQ(columns.points[4], Point(9.5e-3, 10.5e-3));
  EXPECT_EQ(columns.notes.front(), "columns from the header (line 1)");
  ASSERT_EQ(columns.repairs.size(), 1u);
  EXPECT_EQ(columns.repairs.front().lines, (std::vector<int>{2, 4, 5, 6}));
  EXPECT_EQ(columns.repairs.front().message,
            "c.csv:2: 4 point rows carry text after their numbers, read as a comment (after \", "
            "%, ! or #)");
  // Simpack: '!' is the format's own comment, the others are reported.
  const RawProfile simpack = parse_simpack(
      "header.begin\n type = 0\nheader.end\nspline.begin\n point.begin\n 1 2 ! fine\n"
      " 3 4 % note\n 5 6\n point.end\nspline.end\n",
      "s.prr");
  ASSERT_EQ(simpack.points.size(), 3u);
  EXPECT_EQ(simpack.points[1], Point(3e-3, 4e-3));
  ASSERT_EQ(simpack.repairs.size(), 1u);
  EXPECT_EQ(simpack.repairs.front().message,
            "s.prr:7: 1 point row carries text after its numbers, read as a comment (after \", % "
            "or #)");
}

TEST(RealRailFiles, DenseNoiseFreeSamplingIsNotRefused) {
  // S1002 sampled every 5 um (made here: 0.2 m of profile in 40 000 rows). Merging joins runs of
  // points within 10 um of their first, two or three of them: more than half the points merge,
  // none is lost, and each merged point stays on the sampled curve.
  const PointList dense = s1002().resample(5e-6);
  const auto dir = testing::scratch_dir();
  write_csv(dir / "s1002_dense.csv", dense, {.body = Body::wheel});
  const LoadedProfile wheel = load_profile(dir / "s1002_dense.csv");
  const std::size_t n = dense.size();
  const std::size_t kept = wheel.cleaning.kept_points;
  EXPECT_EQ(wheel.points_read, n);
  EXPECT_GE(kept, n / 3);
  EXPECT_LE(kept, n / 2 + 1);
  EXPECT_EQ(wheel.cleaning.merged(), n - kept);
  EXPECT_EQ(wheel.cleaning.discarded(), 0u);
  EXPECT_EQ(wheel.cleaning.summary(), "kept " + std::to_string(kept) + " of " + std::to_string(n) +
                                          " points (merge_duplicates " + std::to_string(n - kept) +
                                          ")");
  // Distance of each kept point to the polyline through the samples, walked in order.
  std::size_t segment = 0, compared = 0;
  for (const Point& p : wheel.points.points) {
    double best = INFINITY;
    for (std::size_t j = segment; j + 1 < n && j < segment + 8; ++j) {
      const Point a = dense[j], d = dense[j + 1] - a;
      const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
      const double distance = (a + t * d - p).norm();
      if (distance < best) {
        best = distance;
        segment = j;
      }
    }
    ASSERT_LT(best, 1e-9) << compared;
    ++compared;
  }
  EXPECT_EQ(compared, kept);
}

TEST(RealRailFiles, MergedDuplicatesAreNamedApartWhenTooMuchIsDropped) {
  // Every third point of 60E1 spiked by 5 mm (a third dropped by fold_backs) and ten points
  // doubled 2 um apart: the limit counts the fold-backs only and the message names the merges.
  PointList points = rail_60e1_points({.point_spacing = 0.5e-3});
  for (std::size_t i = 0; i < points.size(); i += 3) points[i] += Point(0.0, 5e-3);
  for (std::size_t i = 0; i < 10; ++i) {
    const std::size_t at = 50 + 20 * i;
    points.insert(points.begin() + static_cast<std::ptrdiff_t>(at), points[at] + Point(2e-6, 0));
  }
  RawProfile raw;
  raw.source = "spiked.csv";
  raw.points = points;
  const std::string message = error_of([&] { clean(raw, Body::rail); });
  EXPECT_NE(message.find("; besides, 10 near-duplicate points were merged (not counted). The "
                         "data are too noisy or are not one profile."),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find("merge_duplicates"), std::string::npos) << message;
}

TEST(RealRailFiles, MiniprofMptFilesAreRefusedByName) {
  const auto mpt = rail_file("miniprof_multi_profile.mpt");
  EXPECT_EQ(detect_format(mpt, ""), FileFormat::miniprof);
  EXPECT_EQ(error_of([&] { load_profile(mpt, as_rail()); }),
            mpt.string() +
                ": MiniProf .mpt files are not supported; export .whl/.ban from "
                "MiniProf");
  // Under another name, by its first line.
  const auto dir = testing::scratch_dir();
  testing::write_text(dir / "profile.txt", testing::read_text(mpt));
  EXPECT_EQ(error_of([&] { load_profile(dir / "profile.txt", as_rail()); }),
            (dir / "profile.txt").string() +
                ":1: \"[FileInfo]\" begins a MiniProf multi-profile (.mpt) file; MiniProf .mpt "
                "files are not supported; export .whl/.ban from MiniProf");
}

TEST(RealRailFiles, AFileThatSaysItIsARailIsNotTakenForAWheel) {
  const auto path = rail_file("simpack_rail_type0.prr");
  LoadOptions wheel;
  wheel.read.body = Body::wheel;
  EXPECT_EQ(error_of([&] { load_profile(path, wheel); }),
            path.string() +
                ":4: the file says it is a rail profile (type = 0), but a wheel profile is "
                "expected here; give a wheel profile file");
  // As a rail (said or not) it is rail_base.ban in CONTACT's frame: the same points, up to the
  // rounding of mm -> m.
  const LoadedProfile rail = load_profile(path);
  const LoadedProfile base = load_profile(rail_file("rail_base.ban"));
  ASSERT_EQ(rail.points.points.size(), base.points.points.size());
  for (std::size_t i = 0; i < base.points.points.size(); ++i)
    EXPECT_NEAR((rail.points.points[i] - base.points.points[i]).norm(), 0.0, 1e-17) << i;
  EXPECT_NO_THROW(load_profile(path, as_rail()));
  // The same for wheelwear's own "# body:" line.
  const auto dir = testing::scratch_dir();
  write_csv(dir / "rail.csv", rail_60e1_points(), {.body = Body::rail});
  EXPECT_EQ(error_of([&] { load_profile(dir / "rail.csv", wheel); }),
            (dir / "rail.csv").string() +
                ":2: the file says it is a rail profile, but a wheel profile is expected here; "
                "give a wheel profile file");
}

// switch_rail_field_side_deeper.ban: 60E1 at 1:40 (rail_60e1_points, 1 mm apart) measured down to
// 16 mm on the gauge side and 22 mm on the field side, in MiniProf rail axes (X = -y, Y = -z): the
// automatic rule takes the deeper field side for the gauge face.
TEST(RealRailFiles, AMirroredSwitchRailIsWarnedOfAndSetRightByTheGaugeSide) {
  const auto path = rail_file("switch_rail_field_side_deeper.ban");
  const double incl = std::atan(1.0 / 40.0);
  const Profile reference = rail_60e1({.inclination = incl});
  const LoadedProfile automatic = load_profile(path);
  EXPECT_FALSE(automatic.orientation.mirrored_y);  // wrong: MiniProf's X runs to the gauge face
  const auto wrong = estimate_inclination(automatic.profile);
  ASSERT_TRUE(wrong);
  EXPECT_NEAR(wrong->angle, -incl, 1e-3);
  ASSERT_EQ(automatic.cleaning.warnings.size(), 1u);
  EXPECT_EQ(automatic.cleaning.warnings.front(),
            path.string() +
                ": the field side lies lower than the gauge side (estimated inclination -0.0248 "
                "rad, about 1:40), but rails are canted towards the track centre: the gauge face "
                "is probably at the file's other end (larger lateral values; the automatic rule "
                "takes the end measured deeper). Set the gauge side if so (profile --gauge-side "
                "right, LoadOptions::orientation.mirror_y)");

  LoadOptions right;
  right.orientation.mirror_y = *gauge_side_mirror("right");
  const LoadedProfile set = load_profile(path, right);
  EXPECT_TRUE(set.orientation.mirrored_y);
  EXPECT_TRUE(set.cleaning.warnings.empty());
  const auto estimate = estimate_inclination(set.profile);
  ASSERT_TRUE(estimate);
  EXPECT_NEAR(estimate->angle, incl, 1e-3);
  // The head as generated: over the crown, within the smoothing of 1 mm steps.
  std::size_t compared = 0;
  for (int k = -60; k <= 50; ++k, ++compared) {
    const double y = 0.5e-3 * k;
    ASSERT_NEAR(*set.profile.z_at(y), *reference.z_at(y), 0.01e-3) << y;
  }
  EXPECT_EQ(compared, 111u);
  EXPECT_EQ(gauge_side_mirror("left"), Mirror::keep);
  EXPECT_EQ(gauge_side_mirror("auto"), Mirror::automatic);
  EXPECT_FALSE(gauge_side_mirror("gauge"));
}

// rail_shallow_gauge_side.ban: 60E1 at 1:40 measured down to 10 mm on the gauge side, 5 mm on the
// field side.
TEST(RealRailFiles, ARailWithoutAGaugePointIsWarnedOf) {
  const auto path = rail_file("rail_shallow_gauge_side.ban");
  const LoadedProfile rail = load_profile(path);
  EXPECT_TRUE(rail.orientation.mirrored_y);
  EXPECT_THROW(gauge_point(rail.profile), InputError);
  EXPECT_FALSE(estimate_inclination(rail.profile));
  // Its last row, line 78, is the gauge end: 9.6 mm below the top (Y = 0).
  ASSERT_EQ(rail.cleaning.warnings.size(), 1u);
  EXPECT_EQ(rail.cleaning.warnings.front(),
            path.string() +
                ":78: no gauge point: the gauge side (the profile's -y end, the file's larger "
                "lateral values) reaches 9.6 mm below the top of rail, less than the 14.0 mm "
                "where the gauge is measured, so `contact` cannot place this rail. If the gauge "
                "face is at the file's other end, set the gauge side (profile --gauge-side, "
                "LoadOptions::orientation.mirror_y)");
}

TEST(RealRailFiles, TheInclinationEstimateFindsTheCant) {
  std::size_t compared = 0;
  for (double incl : {0.0, 1.0 / 200.0, std::atan(1.0 / 40.0), std::atan(1.0 / 20.0)}) {
    const auto estimate = estimate_inclination(rail_60e1({.inclination = incl}));
    ASSERT_TRUE(estimate);
    EXPECT_NEAR(estimate->angle, incl, 1e-3) << incl;
    ++compared;
  }
  // CONTACT's benchmark rail, "already canted" 1:40.
  const auto contact = estimate_inclination(load_profile(testing::contact_rail_file()).profile);
  ASSERT_TRUE(contact);
  EXPECT_NEAR(contact->angle, std::atan(1.0 / 40.0), 1e-3);
  EXPECT_EQ(compared + 1, 5u);
}

// The measured files load as they did before rails were cropped and repaired: the counts, and
// coordinates as that loader printed them (17 digits). 1e-12 m: the same points fitted by a
// build for another CPU (fused multiply-adds or not) move by 4e-13 m at most.
constexpr double kSameFit = 1e-12;
TEST(RealRailFiles, TheMeasuredFilesLoadAsBefore) {
  const LoadedProfile rail = load_profile(testing::measured_rail_file());
  EXPECT_EQ(rail.points_read, 147u);
  EXPECT_EQ(rail.cleaning.kept_points, 146u);
  EXPECT_EQ(rail.cleaning.merged(), 1u);
  EXPECT_EQ(rail.cleaning.crop.cropped(), 0u);
  EXPECT_TRUE(rail.cleaning.reading.empty());
  EXPECT_TRUE(rail.cleaning.warnings.empty());
  EXPECT_NEAR(rail.profile.y_min(), -0.046589730130667452, kSameFit);
  EXPECT_NEAR(rail.profile.y_max(), 0.011729949340548671, kSameFit);
  EXPECT_NEAR(rail.profile.length(), 0.073426030788322716, kSameFit);
  EXPECT_NEAR(top_of_rail(rail.profile).point[0], -0.0041084863967899071, kSameFit);
  EXPECT_NEAR(gauge_point(rail.profile).point[0], -0.044875462076385528, kSameFit);
  const LoadedProfile wheel = load_profile(testing::measured_wheel_file());
  EXPECT_EQ(wheel.points_read, 645u);
  EXPECT_EQ(wheel.cleaning.kept_points, 643u);
  EXPECT_EQ(wheel.cleaning.discarded(), 2u);
  EXPECT_TRUE(wheel.cleaning.reading.empty());
  EXPECT_NEAR(wheel.profile.y_min(), -0.00015549153165455548, kSameFit);
  EXPECT_NEAR(wheel.profile.y_max(), 0.13135365393617759, kSameFit);
  EXPECT_NEAR(wheel.profile.length(), 0.19913375918870874, kSameFit);
}

}  // namespace
}  // namespace wheelwear::profiles
