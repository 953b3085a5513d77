// Tests of format detection, file round trips through every writer, and atomic writing.

#include "wheelwear/profiles/profile_io.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {

using core::check_text;
using core::format_number;
using core::parse_inclination;
using core::parse_number;
using core::read_text_file;
using core::write_file_atomically;
namespace {

using testing::read_text;
using testing::scratch_dir;
using testing::write_text;

TEST(ProfileIo, DetectsFormatsByExtensionThenContent) {
  EXPECT_EQ(detect_format("a.PRW", ""), FileFormat::simpack);
  EXPECT_EQ(detect_format("a.prr", ""), FileFormat::simpack);
  EXPECT_EQ(detect_format("a.whl", ""), FileFormat::miniprof);
  EXPECT_EQ(detect_format("a.BAN", ""), FileFormat::miniprof);
  EXPECT_EQ(detect_format("a.txt", "! x\nheader.begin\n"), FileFormat::simpack);
  EXPECT_EQ(detect_format("a.dat", "XYPoints=3\n"), FileFormat::miniprof);
  EXPECT_EQ(detect_format("a.csv", "y,z\n1,2\n"), FileFormat::columns);
}

TEST(ProfileIo, EveryWriterRoundTripsThroughTheLoader) {
  // Each format written, read back, oriented, cleaned and fitted gives the profile it came from.
  const auto dir = scratch_dir();
  LoadOptions options;
  options.curve.smoothing_length = 0.0;
  for (Body body : {Body::wheel, Body::rail}) {
    const Profile original = body == Body::wheel ? s1002() : rail_60e1();
    const PointList points = original.knot_points();
    for (const char* ext : {".csv", ".prw", ".prr", ".whl", ".ban", ".txt"}) {
      const auto path = dir / (std::string(to_string(body)) + ext);
      write_profile_file(path, points, body);
      options.read.body = body;
      const LoadedProfile back = load_profile(path, options);
      EXPECT_EQ(back.cleaning.dropped(), 0u) << path;
      EXPECT_FALSE(back.orientation.reversed) << path;
      // The knots are re-interpolated: the same curve to the knot-interpolation error. (Not right
      // at the wheel's flange back, where the tangent is vertical and z(y) ill-conditioned.)
      for (double y = original.y_min() + 0.5e-3; y <= original.y_max(); y += 0.5e-3)
        ASSERT_NEAR(*back.profile.z_at(y), *original.z_at(y), 1e-9) << path << " y = " << y;
    }
  }
}

TEST(ProfileIo, WritesAtomically) {
  const auto dir = scratch_dir();
  const auto path = dir / "out.csv";
  write_text(path, "old content\n");
  write_file_atomically(path, "new content\n");
  EXPECT_EQ(read_text(path), "new content\n");
  // A target that cannot be replaced (a folder) fails and leaves nothing behind.
  std::filesystem::create_directory(dir / "taken");
  EXPECT_THROW(write_file_atomically(dir / "taken", "x"), InputError);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "taken"));
  EXPECT_THROW(write_file_atomically(dir / "missing" / "out.csv", "x"), InputError);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 2u);  // out.csv and the folder: no temporary file left
}

TEST(TextFile, ParsesNumbersStrictly) {
  EXPECT_EQ(parse_number("+1.5e+03"), 1500.0);
  EXPECT_EQ(parse_number("-0.25"), -0.25);
  EXPECT_TRUE(std::isnan(*parse_number("nan")));
  EXPECT_EQ(parse_number("1e999"), std::numeric_limits<double>::infinity());
  EXPECT_FALSE(parse_number(""));
  EXPECT_FALSE(parse_number("1.5x"));
  EXPECT_FALSE(parse_number("--1"));
  EXPECT_FALSE(parse_number("1,5"));
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(*parse_number(format_number(1.0 / 3.0)), 1.0 / 3.0);
}

// One way to give a rail's inclination everywhere: 1:N or a slope, none or 0.
TEST(Inclination, IsOneInNOrASlope) {
  EXPECT_EQ(parse_inclination("1:40", "--incl"), std::atan(1.0 / 40.0));
  EXPECT_EQ(parse_inclination("0.025", "--incl"), std::atan(0.025));  // the same angle
  EXPECT_EQ(parse_inclination("1:20", "--incl"), std::atan(0.05));
  EXPECT_EQ(parse_inclination("-0.025", "--incl"), std::atan(-0.025));
  EXPECT_EQ(parse_inclination("none", "--incl"), 0.0);
  EXPECT_EQ(parse_inclination("0", "--incl"), 0.0);
  int refused = 0;
  for (const char* bad : {"40", "1:0", "1:2", "2:40", "1:", "abc", "0.3", "nan", ""}) {
    try {
      parse_inclination(bad, "--incl");
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--incl"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("1:N"), std::string::npos) << e.what();
      ++refused;
    }
  }
  EXPECT_EQ(refused, 9);
}

TEST(TextFile, RejectsMissingEmptyAndBinaryFiles) {
  const auto dir = scratch_dir();
  EXPECT_THROW(read_text_file(dir / "none.csv"), InputError);
  write_text(dir / "empty.csv", "");
  EXPECT_THROW(read_text_file(dir / "empty.csv"), InputError);
  EXPECT_THROW(check_text(std::string("1 2\n\0\0\0", 7), "nul"), InputError);
  EXPECT_NO_THROW(check_text("y z\r\n1 2\r\n\tcomment\f\n", "ok"));
  EXPECT_THROW(read_text_file(dir), InputError);
}

}  // namespace
}  // namespace wheelwear::profiles
