// Tests of the SIMPACK/CONTACT reader and writer: CONTACT's files, every header flag, round trip.

#include "wheelwear/profiles/simpack_format.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"

namespace wheelwear::profiles {
namespace {

using testing::contact_rail_file;
using testing::contact_wheel_file;

std::string simpack(const std::string& flags, const std::string& rows) {
  return "header.begin\n  type = 0\nheader.end\nspline.begin\n" + flags + "  point.begin\n" + rows +
         "  point.end\nspline.end\n";
}

TEST(SimpackFormat, ReadsContactsWheelInItsFrame) {
  const RawProfile raw = read_profile_file(contact_wheel_file());
  EXPECT_EQ(raw.format, "simpack");
  EXPECT_EQ(raw.body, Body::wheel);
  ASSERT_EQ(raw.points.size(), 399u);  // the first row, at line 43, is commented out
  // File rows run from y = 69.6 to -60 mm; mirror.y and inversion make it 60 ... -69.6 mm.
  EXPECT_NEAR(raw.points.front()[0], 0.060, 1e-12);
  EXPECT_EQ(raw.lines.front(), 442);
  EXPECT_NEAR(raw.points.back()[0], -0.069612628, 1e-12);
  EXPECT_NEAR(raw.points.back()[1], 0.013485642, 1e-12);
  EXPECT_EQ(raw.lines.back(), 44);
  EXPECT_EQ(raw.header_value("spline.mirror.y"), "1");
}

TEST(SimpackFormat, ReadsContactsRail) {
  const RawProfile raw = read_profile_file(contact_rail_file());
  EXPECT_EQ(raw.body, Body::rail);
  ASSERT_EQ(raw.points.size(), 495u);
  EXPECT_NEAR(raw.points.front()[0], -0.043704898, 1e-12);
  EXPECT_NEAR(raw.points.back()[1], 0.036653225, 1e-12);
}

TEST(SimpackFormat, AppliesEveryProcessingKeyInSimpacksOrder) {
  const std::string rows = "  1 0\n  1.00001 5\n  2 1\n  3 2\n  4 9\n";
  // Only the dropped point and the unit.
  const RawProfile plain =
      parse_simpack(simpack("  point.dist.min = 0.001\n  units.len.f = 1\n", rows), "a.prr");
  ASSERT_EQ(plain.points.size(), 4u);  // 1.00001 is within 0.001 of 1 in y
  EXPECT_EQ(plain.points[1], Point(2, 1));
  // Shift, then rotate by 90 deg (given in degrees), then mirror z, then invert, then mm -> m.
  const RawProfile moved = parse_simpack(
      simpack("  shift.y = 1\n  shift.z = -1\n  rotate = 90\n  units.ang.f = 57.295779513082323\n"
              "  mirror.z = 1\n  inversion = 1\n  units.len.f = 1000\n",
              rows),
      "b.prr");
  ASSERT_EQ(moved.points.size(), 5u);
  // (1, 0) -> (2, -1) -> rotated (1, 2) -> mirrored z (1, -2) -> last after inversion, in m.
  EXPECT_NEAR(moved.points.back()[0], 1e-3, 1e-15);
  EXPECT_NEAR(moved.points.back()[1], -2e-3, 1e-15);
  EXPECT_EQ(moved.lines.back(), 13);  // the first row, after 7 key lines and point.begin
  // Bounds: y outside [1.5, 3.5] dropped, z clipped to [0, 1.5].
  const RawProfile bounded = parse_simpack(
      simpack("  bound.y.min = 1.5\n  bound.y.max = 3.5\n  bound.z.min = 0\n  bound.z.max = 1.5\n"
              "  mirror.y = 1\n  units.len.f = 1\n",
              rows),
      "c.prr");
  ASSERT_EQ(bounded.points.size(), 2u);
  EXPECT_EQ(bounded.points[0], Point(-2, 1));
  EXPECT_EQ(bounded.points[1], Point(-3, 1.5));
}

TEST(SimpackFormat, RoundTrips) {
  const PointList points = rail_60e1_points();
  const RawProfile back =
      parse_simpack(format_simpack(points, Body::rail, "60E1 'test' !"), "rt.prr");
  EXPECT_EQ(back.body, Body::rail);
  ASSERT_EQ(back.points.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    ASSERT_NEAR((back.points[i] - points[i]).norm(), 0.0, 1e-16);  // m -> mm -> m: an ulp or two
}

TEST(SimpackFormat, RejectsDamagedFiles) {
  auto message = [](const std::string& text) {
    try {
      parse_simpack(text, "bad.prw");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("header.begin\n type = 1\nheader.end\nspline.begin\n point.begin\n 1 2\n 3 4\n")
                .find("bad.prw:7: the file ends inside the point block"),
            std::string::npos);
  EXPECT_NE(message(simpack("", " 1 2\n x 4\n")).find("bad.prw:7: \"x 4\" is not a row"),
            std::string::npos);
  EXPECT_NE(message(simpack("", " 1\n")).find("1 values where"), std::string::npos);
  EXPECT_NE(message("header.begin\n type = 1\nheader.end\n").find("no point block"),
            std::string::npos);
  EXPECT_NE(message("foo.begin\n").find("unknown section"), std::string::npos);
  EXPECT_NE(message("header.begin\n type = 7\nheader.end\nspline.begin\n point.begin\n 1 2\n"
                    " point.end\nspline.end\n")
                .find("must be 0 (rail) or 1 (wheel)"),
            std::string::npos);
}

}  // namespace
}  // namespace wheelwear::profiles
