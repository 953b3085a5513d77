// Real rail files, continued: comments in every format, dense sampling, MiniProf .mpt, a file's
// stated body, a mirrored switch rail, a rail without a gauge point, the inclination estimate,
// and the measured files loading as before.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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
                "takes the end measured deeper). Set the gauge side if so (--gauge-side right, the "
                "scene's [rail] gauge_side, LoadOptions::orientation.mirror_y)");

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
  EXPECT_EQ(
      rail.cleaning.warnings.front(),
      path.string() +
          ":78: no gauge point: the gauge side (the profile's -y end, the file's larger "
          "lateral values) reaches 9.6 mm below the top of rail, less than the 14.0 mm "
          "where the gauge is measured, so `contact` cannot place this rail. If the gauge "
          "face is at the file's other end, set the gauge side (--gauge-side of profile, "
          "contact and wear, the scene's [rail] gauge_side, LoadOptions::orientation.mirror_y)");
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
  // Moved by the internal-face origin (70 mm): the same fit, shifted.
  EXPECT_NEAR(wheel.profile.y_min(), -0.00015549153165455548 - 0.070, kSameFit);
  EXPECT_NEAR(wheel.profile.y_max(), 0.13135365393617759 - 0.070, kSameFit);
  EXPECT_NEAR(wheel.profile.length(), 0.19913375918870874, kSameFit);
}

}  // namespace
}  // namespace wheelwear::profiles
