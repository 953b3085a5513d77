// The plausibility table (core/plausibility.hpp): every row refused and warned at its limits,
// docs/cli.md listing the same rows, the load collective refusing by it with the line, and the
// commands creep, contact and wear refusing and warning through it.

#include "wheelwear/core/plausibility.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear {

namespace core {
// Names a row in test listings (the default prints the pointer, different in every run).
void PrintTo(const PlausibilityLimit* limit, std::ostream* os) {
  *os << limit->quantity;
}
}  // namespace core

namespace {

namespace fs = std::filesystem;
using core::PlausibilityLimit;
using testing::run_wheelwear;

constexpr double kInf = std::numeric_limits<double>::infinity();

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The message of the InputError `value` of `input` raises, or "" when it is accepted.
std::string refusal(const PlausibilityLimit& row, double value, const std::string& input = "in") {
  try {
    core::require_plausible(row, input, value);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

class PlausibilityRow : public ::testing::TestWithParam<const PlausibilityLimit*> {};

// The largest value accepted and the smallest refused: the limit itself is refused for rows
// marked refuse_at_limit (|yaw| >= 0.1 rad), accepted for the others (a > 0.1 m).
TEST_P(PlausibilityRow, RefusesJustOutsideTheLimitNamingInputValueLimitAndFix) {
  const PlausibilityLimit& row = *GetParam();
  if (row.refuse == kInf) {  // computed, never refused
    EXPECT_EQ(refusal(row, 1e300), "") << row.quantity;
    return;
  }
  const double inside = row.refuse_at_limit ? std::nextafter(row.refuse, 0.0) : row.refuse;
  const double outside = row.refuse_at_limit ? row.refuse : std::nextafter(row.refuse, kInf);
  for (const double sign : {1.0, -1.0}) {
    if (sign < 0 && row.positive) continue;  // negative values are refused as such, below
    EXPECT_EQ(refusal(row, sign * inside), "") << row.quantity << " at " << sign * inside;
    const std::string message = refusal(row, sign * outside, "--flag");
    EXPECT_TRUE(contains(message, "--flag = " + core::limit_text(sign * outside, row.unit)))
        << message;
    EXPECT_TRUE(contains(message, std::string(row.quantity))) << message;
    EXPECT_TRUE(contains(message, core::limit_text(row.refuse, row.unit) + " ")) << message;
    EXPECT_TRUE(contains(
        message, "are impossible: " + std::string(row.refuse_reason) + "; " + std::string(row.fix)))
        << message;
  }
}

TEST_P(PlausibilityRow, WarnsJustAboveTheWarnLimitWithTheReason) {
  const PlausibilityLimit& row = *GetParam();
  if (row.warn == kInf) {  // refused or plausible, nothing between
    EXPECT_FALSE(core::plausibility_warning(row, "x", std::nextafter(row.refuse, 0.0)));
    return;
  }
  EXPECT_FALSE(core::plausibility_warning(row, "x", row.warn).has_value());
  const double above = std::nextafter(row.warn, kInf);
  const auto warning = core::plausibility_warning(row, "--flag", above);
  ASSERT_TRUE(warning.has_value()) << row.quantity;
  EXPECT_EQ(*warning,
            "--flag = " + core::limit_text(above, row.unit) + ": " + std::string(row.quantity) +
                " above " + core::limit_text(row.warn, row.unit) +
                " are implausible: " + std::string(row.warn_reason) + "; " + std::string(row.fix));
  if (!row.positive) {
    EXPECT_TRUE(core::plausibility_warning(row, "x", -above).has_value());
  }
  // A warned value is accepted: the warning limit lies below the refusal.
  EXPECT_LT(row.warn, row.refuse);
  EXPECT_EQ(refusal(row, above), "");
  std::vector<std::string> warnings;
  core::check_plausible(row, "--flag", above, warnings);
  EXPECT_EQ(warnings, std::vector<std::string>{*warning});
}

TEST_P(PlausibilityRow, RefusesWhatIsNotFiniteAndWhatMustBePositive) {
  const PlausibilityLimit& row = *GetParam();
  for (const double bad : {std::nan(""), kInf, -kInf})
    EXPECT_TRUE(contains(refusal(row, bad, "--flag"), "must be a finite number")) << bad;
  if (row.positive) {
    EXPECT_TRUE(
        contains(refusal(row, 0.0, "--flag"), "--flag = " + core::limit_text(0.0, row.unit)));
    EXPECT_TRUE(contains(refusal(row, -1.0), std::string(row.quantity) + " must be positive"));
  } else {
    EXPECT_EQ(refusal(row, 0.0), "");
  }
}

INSTANTIATE_TEST_SUITE_P(EveryRow, PlausibilityRow, ::testing::ValuesIn(core::kPlausibilityLimits),
                         [](const auto& param_info) {
                           std::string name;
                           for (const char c : param_info.param->quantity)
                             if (std::isalpha(static_cast<unsigned char>(c))) name += c;
                           return name;
                         });

// The unit mistakes the table is for, as a user makes them.
TEST(Plausibility, NamesTheLikelyUnitMistake) {
  EXPECT_TRUE(contains(refusal(core::kSemiAxisLimit, 4.25, "--a"),
                       "--a = 4.25 m: contact semi-axes above 0.1 m are impossible"));
  EXPECT_TRUE(contains(refusal(core::kSemiAxisLimit, 4.25), "did you give millimetres?"));
  EXPECT_TRUE(contains(refusal(core::kYawLimit, 1.5, "--yaw"),
                       "--yaw = 1.5 rad: yaw angles of 0.1 rad or more are impossible"));
  EXPECT_TRUE(contains(refusal(core::kWheelLoadLimit, 1e12, "--load"),
                       "--load = 1e12 N: wheel loads above 1e6 N are impossible"));
  EXPECT_TRUE(contains(refusal(core::kSpeedLimit, 300.0), "did you give km/h?"));
  EXPECT_TRUE(contains(refusal(core::kFrictionLimit, 35.0), "did you give per cent?"));
  EXPECT_EQ(core::limit_text(3e-3, "m"), "0.003 m");
  EXPECT_EQ(core::limit_text(2.5e-7, ""), "2.5e-7");
}

// docs/cli.md, "Plausibility limits": one table row per row of the code, in its order, with the
// code's limits (the refusal's comparison, and "≤ 0" where the value must be positive).
TEST(Plausibility, DocumentedTableIsTheCodes) {
  std::ifstream in(std::string(WHEELWEAR_TEST_DATA) + "/../../docs/cli.md");
  ASSERT_TRUE(in) << "docs/cli.md";
  std::string line;
  while (std::getline(in, line) && line != "## Plausibility limits") {
  }
  ASSERT_EQ(line, "## Plausibility limits");
  std::vector<std::vector<std::string>> rows;  // the cells of each table row below the header
  bool header = true;
  while (std::getline(in, line) && !line.starts_with("## ")) {
    if (!line.starts_with("| ")) continue;
    if (header) {  // the header row; the separator row starts with "|-"
      header = false;
      continue;
    }
    std::vector<std::string> cells;
    std::size_t start = 2;
    for (std::size_t bar = line.find(" | ", start); bar != std::string::npos;
         start = bar + 3, bar = line.find(" | ", start))
      cells.push_back(line.substr(start, bar - start));
    rows.push_back(cells);
  }
  ASSERT_EQ(rows.size(), core::kPlausibilityLimits.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PlausibilityLimit& row = *core::kPlausibilityLimits[i];
    ASSERT_GE(rows[i].size(), 4u);
    EXPECT_EQ(rows[i][0], row.quantity);
    EXPECT_EQ(rows[i][2], row.warn == kInf ? "—" : core::limit_text(row.warn, row.unit))
        << row.quantity;
    const std::string refused = row.refuse == kInf ? "—"
                                                   : (row.refuse_at_limit ? "≥ " : "> ") +
                                                         core::limit_text(row.refuse, row.unit) +
                                                         (row.positive ? ", ≤ 0" : "");
    EXPECT_EQ(rows[i][3], refused) << row.quantity;
  }
}

// The load collective refuses yaw, loads, speed and creepages by the table, naming the file and
// line (or the scene line); values inside the limits load.
class CollectivePlausibility : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("wheelwear_plausibility_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // The error of a collective file with one state whose `column` is `value`; "" if it loads.
  std::string collective_error(const std::string& column, const std::string& value) const {
    // The speed is given once: by its own case, or as the state's base.
    const bool speed = column == "speed_m_s";
    std::ofstream(dir_ / "states.csv")
        << "# one state\naxle_load_N," << (speed ? "" : "speed_m_s,") << column << "\n1e5,"
        << (speed ? "" : "20,") << value << "\n";
    try {
      pipeline::parse_scene("[load_collective]\nfile = \"states.csv\"\n", dir_);
    } catch (const InputError& e) {
      return e.what();
    }
    return {};
  }
  fs::path dir_;
};

TEST_F(CollectivePlausibility, RefusesByTheTableWithTheLine) {
  struct Case {
    std::string column, inside, outside, limit;
  };
  for (const Case& c :
       {Case{"yaw_rad", "-0.0999999", "-0.1", "of 0.1 rad or more"},
        Case{"load_left_N", "1e6", "1.000001e6", "above 1e6 N"},
        Case{"load_right_N", "1e6", "1.000001e6", "above 1e6 N"},
        Case{"speed_m_s", "150", "150.001", "above 150 m/s"},
        Case{"vx_left", "-1", "-1.001", "above 1"}, Case{"vy_right", "1", "1.001", "above 1"}}) {
    // Creepages come in threes; loads one wheel at a time (the axle load is set first).
    std::string column = c.column, inside = c.inside, outside = c.outside;
    if (c.column.starts_with("v")) {
      const std::string side = c.column.ends_with("left") ? "left" : "right";
      const std::string other = c.column.starts_with("vx") ? "vy_" + side : "vx_" + side;
      column += "," + other + ",spin_" + side + "_1_m";
      inside += ",0,0";
      outside += ",0,0";
    }
    EXPECT_EQ(collective_error(column, inside), "") << c.column;
    const std::string message = collective_error(column, outside);
    EXPECT_TRUE(contains(message, "states.csv line 3: " + c.column + " = ")) << message;
    EXPECT_TRUE(contains(message, c.limit + " are impossible")) << message;
  }
}

TEST_F(CollectivePlausibility, InlineStatesNameTheSceneLine) {
  try {
    pipeline::parse_scene(
        "[[load_collective.state]]\nyaw_rad = 1.5\naxle_load_N = 1e5\nspeed_m_s = 20\n", dir_);
    ADD_FAILURE() << "a yaw of 1.5 rad was accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(),
                         "scene line 2: load_collective.state: yaw_rad = 1.5 rad: "
                         "yaw angles of 0.1 rad or more are impossible"))
        << e.what();
  }
}

// Through the commands: refused with exit status 2 and the message, nothing on standard output;
// warned with exit status 0, on standard error and in the JSON's warnings.
TEST(PlausibilityCommands, RefuseTheAbsurd) {
  struct Case {
    std::string arguments, message;
  };
  for (const Case& c :
       {Case{"creep --a 4.25 --b 4.25e-3 --N 37830 --json",
             "wheelwear: error: --a = 4.25 m: contact semi-axes above 0.1 m are impossible"},
        Case{"creep --a 4.25e-3 --b 0.2 --N 37830", "--b = 0.2 m"},
        Case{"creep --a 4.25e-3 --b 4.25e-3 --N 2e6", "--N = 2e6 N: wheel loads above 1e6 N"},
        Case{"creep --a 4.25e-3 --b 4.25e-3 --N 37830 --vx 5", "--vx = 5: creepages above 1"},
        Case{"contact --dy 0 --load 55000 --yaw 1.5 --json",
             "wheelwear: error: --yaw = 1.5 rad: yaw angles of 0.1 rad or more are impossible"},
        Case{"contact --dy 0 --load 1e12 --json",
             "wheelwear: error: --load = 1e12 N: wheel loads above 1e6 N are impossible"},
        Case{"contact --dy 0 --load 55000 --mu 35", "--mu = 35: friction coefficients above 1"},
        Case{"wear --dy 0 --load 55000 --V 300", "--V = 300 m/s: speeds above 150 m/s"},
        Case{"wear --dy 0 --load 55000 --yaw -0.1", "--yaw = -0.1 rad"}}) {
    const auto r = run_wheelwear(c.arguments);
    EXPECT_EQ(r.exit_code, 2) << c.arguments << ": " << r.err;
    EXPECT_TRUE(contains(r.err, c.message)) << c.arguments << ": " << r.err;
    EXPECT_EQ(r.out, "") << c.arguments;
  }
}

TEST(PlausibilityCommands, WarnOnStandardErrorAndInTheJson) {
  struct Case {
    std::string arguments, warning;
  };
  const std::string load = "--load = 4e5 N: wheel loads above 3e5 N are implausible";
  for (const Case& c : {Case{"contact --dy 0 --load 4e5 --json", load},
                        Case{"wear --dy 0 --load 4e5 --vx 1e-3 --cells 10 --json", load},
                        Case{"creep --a 0.035 --b 4.25e-3 --N 37830 --vx 1e-3 --json",
                             "--a = 0.035 m: contact semi-axes above 0.03 m are implausible"},
                        Case{"contact --dy 0.004 --load 55000 --E 200e6 --json",
                             "m: wheel/rail approaches above 0.005 m are implausible"},
                        Case{"wear --dy 0 --load 55000 --vx 1e-3 --cells 10 --V 120 --json",
                             "--V = 120 m/s: speeds above 100 m/s are implausible"}}) {
    const auto r = run_wheelwear(c.arguments);
    EXPECT_EQ(r.exit_code, 0) << c.arguments << ": " << r.err;
    EXPECT_TRUE(contains(r.err, "wheelwear: warning: ")) << c.arguments << ": " << r.err;
    EXPECT_TRUE(contains(r.err, c.warning)) << c.arguments << ": " << r.err;
    EXPECT_TRUE(contains(r.out, "\"warnings\": [\"")) << c.arguments << ": " << r.out;
    EXPECT_TRUE(contains(r.out, c.warning)) << c.arguments << ": " << r.out;
  }
  // Plausible inputs: no warning, an empty list.
  const auto quiet = run_wheelwear("contact --dy 0 --load 55000 --json");
  EXPECT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  EXPECT_TRUE(contains(quiet.out, "\"warnings\": []")) << quiet.out;
}

}  // namespace
}  // namespace wheelwear
