// A table of bad profile files, each made from a good one with one defect, and the specific error
// each must produce through the whole loader.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <sstream>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/columns_format.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace wheelwear::profiles {
namespace {

using testing::contact_wheel_file;
using testing::measured_rail_file;
using testing::read_text;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += line + "\n";
  return out;
}

std::string rail_csv(LengthUnit unit = LengthUnit::millimetre) {
  CsvWriteOptions options;
  options.unit = unit;
  return format_csv(rail_60e1_points({.point_spacing = 0.5e-3}), options);
}

// The S1002 points with a small loop (radius 0.5 mm, 12 points 30 deg apart) inserted on the
// tread at y = 0: the path comes back across itself without any sharp turn or gap.
std::string wheel_with_loop() {
  PointList points = s1002_points();
  const auto at =
      std::find_if(points.begin(), points.end(), [](const Point& p) { return p[0] >= 0.0; });
  const Point p = *at;
  const double r = 0.5e-3;
  const Point centre = p - Point(0.0, r);
  PointList loop;
  for (int k = 1; k <= 11; ++k) {
    const double a = k * std::acos(-1.0) / 6.0;
    loop.push_back(centre + r * Point(std::sin(a), std::cos(a)));
  }
  points.insert(at + 1, loop.begin(), loop.end());
  return format_csv(points, {});
}

struct BadFile {
  std::string name;                      // test name
  std::string file;                      // file name (the extension picks the format)
  std::function<std::string()> content;  // how the file is made
  std::optional<Body> body;              // what the caller says it is
  LengthUnit unit;                       // unit the caller asks for
  std::string expected;                  // part of the message that names the problem
};

std::vector<BadFile> bad_files() {
  return {
      {"Empty", "empty.csv", [] { return std::string(); }, Body::rail, LengthUnit::automatic,
       "empty.csv: the file is empty"},
      {"OneLine", "one.csv", [] { return std::string("-12.5 3.25\n"); }, Body::rail,
       LengthUnit::automatic, "one.csv: only 1 profile point; at least 10"},
      {"NaN", "nan.csv",
       [] {
         auto lines = lines_of(rail_csv());
         lines[19] = "-35.5,nan";  // line 20
         return join(lines);
       },
       Body::rail, LengthUnit::automatic, "nan.csv:20: z = nan: not a finite number"},
      {"Infinity", "inf.csv",
       [] {
         auto lines = lines_of(rail_csv());
         lines[29] = "1e999,2";  // line 30
         return join(lines);
       },
       Body::rail, LengthUnit::automatic, "inf.csv:30: y = inf: not a finite number"},
      {"BinaryGarbage", "garbage.csv",
       [] {
         std::mt19937 random(42);
         std::string bytes(2000, '\0');
         for (char& c : bytes) c = static_cast<char>(random() & 0xff);
         return bytes;
       },
       Body::wheel, LengthUnit::automatic, "garbage.csv: binary data at byte"},
      {"ReversedOrder", "reversed.csv",
       [] {
         // The second half listed backwards: the points run to the field side, jump back.
         auto lines = lines_of(rail_csv());
         std::reverse(lines.begin() + static_cast<std::ptrdiff_t>(lines.size() / 2), lines.end());
         return join(lines);
       },
       Body::rail, LengthUnit::automatic, "points out of order"},
      {"SelfIntersecting", "loop.csv", wheel_with_loop, Body::wheel, LengthUnit::automatic,
       "loop.csv: the profile crosses itself"},
      {"TruncatedSimpack", "cut.prw",
       [] {
         auto lines = lines_of(read_text(contact_wheel_file()));
         lines.resize(250);
         return join(lines);
       },
       Body::wheel, LengthUnit::automatic,
       "cut.prw:250: the file ends inside the point block (point.end missing): truncated?"},
      {"TruncatedMiniprof", "cut.ban",
       [] {
         auto lines = lines_of(read_text(measured_rail_file()));
         lines.resize(lines.size() - 40);  // the empty last line and 39 points
         return join(lines);
       },
       Body::rail, LengthUnit::automatic, "XYPoints=147 but 108 points were read"},
      {"TruncatedLine", "cut.csv",
       [] {
         std::string text = rail_csv();
         text.resize(text.rfind(','));  // the last line loses its second number
         return text;
       },
       Body::rail, LengthUnit::automatic, "1 value where at least 2 columns"},
      {"MillimetresReadAsMetres", "mm.csv", [] { return rail_csv(); }, Body::rail,
       LengthUnit::metre, "1000 times too large (millimetres read as metres?)"},
      {"MetresReadAsMillimetres", "m.csv", [] { return rail_csv(LengthUnit::metre); }, Body::rail,
       LengthUnit::millimetre, "1000 times too small (metres read as millimetres?)"},
      {"Gap", "gap.csv",
       [] {
         auto lines = lines_of(rail_csv());
         lines.erase(lines.begin() + 100, lines.begin() + 140);  // 20 mm of points
         return join(lines);
       },
       Body::rail, LengthUnit::automatic, "gap.csv: gap of 19.75"},
      {"TextInPointBlock", "text.prw",
       [] {
         auto lines = lines_of(read_text(contact_wheel_file()));
         lines[99] = "   1.0   two";  // line 100
         return join(lines);
       },
       Body::wheel, LengthUnit::automatic, "text.prw:100: \"1.0   two\" is not a row of numbers"},
      {"UnknownBody", "what.csv", [] { return rail_csv(); }, std::nullopt, LengthUnit::automatic,
       "what.csv: cannot tell whether this is a wheel or a rail profile"},
  };
}

class BadFileTest : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadFileTest, GivesItsSpecificError) {
  const BadFile& bad = GetParam();
  const auto dir = testing::scratch_dir();
  const auto path = dir / bad.file;
  testing::write_text(path, bad.content());
  LoadOptions options;
  options.read.body = bad.body;
  options.read.unit = bad.unit;
  try {
    load_profile(path, options);
    FAIL() << bad.name << ": accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(bad.expected), std::string::npos)
        << bad.name << ": expected \"" << bad.expected << "\" in\n  " << message;
  }
}

INSTANTIATE_TEST_SUITE_P(Profiles, BadFileTest, ::testing::ValuesIn(bad_files()),
                         [](const auto& param_info) { return param_info.param.name; });

TEST(BadFiles, MissingFile) {
  try {
    load_profile(testing::scratch_dir() / "absent.prr");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("absent.prr: no such file"), std::string::npos);
  }
}

}  // namespace
}  // namespace wheelwear::profiles
