// Tests of the whole loading chain on the real files: measured profiles read, clean and validate;
// the same profile in mm and in m gives the same result.

#include "wheelwear/profiles/profile_loader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/columns_format.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/track.hpp"

namespace wheelwear::profiles {
namespace {

std::vector<int> lines_dropped(const CleaningReport& report) {
  std::vector<int> lines;
  for (const auto& step : report.steps)
    lines.insert(lines.end(), step.lines.begin(), step.lines.end());
  return lines;
}

TEST(ProfileLoader, MeasuredWheelReadsCleansAndValidates) {
  const LoadedProfile wheel = load_profile(testing::measured_wheel_file());
  EXPECT_EQ(wheel.profile.body(), Body::wheel);  // from the .whl extension
  EXPECT_EQ(wheel.points_read, 645u);
  // MiniProf's wheel axes already are the profile frame: nothing mirrored or reversed.
  EXPECT_FALSE(wheel.orientation.mirrored_y);
  EXPECT_FALSE(wheel.orientation.mirrored_z);
  EXPECT_FALSE(wheel.orientation.reversed);
  // The trace folds back at the flange tip (lines 222-229: y runs 15.895 -> 15.298 mm): the
  // fold_backs step drops two points there and the rest of the zigzag is reported as kinks.
  EXPECT_EQ(wheel.cleaning.dropped(), 2u);
  for (int line : lines_dropped(wheel.cleaning)) {
    EXPECT_GE(line, 220);
    EXPECT_LE(line, 229);
  }
  EXPECT_GE(wheel.cleaning.kinks.size(), 4u);
  for (const Kink& kink : wheel.cleaning.kinks) {
    EXPECT_GE(kink.line, 219);
    EXPECT_LE(kink.line, 230);
  }
  // Flange back at X = 0 (MiniProf's origin), field side at X = 131 mm; the automatic origin
  // rule takes the internal face and moves the wheel by 70 mm to put the taping line at y = 0.
  EXPECT_EQ(wheel.origin.origin, WheelOrigin::internal_face);
  EXPECT_NEAR(wheel.profile.y_min(), -0.070, 0.2e-3);
  EXPECT_NEAR(wheel.profile.y_max(), 0.1313 - 0.070, 0.1e-3);
}

TEST(ProfileLoader, MeasuredRailReadsCleansAndValidates) {
  const LoadedProfile rail = load_profile(testing::measured_rail_file());
  EXPECT_EQ(rail.profile.body(), Body::rail);
  // MiniProf's rail axes (X towards the gauge face, Y up) are turned into the profile frame.
  EXPECT_TRUE(rail.orientation.mirrored_y);
  EXPECT_TRUE(rail.orientation.mirrored_z);
  EXPECT_TRUE(rail.orientation.reversed);
  EXPECT_EQ(rail.cleaning.dropped(), 1u);  // two rows 0.01 mm apart on the gauge face, merged
  // The gauge face is measured 25 mm deep: a gauge point exists, on the -y side of the top.
  const ProfilePoint top = top_of_rail(rail.profile);
  const ProfilePoint gauge = gauge_point(rail.profile);
  EXPECT_LT(gauge.point[0], top.point[0] - 0.030);
  EXPECT_NEAR(gauge.point[1] - top.point[1], 0.014, 1e-9);
}

TEST(ProfileLoader, ContactFilesLoadInTheirFrame) {
  const LoadedProfile wheel = load_profile(testing::contact_wheel_file());
  EXPECT_TRUE(wheel.orientation.reversed);  // CONTACT lists wheels with y descending
  EXPECT_EQ(wheel.cleaning.dropped(), 0u);
  const LoadedProfile rail = load_profile(testing::contact_rail_file());
  EXPECT_FALSE(rail.orientation.mirrored_y);
  EXPECT_FALSE(rail.orientation.reversed);
  // The file repeats points 0.05 um apart at the flank bottoms; they are merged.
  EXPECT_GT(rail.cleaning.dropped(), 0u);
  EXPECT_LT(rail.cleaning.dropped(), rail.points_read / 10);
}

TEST(ProfileLoader, AStraySentinelIsCleanedNotTakenForAUnitError) {
  // A -999 mm "no reading" value in one row: the bounding box drops it; the unit check, which
  // looks at the 5th to 95th percentile of y, is not fooled by it.
  PointList points = s1002_points({.point_spacing = 0.5e-3});
  points[100] = Point(-0.999, -0.999);
  RawProfile raw;
  raw.source = "sentinel.csv";
  raw.points = points;
  raw.body = Body::wheel;
  const LoadedProfile loaded = prepare_profile(raw);
  EXPECT_EQ(loaded.cleaning.dropped(), 1u);
  EXPECT_EQ(loaded.cleaning.steps.front().name, "bounding_box");
  EXPECT_EQ(loaded.cleaning.steps.front().dropped, 1u);
}

TEST(ProfileLoader, SameProfileInMillimetresAndMetresGivesTheSameResult) {
  const PointList points = s1002_points({.point_spacing = 0.2e-3});
  const auto dir = testing::scratch_dir();
  std::ostringstream mm, m;
  mm.precision(17);
  m.precision(17);
  for (const Point& p : points) {
    mm << p[0] * 1e3 << ' ' << p[1] * 1e3 << '\n';
    m << p[0] << ' ' << p[1] << '\n';
  }
  testing::write_text(dir / "mm.txt", mm.str());
  testing::write_text(dir / "m.txt", m.str());
  LoadOptions options;
  options.read.body = Body::wheel;
  const LoadedProfile a = load_profile(dir / "mm.txt", options);
  const LoadedProfile b = load_profile(dir / "m.txt", options);
  // Identical inputs up to one rounding of the mm -> m conversion: the fits agree to round-off.
  EXPECT_NEAR(a.profile.length(), b.profile.length(), 1e-15);
  for (double s = 0.0; s <= a.profile.length(); s += 0.5e-3) {
    ASSERT_NEAR((a.profile.position(s) - b.profile.position(s)).norm(), 0.0, 1e-14);
    ASSERT_NEAR(a.profile.curvature(s), b.profile.curvature(s),
                1e-6 * (1.0 + std::abs(a.profile.curvature(s))));
  }
}

}  // namespace
}  // namespace wheelwear::profiles
