// Tests of the MiniProf reader and writer: the two measured files, round trips, damaged files.

#include "wheelwear/profiles/miniprof_format.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/orientation.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

using testing::measured_rail_file;
using testing::measured_wheel_file;
using testing::read_text;

TEST(MiniprofFormat, ReadsTheMeasuredWheel) {
  const RawProfile raw = read_profile_file(measured_wheel_file());
  EXPECT_EQ(raw.format, "miniprof");
  EXPECT_EQ(raw.body, Body::wheel);
  ASSERT_EQ(raw.points.size(), 645u);
  EXPECT_EQ(raw.lines.front(), 11);  // after the empty line 10
  EXPECT_NEAR(raw.points.front()[0], -0.0986e-3, 1e-12);
  EXPECT_NEAR(raw.points.front()[1], -22.0603e-3, 1e-12);
  EXPECT_EQ(raw.header_value("Sd"), "32.58");
  EXPECT_EQ(raw.header_value("Sh"), "37.11");
  EXPECT_EQ(raw.header_value("qR"), "14.71");
}

TEST(MiniprofFormat, ReadsTheMeasuredRailByItsColumnDef) {
  const RawProfile raw = read_profile_file(measured_rail_file());
  EXPECT_EQ(raw.body, Body::rail);
  ASSERT_EQ(raw.points.size(), 147u);                   // XYPoints=147
  EXPECT_EQ(raw.header_value("ColumnDef"), "X,Y,A,C");  // the last of the two ColumnDef lines
  EXPECT_EQ(raw.lines.front(), 53);
  EXPECT_NEAR(raw.points.front()[0], -11.73e-3, 1e-12);
  EXPECT_NEAR(raw.points.front()[1], -1.52e-3, 1e-12);
}

TEST(MiniprofFormat, RoundTripsWheelsAndRails) {
  for (Body body : {Body::wheel, Body::rail}) {
    const PointList points = body == Body::wheel ? s1002_points() : rail_60e1_points();
    RawProfile back =
        parse_miniprof(format_miniprof(points, body), "rt", body == Body::wheel ? ".whl" : ".ban");
    EXPECT_EQ(back.body, body);
    // Rails are written with MiniProf's rail axes (X to the gauge face, Y up): orientation
    // brings them back.
    const OrientationReport report = orient(back, body);
    EXPECT_EQ(report.mirrored_y, body == Body::rail);
    EXPECT_EQ(report.mirrored_z, body == Body::rail);
    ASSERT_EQ(back.points.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      ASSERT_NEAR((back.points[i] - points[i]).norm(), 0.0, 1e-16) << i;  // m -> mm -> m
  }
}

TEST(MiniprofFormat, RejectsDamagedFiles) {
  const std::string ban = read_text(measured_rail_file());
  // Cut after 100 of the 147 points: XYPoints no longer matches.
  std::size_t at = 0;
  for (int line = 0; line < 52 + 100; ++line) at = ban.find('\n', at) + 1;
  try {
    parse_miniprof(ban.substr(0, at), "cut.ban", ".ban");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("XYPoints=147 but 100 points"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parse_miniprof("ColumnDef=A,C\n\n1 2\n3 4\n", "x.ban", ".ban"), InputError);
  EXPECT_THROW(parse_miniprof("XYPoints=2\n\n1 2\n3 four\n", "x.ban", ".ban"), InputError);
  EXPECT_THROW(parse_miniprof("XYPoints=2\nstray header text\n\n1 2\n3 4\n", "x.ban", ".ban"),
               InputError);
  EXPECT_THROW(parse_miniprof("ColumnDef=A,X,Y\n\n1 2\n3 4\n", "x.ban", ".ban"), InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
