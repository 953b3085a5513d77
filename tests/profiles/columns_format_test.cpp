// Tests of the plain-text/CSV reader and writer: round trips, units, column order, bad rows.

#include "wheelwear/profiles/columns_format.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

// Numbers are written in shortest round-trip form; converting m -> mm -> m costs an ulp or two
// of each product: 1.4e-17 m at 0.07 m.
constexpr double kRoundTrip = 1e-16;

std::string plain_text(const PointList& points, double scale, const char* separator,
                       bool z_first = false) {
  std::ostringstream out;
  out.precision(17);
  for (const Point& p : points) {
    if (z_first)
      out << p[1] * scale << separator << p[0] * scale << '\n';
    else
      out << p[0] * scale << separator << p[1] * scale << '\n';
  }
  return out.str();
}

void expect_same(const PointList& a, const PointList& b, double tolerance) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_NEAR(a[i][0], b[i][0], tolerance) << i;
    ASSERT_NEAR(a[i][1], b[i][1], tolerance) << i;
  }
}

TEST(ColumnsFormat, RoundTripsInMillimetresAndMetres) {
  const PointList points = s1002_points();
  for (LengthUnit unit : {LengthUnit::millimetre, LengthUnit::metre}) {
    CsvWriteOptions options;
    options.unit = unit;
    options.name = "S1002";
    options.body = Body::wheel;
    options.side = Side::left;
    const RawProfile back = parse_columns(format_csv(points, options), "roundtrip.csv");
    expect_same(back.points, points, kRoundTrip);
    EXPECT_EQ(back.body, Body::wheel);
    EXPECT_EQ(back.side, Side::left);
    EXPECT_EQ(back.lines.front(), 7);  // after five comment lines and the header
  }
}

TEST(ColumnsFormat, SameProfileInMillimetresAndMetresGivesTheSamePoints) {
  const PointList points = rail_60e1_points();
  const RawProfile mm = parse_columns(plain_text(points, 1e3, " "), "mm.txt");
  const RawProfile m = parse_columns(plain_text(points, 1.0, " "), "m.txt");
  // Detected from the magnitudes: the lateral extent is 74.3 (mm) or 0.0743 (m).
  expect_same(mm.points, m.points, 1e-15);
  expect_same(m.points, points, 1e-15);
  // An explicit unit overrides the detection; a unit in the header is used when present.
  const RawProfile forced =
      parse_columns(plain_text(points, 1e3, ","), "mm.csv", {.unit = LengthUnit::millimetre});
  expect_same(forced.points, points, 1e-15);
  const RawProfile header =
      parse_columns("y [m], z [m]\n" + plain_text(points, 1.0, ","), "header.csv");
  expect_same(header.points, points, 1e-15);
  EXPECT_THROW(parse_columns("y [mm], z [m]\n1,2\n3,4\n", "mixed.csv"), InputError);
}

TEST(ColumnsFormat, FindsTheColumnOrder) {
  const PointList points = s1002_points();
  // A header naming z first.
  const RawProfile named =
      parse_columns("z_mm;y_mm\n" + plain_text(points, 1e3, ";", true), "zy.csv");
  expect_same(named.points, points, 1e-15);
  // MiniProf-style names: x lateral, y vertical.
  const RawProfile xy = parse_columns("X Y\n" + plain_text(points, 1e3, " "), "xy.txt");
  expect_same(xy.points, points, 1e-15);
  // No header, z first: the second column spans 130 mm against 38 mm, so it is y.
  const RawProfile spans = parse_columns(plain_text(points, 1e3, "\t", true), "zy.txt");
  expect_same(spans.points, points, 1e-15);
  // Or say so.
  const RawProfile told =
      parse_columns(plain_text(points, 1e3, " ", true), "zy.txt", {.columns = ColumnOrder::z_y});
  expect_same(told.points, points, 1e-15);
}

TEST(ColumnsFormat, ReadsDecimalCommasWithSemicolonsAndExtraColumns) {
  const RawProfile raw = parse_columns(
      "# spreadsheet export\ny;z;weight\n-12,5;3,25;1\n0;0;1\n10;-0,5;1\n20,25;-1;1\n", "eu.csv");
  ASSERT_EQ(raw.points.size(), 4u);
  EXPECT_NEAR(raw.points[0][0], -0.0125, 1e-18);
  EXPECT_NEAR(raw.points[0][1], 0.00325, 1e-18);
  EXPECT_NEAR(raw.points[3][0], 0.02025, 1e-18);
}

TEST(ColumnsFormat, NamesTheLineOfABadRow) {
  try {
    parse_columns("y,z\n1,2\n3,4\n5,oops\n", "bad.csv");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.csv:4"), std::string::npos) << e.what();
  }
  try {
    parse_columns("1 2\n3 4\n5\n", "short.txt");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("short.txt:3: 1 value"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("truncated line?"), std::string::npos);
  }
  try {
    parse_columns("1 2\n3 4 5\n", "ragged.txt");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ragged.txt:2: 3 values, but line 1 has 2"),
              std::string::npos)
        << e.what();
  }
}

TEST(ColumnsFormat, KeepsNonFiniteValuesForTheValidation) {
  // The reader reads what is there; validate_points reports it with its line.
  const RawProfile raw = parse_columns("1 2\n3 nan\n4 inf\n", "nan.txt");
  ASSERT_EQ(raw.points.size(), 3u);
  EXPECT_TRUE(std::isnan(raw.points[1][1]));
  EXPECT_TRUE(std::isinf(raw.points[2][1]));
  EXPECT_EQ(raw.lines[1], 2);
}

}  // namespace
}  // namespace wheelwear::profiles
