// Header values of profile files: the wheel's diameter at the taping line and the taping line's
// distance from the internal face (RawProfile::wheel_diameter, taping_line_distance). The keys
// are MiniProf's DiameterTaperline and WheelDiameterTaperline (docs/profiles.md says why); the
// references are the values the files write, in mm.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "test_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/miniprof_format.hpp"
#include "wheelwear/profiles/profile_io.hpp"
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/profiles/wheel_parameters.hpp"

namespace wheelwear::profiles {
namespace {

// A value in mm read as m differs from value * 1e-3 by the rounding of that product only.
constexpr double kConversion = 1e-15;

using testing::refusal;

bool has_note(const RawProfile& raw, const std::string& text) {
  return std::any_of(raw.notes.begin(), raw.notes.end(),
                     [&](const std::string& note) { return note == text; });
}

// A MiniProf key=value wheel file with `header` lines and a few points.
std::string windows_whl(const std::string& header) {
  return "ProgramName=MiniProf for Windows\n" + header + "ColumnDef=X,Y\n\n0 0\n0 5\n5 20\n70 0\n";
}

TEST(HeaderValues, AMiniProfForWindowsExportStatesDiameterAndTapingLine) {
  // s1002_miniprof_windows.whl: DiameterTaperline=920.0000 on line 13, WheelDiameterTaperline=
  // 70.0000 on line 11, as MiniProf for Windows writes them.
  const auto path = testing::data_path("profiles/s1002_miniprof_windows.whl");
  const RawProfile raw = read_profile_file(path);
  ASSERT_TRUE(raw.wheel_diameter && raw.taping_line_distance);
  EXPECT_NEAR(*raw.wheel_diameter, 0.920, kConversion);
  EXPECT_NEAR(*raw.taping_line_distance, 0.070, kConversion);
  EXPECT_TRUE(has_note(raw,
                       "line 13: DiameterTaperline=920.0000: wheel diameter at the taping "
                       "line 0.92 m"));
  EXPECT_TRUE(has_note(raw,
                       "line 11: WheelDiameterTaperline=70.0000: taping line distance from "
                       "the internal face 0.07 m"));
  // The file is S1002 with X from the internal face: it loads as such (origin by the rule), with
  // the nominal Sh and Sd its header states, 28 and 32.5 mm. Bound 1e-6 m: its 4 decimals round
  // by 5e-8 m, and the fit's error at curvature jumps grows with the spacing squared, 16 times
  // curve.hpp's 5e-8 m for 1 mm spacing instead of 0.25 mm.
  LoadOptions options;
  options.origin = WheelOrigin::automatic;
  const LoadedProfile wheel = load_profile(path, options);
  EXPECT_EQ(wheel.origin.origin, WheelOrigin::internal_face);
  EXPECT_EQ(wheel.points.wheel_diameter, raw.wheel_diameter);  // carried to the loader's record
  const WheelParameters en15313 = wheel_parameters(wheel.profile);
  EXPECT_NEAR(en15313.Sh, 0.028, 1e-6);
  EXPECT_NEAR(en15313.Sd, 0.0325, 1e-6);
  EXPECT_NEAR(en15313.running_circle[0], 0.0, 1e-6);
  std::printf(
      "s1002_miniprof_windows.whl: diameter %.4f m, taping line %.4f m, Sh %.6f Sd %.6f mm\n",
      *raw.wheel_diameter, *raw.taping_line_distance, en15313.Sh * 1e3, en15313.Sd * 1e3);
}

TEST(HeaderValues, KeysAreReadInEitherLayoutQuotedAndInAnyCase) {
  struct Case {
    std::string text;
    double diameter;  // [m], 0: not stated
    double distance;  // [m], 0: not stated
  };
  const Case cases[] = {
      // The older layout with a key line among its free header lines.
      {"#MINIWHEELPROF\nw\nMINIPROF 2020\nDiameterTaperline=850.5\n\n0 0\n0 5\n5 20\n70 0\n",
       0.8505, 0.0},
      {windows_whl("\"WheelDiameterTaperline=72.5\"\n"), 0.0, 0.0725},
      {windows_whl("diametertaperline=1000\nWHEELDIAMETERTAPERLINE=68\n"), 1.0, 0.068},
      {windows_whl("DiameterTaperline=\nWheelDiameterTaperline=\n"), 0.0, 0.0},  // empty: unknown
      {windows_whl("DiameterTaperline=900\nDiameterTaperline=910\n"), 0.910, 0.0},  // last wins
  };
  std::size_t compared = 0;
  for (const Case& c : cases) {
    const RawProfile raw = parse_miniprof(c.text, "w.whl", ".whl");
    EXPECT_EQ(raw.wheel_diameter.has_value(), c.diameter > 0.0) << c.text;
    EXPECT_EQ(raw.taping_line_distance.has_value(), c.distance > 0.0) << c.text;
    EXPECT_NEAR(raw.wheel_diameter.value_or(0.0), c.diameter, kConversion) << c.text;
    EXPECT_NEAR(raw.taping_line_distance.value_or(0.0), c.distance, kConversion) << c.text;
    compared += 2;
  }
  EXPECT_EQ(compared, 10u);
}

TEST(HeaderValues, NonsenseIsRefusedNamingFileLineAndKey) {
  const std::pair<std::string, std::string> cases[] = {
      {"DiameterTaperline=0.92\n",  // metres where MiniProf writes mm
       "w.whl:2: DiameterTaperline=0.92 mm: the wheel diameter at the taping line must lie in "
       "200 ... 2500 mm (railway wheels measure about 0.3 ... 1.3 m; a value outside is a wrong "
       "unit or key)"},
      {"WheelDiameterTaperline=920\n",  // a diameter under the taping line's key
       "w.whl:2: WheelDiameterTaperline=920 mm: the taping line distance from the internal face "
       "must lie in 30 ... 110 mm (EN 13715 puts the taping line 70 mm from the internal face; "
       "the range is that of LoadOptions::taping_line_distance)"},
      {"DiameterTaperline=920 mm\n",
       "w.whl:2: DiameterTaperline=920 mm: the wheel diameter at the taping line must be a number "
       "in mm"},
      {"\"WheelDiameterTaperline=nan\"\n",
       "w.whl:2: WheelDiameterTaperline=nan: the taping line distance from the internal face must "
       "be a number in mm"},
  };
  for (const auto& [header, message] : cases)
    EXPECT_EQ(refusal([&] { parse_miniprof(windows_whl(header), "w.whl", ".whl"); }), message);
}

TEST(HeaderValues, NoOtherKeyOrFormatStatesThem) {
  // Spellings no public MiniProf file shows are kept as header entries only: "Diameter" alone
  // could as well be the flange's (DiameterFlange), and a guessed key read wrongly misplaces the
  // taping line without a symptom.
  const RawProfile guessed = parse_miniprof(
      windows_whl("Diameter=920\nWheelDiameter=920\nTapeLineDiameter=920\nTapingLine=70\n"
                  "FlangeBackToTapingLine=70\nDiameterFlange=976\n"),
      "w.whl", ".whl");
  EXPECT_FALSE(guessed.wheel_diameter);
  EXPECT_FALSE(guessed.taping_line_distance);
  EXPECT_EQ(guessed.header_value("WheelDiameter"), "920");
  // The measured wheel (older layout) has no such keys; SIMPACK and columns files have none.
  for (const auto& path : {testing::measured_wheel_file(), testing::contact_wheel_file(),
                           testing::data_path("profiles/en15302_rail_a_table_i6.csv")}) {
    const RawProfile raw = read_profile_file(path);
    EXPECT_FALSE(raw.wheel_diameter) << path;
    EXPECT_FALSE(raw.taping_line_distance) << path;
  }
}

}  // namespace
}  // namespace wheelwear::profiles
