// Tests of the validation checks: self-intersection with exact predicates, and each error.

#include "wheelwear/profiles/validation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

std::string error_of(const std::function<void()>& check) {
  try {
    check();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

RawProfile numbered(const PointList& points) {
  RawProfile raw;
  raw.source = "v.csv";
  raw.points = points;
  for (std::size_t i = 0; i < points.size(); ++i) raw.lines.push_back(static_cast<int>(i + 1));
  return raw;
}

TEST(SelfIntersection, FindsCrossingsAndOverlapsOnly) {
  // A figure eight.
  const PointList eight = {Point(0, 0), Point(1, 1), Point(2, 0),
                           Point(2, 1), Point(1, 0), Point(0, 1)};
  const auto crossing = find_self_intersection(eight);
  ASSERT_TRUE(crossing);
  EXPECT_EQ(crossing->first, 0u);  // of the two crossings, the one of the earliest segment
  EXPECT_EQ(crossing->second, 4u);
  EXPECT_NEAR(crossing->where[0], 0.5, 1e-12);
  EXPECT_NEAR(crossing->where[1], 0.5, 1e-12);
  // A zigzag that never crosses, with touching-free sharp turns.
  EXPECT_FALSE(
      find_self_intersection({Point(0, 0), Point(1, 1), Point(2, 0), Point(3, 1), Point(4, 0)}));
  // Running straight back over itself (neighbouring segments overlap).
  const auto back = find_self_intersection({Point(0, 0), Point(2, 0), Point(1, 0), Point(1, 5)});
  ASSERT_TRUE(back);
  EXPECT_EQ(back->first, 0u);
  EXPECT_EQ(back->second, 1u);
  // A far segment touching exactly at one point counts (exact predicate, no tolerance).
  EXPECT_TRUE(
      find_self_intersection({Point(0, 0), Point(4, 0), Point(4, 1), Point(2, 1), Point(2, 0)}));
  // Nearly touching is not touching: 1e-17 apart, exact predicates still tell them apart.
  EXPECT_FALSE(find_self_intersection(
      {Point(0, 0), Point(4, 0), Point(4, 1), Point(2, 1), Point(2, 1e-17)}));
  EXPECT_FALSE(find_self_intersection(s1002_points()));
}

TEST(Validation, NamesLineAndProblem) {
  PointList points = s1002_points();
  RawProfile raw = numbered(points);
  EXPECT_NO_THROW(validate_points(raw));
  EXPECT_NO_THROW(validate_geometry(raw));

  RawProfile nan = raw;
  nan.points[9][1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error_of([&] { validate_points(nan); }).find("v.csv:10: z = nan: not a finite"),
            std::string::npos);
  RawProfile few = numbered({Point(0, 0), Point(0.01, 0), Point(0.02, 0)});
  EXPECT_NE(error_of([&] { validate_points(few); }).find("only 3 profile points; at least 10"),
            std::string::npos);
  RawProfile none = numbered({});
  EXPECT_NE(error_of([&] { validate_points(none); }).find("no profile points"), std::string::npos);

  RawProfile large = raw;
  for (Point& p : large.points) p *= 1000.0;
  EXPECT_NE(error_of([&] { validate_points(large); }).find("1000 times too large"),
            std::string::npos);
  RawProfile small = raw;
  for (Point& p : small.points) p *= 0.001;
  EXPECT_NE(error_of([&] { validate_points(small); }).find("1000 times too small"),
            std::string::npos);

  RawProfile gap = raw;
  gap.points.erase(gap.points.begin() + 300, gap.points.begin() + 400);
  gap.lines.erase(gap.lines.begin() + 300, gap.lines.begin() + 400);
  EXPECT_NE(
      error_of([&] { validate_geometry(gap); }).find("between the points of lines 300 and 401"),
      std::string::npos)
      << error_of([&] { validate_geometry(gap); });
}

TEST(Validation, OrderMattersForRailsOnly) {
  PointList points;
  for (int i = 0; i < 60; ++i) points.emplace_back(-0.03 + 0.001 * i, 0.0);
  points[30][0] -= 2e-3;  // back 1 mm behind point 29: out of order
  RawProfile raw = numbered(points);
  EXPECT_NO_THROW(validate_order(raw, Body::wheel));
  EXPECT_NE(error_of([&] {
              validate_order(raw, Body::rail);
            }).find("v.csv:31: y = -2 mm after y = -1 mm at line 30"),
            std::string::npos)
      << error_of([&] { validate_order(raw, Body::rail); });
  points[30][0] = points[29][0] - 0.2e-3;  // 0.2 mm back: noise, left to the cleaning
  RawProfile noisy = numbered(points);
  EXPECT_NO_THROW(validate_order(noisy, Body::rail));
  ValidationOptions strict;
  strict.monotonic_y = true;
  strict.order_tolerance = 0.0;
  EXPECT_THROW(validate_order(noisy, Body::wheel, strict), InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
