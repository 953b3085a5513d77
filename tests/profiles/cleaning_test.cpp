// Tests of the cleaning pipeline: each named step on a planted defect, the report, the limit.

#include "wheelwear/profiles/cleaning.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

RawProfile numbered(const PointList& points) {
  RawProfile raw;
  raw.source = "planted.csv";
  raw.points = points;
  for (std::size_t i = 0; i < points.size(); ++i) raw.lines.push_back(static_cast<int>(i + 1));
  return raw;
}

const CleaningStep& step(const CleaningReport& report, const std::string& name) {
  for (const CleaningStep& s : report.steps)
    if (s.name == name) return s;
  throw std::runtime_error("no step " + name);
}

TEST(Cleaning, LeavesAStandardProfileAlone) {
  RawProfile raw = numbered(s1002_points());
  const CleaningReport report = clean(raw, Body::wheel);
  EXPECT_EQ(report.dropped(), 0u);
  EXPECT_TRUE(report.kinks.empty());  // 0.1 mm steps turn by 0.5 deg at most (R12 tip)
  EXPECT_EQ(report.steps.size(), 4u);
}

TEST(Cleaning, EachStepRemovesItsDefect) {
  PointList points = rail_60e1_points({.point_spacing = 0.5e-3});
  const std::size_t n = points.size();
  // On the near-vertical gauge flank, y steps back 0.2 mm while z advances 0.5 mm: a reversal,
  // but a turn of only 46 deg.
  points[10][0] = points[9][0] - 0.2e-3;
  points[20] = Point(0.5, 0.5);      // a sentinel far away
  points[150] += Point(0.0, -2e-3);  // a 2 mm spike on the crown: turns by 152 deg
  points.insert(points.begin() + 40, points[40] + Point(2e-6, 0));  // a near-duplicate
  RawProfile raw = numbered(points);
  const CleaningReport report = clean(raw, Body::rail);
  EXPECT_EQ(step(report, "bounding_box").lines, std::vector<int>{21});
  EXPECT_EQ(step(report, "merge_duplicates").lines, std::vector<int>{42});
  EXPECT_EQ(step(report, "fold_backs").lines, std::vector<int>{152});
  EXPECT_EQ(step(report, "reversing_segments").lines, std::vector<int>{11});
  EXPECT_EQ(report.input_points, n + 1);
  EXPECT_EQ(report.dropped(), 4u);
  EXPECT_EQ(report.kept_points, raw.points.size());
  EXPECT_NE(report.summary().find("bounding_box 1"), std::string::npos) << report.summary();
  for (std::size_t i = 1; i < raw.points.size(); ++i)
    EXPECT_GE(raw.points[i][0], raw.points[i - 1][0]);
}

TEST(Cleaning, ReportsKinksButKeepsThem) {
  // A 45 deg chamfer corner, sampled every 0.5 mm: real, so it is kept and reported.
  PointList points;
  for (int i = 0; i <= 40; ++i) points.emplace_back(-0.02 + 0.0005 * i, 0.0);
  for (int i = 1; i <= 20; ++i) points.emplace_back(0.0005 * i, 0.0005 * i);
  RawProfile raw = numbered(points);
  const CleaningReport report = clean(raw, Body::wheel);
  EXPECT_EQ(report.dropped(), 0u);
  ASSERT_EQ(report.kinks.size(), 1u);
  EXPECT_EQ(report.kinks.front().line, 41);
  EXPECT_NEAR(report.kinks.front().angle_deg, 45.0, 1e-9);
}

TEST(Cleaning, ReversalsAreRemovedFromRailsOnly) {
  // A steep face whose 21st point steps back 0.2 mm in y: noise on a rail, legitimate on a
  // wheel (its flange back may overhang).
  PointList points;
  for (int i = 0; i < 40; ++i) points.emplace_back(1e-5 * i, 5e-4 * i);
  points[20][0] -= 2e-4;
  RawProfile wheel = numbered(points);
  EXPECT_EQ(step(clean(wheel, Body::wheel), "reversing_segments").dropped, 0u);
  RawProfile rail = numbered(points);
  EXPECT_EQ(step(clean(rail, Body::rail), "reversing_segments").lines, std::vector<int>{21});
  RawProfile forced = numbered(points);
  CleaningOptions options;
  options.remove_reversals = true;
  EXPECT_EQ(step(clean(forced, Body::wheel, options), "reversing_segments").dropped, 1u);
}

TEST(Cleaning, VerticalStretchesGoOnlyWhenAsked) {
  // 60E1 inclined 1:20: its gauge flank is exactly vertical, which a rail may have.
  const PointList points = rail_60e1_points({.inclination = std::atan(1.0 / 20.0)});
  RawProfile kept = numbered(points);
  EXPECT_EQ(clean(kept, Body::rail).dropped(), 0u);
  // Asked to keep segments within 80 deg of the y axis, the cleaning drops the flank and the
  // steepest part of the R13 arc (from 80 deg on), which together exceed the 20% limit.
  RawProfile steep = numbered(points);
  CleaningOptions options;
  options.max_segment_angle_deg = 80.0;
  options.max_drop_fraction = 1.0;
  const CleaningReport report = clean(steep, Body::rail, options);
  EXPECT_GT(step(report, "reversing_segments").dropped, 200u);
  for (std::size_t i = 1; i < steep.points.size(); ++i) {
    const Point d = steep.points[i] - steep.points[i - 1];
    ASSERT_LE(std::abs(d[1]), std::tan(80.0 * std::acos(-1.0) / 180.0) * d[0] * (1 + 1e-12));
  }
}

TEST(Cleaning, FailsWhenItWouldDropTooMuch) {
  PointList points = rail_60e1_points({.point_spacing = 0.5e-3});
  for (std::size_t i = 0; i < points.size(); i += 3) points[i] += Point(0.0, 5e-3);  // every third
  RawProfile raw = numbered(points);
  try {
    clean(raw, Body::rail);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("planted.csv: cleaning dropped"), std::string::npos) << message;
    EXPECT_NE(message.find("more than the allowed 20%"), std::string::npos) << message;
    EXPECT_NE(message.find("fold_backs"), std::string::npos) << message;
  }
  CleaningOptions loose;
  loose.max_drop_fraction = 1.0;
  RawProfile again = numbered(points);
  EXPECT_NO_THROW(clean(again, Body::rail, loose));
  EXPECT_THROW(clean(again, Body::rail, {.max_turn_deg = 0.0}), InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
