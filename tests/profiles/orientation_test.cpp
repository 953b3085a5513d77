// Tests of automatic orientation: every mirrored and reversed version of the standard profiles
// comes back to the profile frame.

#include "wheelwear/profiles/orientation.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

RawProfile raw_of(const PointList& points, bool mirror_y, bool mirror_z, bool reverse) {
  RawProfile raw;
  raw.source = "test";
  for (std::size_t i = 0; i < points.size(); ++i) {
    raw.points.emplace_back(mirror_y ? -points[i][0] : points[i][0],
                            mirror_z ? -points[i][1] : points[i][1]);
    raw.lines.push_back(static_cast<int>(i + 1));
  }
  if (reverse) {
    std::reverse(raw.points.begin(), raw.points.end());
    std::reverse(raw.lines.begin(), raw.lines.end());
  }
  return raw;
}

TEST(Orientation, RestoresEveryMirroredOrReversedStandardProfile) {
  // 60E1 at 1:40: its gauge end lies 1.86 mm deeper than its field end, which tells the sides.
  for (Body body : {Body::wheel, Body::rail}) {
    const PointList points = body == Body::wheel ? s1002_points() : rail_60e1_points();
    for (int variant = 0; variant < 8; ++variant) {
      const bool my = variant & 1, mz = variant & 2, rev = variant & 4;
      RawProfile raw = raw_of(points, my, mz, rev);
      const OrientationReport report = orient(raw, body);
      EXPECT_EQ(report.mirrored_y, my) << to_string(body) << " variant " << variant;
      EXPECT_EQ(report.mirrored_z, mz) << to_string(body) << " variant " << variant;
      ASSERT_EQ(raw.points.size(), points.size());
      for (std::size_t i = 0; i < points.size(); ++i) ASSERT_EQ(raw.points[i], points[i]);
      EXPECT_EQ(report.reversed, rev) << to_string(body) << " variant " << variant;
      EXPECT_EQ(raw.lines.front(), 1);  // the line numbers travel with their points
    }
  }
}

TEST(Orientation, KeepsASymmetricRailAndObeysExplicitChoices) {
  const PointList upright = rail_60e1_points({.inclination = 0.0});
  RawProfile raw = raw_of(upright, false, false, false);
  EXPECT_FALSE(orient(raw, Body::rail).mirrored_y);  // both ends equally deep: kept
  RawProfile forced = raw_of(upright, false, false, false);
  const OrientationReport report = orient(forced, Body::rail, {Mirror::flip, Mirror::keep});
  EXPECT_TRUE(report.mirrored_y);
  EXPECT_FALSE(report.mirrored_z);
  // Mirrored in y the order runs from +y to -y, so it is reversed as well.
  EXPECT_TRUE(report.reversed);
  EXPECT_NEAR(forced.points.front()[0], upright.front()[0], 1e-15);
}

}  // namespace
}  // namespace wheelwear::profiles
