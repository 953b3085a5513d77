// Route files: the reader's refusal of every kind of bad input with the file, section, key and
// fix, its defaults, and the manual's example.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/vehicle/route.hpp"

namespace wheelwear::vehicle {
namespace {

constexpr const char* kHeader = R"([route]
name = "test"
speed_m_s = 30

[[section]]
kind = "tangent"
length_m = 100
)";

struct BadInput {
  const char* name;
  std::string text;                  // appended to kHeader
  std::vector<std::string> message;  // every piece must appear in the error
};

class RouteParseError : public ::testing::TestWithParam<BadInput> {};

TEST_P(RouteParseError, NamesTheFileSectionKeyAndFix) {
  const BadInput& c = GetParam();
  try {
    parse_route(std::string(kHeader) + c.text, "bad.toml");
    ADD_FAILURE() << c.name << ": no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    std::printf("%s\n", message.c_str());
    EXPECT_EQ(message.rfind("bad.toml line ", 0), 0u) << message;
    for (const std::string& piece : c.message)
      EXPECT_NE(message.find(piece), std::string::npos)
          << c.name << ": '" << piece << "' not in: " << message;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Route, RouteParseError,
    ::testing::Values(
        BadInput{"unknown_key",
                 "\n[[section]]\nkind = \"tangent\"\nlength_m = 5\nlength_km = 1\n",
                 {"line 12", "section[2].length_km", "unknown key", "did you mean 'length_m'"}},
        BadInput{"alias_friction_top",
                 "\n[[section]]\nkind = \"tangent\"\nlength_m = 5\nfriction_top = 0.2\n",
                 {"section[2].friction_top", "'friction'"}},
        BadInput{"missing_length",
                 "\n[[section]]\nkind = \"tangent\"\n",
                 {"line 9", "section 2", "length_m is missing"}},
        BadInput{"negative_length",
                 "\n[[section]]\nkind = \"tangent\"\nlength_m = -5\n",
                 {"line 9", "section 2", "length_m = -5", "> 0"}},
        BadInput{"cant_on_tangent",
                 "\n[[section]]\nkind = \"tangent\"\nlength_m = 5\ncant_m = 0.05\n",
                 {"section 2", "cant_m = 0.05", "tangent track has no cant", "kind = \"curve\""}},
        BadInput{"nan",
                 "\n[[section]]\nkind = \"tangent\"\nlength_m = nan\n",
                 {"line 11", "section[2].length_m = nan", "finite"}},
        BadInput{"friction_above_one",
                 "\n[[section]]\nkind = \"tangent\"\nlength_m = 5\nfriction = 1.2\n",
                 {"section 2", "friction = 1.2", "(0, 1]"}},
        BadInput{"transition_not_joining",
                 "\n[[section]]\nkind = \"transition\"\nlength_m = 50\nradius_m = 1200\n"
                 "cant_m = 0.1\n\n[[section]]\nkind = \"curve\"\nlength_m = 100\n"
                 "radius_m = 1000\ncant_m = 0.1\nname = \"R1000\"\n",
                 {"line 15", "section 3 (\"R1000\")", "the transition before it (section 2)",
                  "ends at radius 1200 m", "give it radius_m = 1000"}},
        BadInput{"transition_into_tangent_with_cant",
                 "\n[[section]]\nkind = \"transition\"\nlength_m = 50\nradius_m = 800\n"
                 "cant_m = 0.1\n\n[[section]]\nkind = \"tangent\"\nlength_m = 100\n",
                 {"section 3", "the transition before it (section 2)", "give it radius_m = 0"}},
        BadInput{"transition_changes_hand",
                 "\n[[section]]\nkind = \"curve\"\nlength_m = 50\nradius_m = 800\n\n"
                 "[[section]]\nkind = \"transition\"\nlength_m = 50\nradius_m = -800\n",
                 {"section 3", "keeps the curve's hand", "radius_m = 0"}},
        BadInput{"cant_jump",
                 "\n[[section]]\nkind = \"curve\"\nlength_m = 50\nradius_m = 800\ncant_m = 0.1\n",
                 {"section 2", "the cant jumps from 0 m", "kind = \"transition\""}},
        BadInput{"reverse_curve_with_cant",
                 "\n[[section]]\nkind = \"transition\"\nlength_m = 50\nradius_m = 800\n"
                 "cant_m = 0.1\n\n[[section]]\nkind = \"curve\"\nlength_m = 50\n"
                 "radius_m = 800\ncant_m = 0.1\n\n[[section]]\nkind = \"curve\"\n"
                 "length_m = 50\nradius_m = -800\ncant_m = 0.1\n",
                 {"line 21", "section 4", "the cant jumps from 0.1 m", "on the other rail"}},
        BadInput{"radius_too_small",
                 "\n[[section]]\nkind = \"curve\"\nlength_m = 50\nradius_m = 50\n",
                 {"section 2", "radius_m = 50", "at least 100 m"}},
        BadInput{"curve_without_radius",
                 "\n[[section]]\nkind = \"curve\"\nlength_m = 50\n",
                 {"section 2", "radius_m is missing"}},
        BadInput{"unknown_kind",
                 "\n[[section]]\nkind = \"spiral\"\nlength_m = 50\n",
                 {"section[2].kind = \"spiral\"", "\"tangent\", \"transition\" or \"curve\""}},
        BadInput{
            "missing_kind", "\n[[section]]\nlength_m = 50\n", {"section 2", "kind is missing"}},
        BadInput{"speed_zero",
                 "\n[[section]]\nkind = \"tangent\"\nlength_m = 5\nspeed_m_s = 0\n",
                 {"section 2", "speed_m_s = 0", "(0, 100] m/s"}},
        BadInput{"length_as_text",
                 "\n[[section]]\nkind = \"tangent\"\nlength_m = \"5\"\n",
                 {"section[2].length_m", "expected a number"}},
        BadInput{"single_table",
                 "\n[section]\nkind = \"tangent\"\n",
                 {"line 9"}},  // TOML: [section] redefines the array of tables
        BadInput{"unknown_top_level",
                 "\n[track]\ngauge_m = 1.435\n",
                 {"line 9", "track", "unknown key", "allowed here: route, section"}}),
    [](const ::testing::TestParamInfo<BadInput>& param_info) {
      return std::string(param_info.param.name);
    });

TEST(Route, ParseRefusesRouteLevelProblems) {
  const auto message = [](const std::string& text) {
    try {
      parse_route(text, "r.toml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // A transition first: it has no section before it to start from.
  EXPECT_NE(message("[[section]]\nkind = \"transition\"\nlength_m = 5\nradius_m = 500\n"
                    "speed_m_s = 10\n")
                .find("first section"),
            std::string::npos);
  // No speed anywhere.
  EXPECT_NE(message("[[section]]\nkind = \"tangent\"\nlength_m = 5\n").find("speed_m_s is missing"),
            std::string::npos);
  // No sections.
  EXPECT_NE(message("[route]\nname = \"x\"\n").find("no [[section]]"), std::string::npos);
  // A route default out of range names the [route] key.
  EXPECT_NE(message("[route]\nfriction = 0\n[[section]]\nkind = \"tangent\"\nlength_m = 5\n"
                    "speed_m_s = 10\n")
                .find("r.toml line 2: route.friction = 0"),
            std::string::npos);
  // TOML syntax.
  EXPECT_NE(message("[[section]]\nkind = \n").find("r.toml line 2"), std::string::npos);
}

TEST(Route, ParseFillsDefaults) {
  const Route r = parse_route(R"([route]
name = "defaults"
speed_m_s = 30
friction = 0.25

[[section]]
kind = "tangent"
length_m = 100

[[section]]
kind = "curve"
length_m = 100
radius_m = -800
speed_m_s = 20
friction = 0.4
friction_flange = 0.1
traction_N = -2e4
name = "braking curve"
)",
                              "defaults.toml");
  ASSERT_EQ(r.sections.size(), 2u);
  EXPECT_EQ(r.name, "defaults");
  const RouteSection& t = r.sections[0];
  EXPECT_EQ(t.speed_m_s, 30.0);        // [route]
  EXPECT_EQ(t.friction_top, 0.25);     // [route]
  EXPECT_EQ(t.friction_flange, 0.25);  // the section's top friction
  EXPECT_EQ(t.traction_N, 0.0);
  EXPECT_EQ(t.cant_m, 0.0);
  const RouteSection& c = r.sections[1];
  EXPECT_EQ(c.radius_m, -800.0);
  EXPECT_EQ(c.speed_m_s, 20.0);
  EXPECT_EQ(c.friction_top, 0.4);
  EXPECT_EQ(c.friction_flange, 0.1);
  EXPECT_EQ(c.traction_N, -2e4);
  EXPECT_EQ(c.name, "braking curve");
  // A curve reached without a transition: allowed where the cant does not jump.
  EXPECT_EQ(track_at(r, 100.0).curvature_1_m, -1.0 / 800.0);
}

TEST(Route, ReadRouteNamesTheFile) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "wheelwear_route_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "bad_route.toml";
  {
    std::ofstream out(file);
    out << kHeader << "\n[[section]]\nkind = \"tangent\"\nlength_m = -1\n";
  }
  try {
    read_route(file);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + " line 9: section 2"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
  EXPECT_THROW(read_route(dir / "missing.toml"), InputError);
}

// The default route keeps the rules its file states (data/routes/default.toml).
TEST(Route, ManualExampleParses) {
  std::ifstream in(std::filesystem::path(WHEELWEAR_TEST_DATA) / ".." / ".." / "docs" / "routes.md");
  ASSERT_TRUE(in) << "docs/routes.md";
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t open = doc.find("```toml\n");
  ASSERT_NE(open, std::string::npos);
  const std::size_t close = doc.find("```", open + 8);
  ASSERT_NE(close, std::string::npos);
  const Route r = parse_route(doc.substr(open + 8, close - open - 8), "docs/routes.md example");
  EXPECT_EQ(r.sections.size(), 5u);
  EXPECT_TRUE(r.validate().empty());
  EXPECT_EQ(r.sections[2].traction_N, -15e3);
  EXPECT_EQ(r.sections[2].friction_flange, 0.12);
  EXPECT_EQ(r.sections[0].friction_flange, 0.35);  // the section's own top friction
}

}  // namespace
}  // namespace wheelwear::vehicle
