// The wear laws' CSV tables: round trips, the shipped files, and every malformed input with
// its message.

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/wear/wear_law.hpp"

namespace wheelwear::wear {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The shipped tables live in data/wear, two levels above tests/data.
std::string shipped(const std::string& file) {
  return std::string(WHEELWEAR_TEST_DATA) + "/../../data/wear/" + file;
}

TEST(WearLawCsv, DefaultsRoundTrip) {
  std::stringstream usfd;
  TgammaLaw::usfd().write_csv(usfd);
  const TgammaLaw usfd_read = TgammaLaw::read_csv(usfd, "usfd round trip", 7850.0, "usfd");
  EXPECT_EQ(std::vector<TgammaRegime>(usfd_read.regimes().begin(), usfd_read.regimes().end()),
            usfd_regimes());

  std::stringstream kth;
  ArchardLaw::kth().write_csv(kth);
  const ArchardLaw kth_read = ArchardLaw::read_csv(kth, "kth round trip");
  EXPECT_EQ(std::vector<ArchardRegime>(kth_read.regimes().begin(), kth_read.regimes().end()),
            kth_wear_map());
}

// Numbers without a short decimal form come back bit for bit (shortest round-trip output).
TEST(WearLawCsv, AwkwardNumbersRoundTripExactly) {
  const std::vector<TgammaRegime> regimes{{"a", 0.0, 1.0 / 3.0, 1e-300, 0.0, 0.0},
                                          {"b", 1.0 / 3.0, kInf, 2.0 / 7.0, 1.0 / 9.0, 0.1}};
  std::stringstream text;
  TgammaLaw(regimes).write_csv(text);
  const TgammaLaw read = TgammaLaw::read_csv(text, "awkward");
  EXPECT_EQ(std::vector<TgammaRegime>(read.regimes().begin(), read.regimes().end()), regimes);

  const std::vector<ArchardRegime> map{{"low", 0.0, 0.1 + 0.2, 0.0, kInf, 1.0 / 3.0},
                                       {"high", 0.1 + 0.2, kInf, 0.0, kInf, 5e-324}};
  std::stringstream map_text;
  ArchardLaw(map).write_csv(map_text);
  const ArchardLaw map_read = ArchardLaw::read_csv(map_text, "awkward map");
  EXPECT_EQ(std::vector<ArchardRegime>(map_read.regimes().begin(), map_read.regimes().end()), map);
}

// Both come from the same decimal literals, which parse to the same correctly rounded doubles:
// the comparison is exact.
TEST(WearLawCsv, ShippedTablesEqualTheBuiltInDefaults) {
  const TgammaLaw usfd = TgammaLaw::load_csv(shipped("usfd.csv"), 7850.0, "usfd");
  EXPECT_EQ(std::vector<TgammaRegime>(usfd.regimes().begin(), usfd.regimes().end()),
            usfd_regimes());
  const ArchardLaw kth = ArchardLaw::load_csv(shipped("archard.csv"), 2.5e9, "archard");
  EXPECT_EQ(std::vector<ArchardRegime>(kth.regimes().begin(), kth.regimes().end()), kth_wear_map());
}

TEST(WearLawCsv, CommentsBlankLinesSpacesAndWindowsLineEndingsAreAccepted) {
  std::istringstream in("# a comment\r\n\r\n" + std::string(kTgammaCsvHeader) +
                        "\r\n  # indented comment\r\nmild , 0 , 10.4 , 5.3 , 0 , 0\r\n\r\n"
                        "severe,10.4,77.2,0,55.0,0\r\ncatastrophic,77.2,inf,61.9,-4778.7,55.0\r\n");
  const TgammaLaw law = TgammaLaw::read_csv(in, "windows.csv");
  EXPECT_EQ(std::vector<TgammaRegime>(law.regimes().begin(), law.regimes().end()), usfd_regimes());
}

TEST(WearLawCsv, MissingFileIsNamed) {
  try {
    TgammaLaw::load_csv("/nonexistent/usfd.csv");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), "/nonexistent/usfd.csv: cannot open the file");
  }
  EXPECT_THROW(ArchardLaw::load_csv("/nonexistent/archard.csv"), InputError);
}

// Regimes given in code are checked as files are, with the regime's index in the message.
TEST(WearLawCsv, RegimesInCodeAreValidatedToo) {
  try {
    TgammaLaw({{"a", 0.0, 10.0, 1.0, 0.0, 0.0}, {"b", 9.0, kInf, 0.0, 10.0, 0.0}}, 7850.0, "mine");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "T gamma law 'mine': regime 2: overlap between regimes: this one starts at 9 "
              "N/mm^2, the one before (regime 1) ends at 10");
  }
  EXPECT_THROW(TgammaLaw(std::vector<TgammaRegime>{}), InputError);
  EXPECT_THROW(ArchardLaw(std::vector<ArchardRegime>{}), InputError);
}

enum class Table { tgamma, archard };

struct BadCsv {
  const char* label;  // test name suffix
  Table table;        // which reader
  std::string text;   // file content
  std::string error;  // the exact message, "bad.csv" being the source
};

std::string tgamma_file(const std::string& rows) {
  return "# comment\n" + std::string(kTgammaCsvHeader) + "\n" + rows;
}
std::string archard_file(const std::string& rows) {
  return std::string(kArchardCsvHeader) + "\n" + rows;
}

const std::string kMild = "mild,0,10.4,5.3,0,0\n";
const std::string kSevere = "severe,10.4,77.2,0,55,0\n";
const std::string kCatastrophic = "catastrophic,77.2,inf,61.9,-4778.7,55\n";
const std::string kSeizure = "seizure,0.8,inf,0,inf,0.035\n";
const std::string kLow = "low,0,0.8,0,0.2,5.5e-4\n";
const std::string kMid = "mid,0,0.8,0.2,0.7,35e-4\n";
const std::string kHigh = "high,0,0.8,0.7,inf,5.5e-4\n";

const std::vector<BadCsv> kBadCsvFiles = {
    {"Empty", Table::tgamma, "",
     "bad.csv: empty file: expected the header '" + std::string(kTgammaCsvHeader) + "'"},
    {"OnlyComments", Table::archard, "# nothing here\n\n",
     "bad.csv: empty file: expected the header '" + std::string(kArchardCsvHeader) + "'"},
    {"BadHeader", Table::tgamma, "regime,lower,upper,slope,intercept,floor\n" + kMild,
     "bad.csv:1: bad header: expected '" + std::string(kTgammaCsvHeader) +
         "', got 'regime,lower,upper,slope,intercept,floor'"},
    {"OtherLawsHeader", Table::archard, tgamma_file(kMild),
     "bad.csv:2: bad header: expected '" + std::string(kArchardCsvHeader) + "', got '" +
         std::string(kTgammaCsvHeader) + "'"},
    {"HeaderOnly", Table::tgamma, tgamma_file(""), "bad.csv: no rows after the header"},
    {"MissingField", Table::tgamma, tgamma_file(kMild + "severe,10.4,77.2,0,55\n"),
     "bad.csv:4: expected 6 comma-separated fields, got 5"},
    {"NotANumber", Table::tgamma, tgamma_file("mild,0,10.4,5.3x,0,0\n"),
     "bad.csv:3: column 'slope_ug_per_m_mm2_per_N_per_mm2': '5.3x' is not a number"},
    {"EmptyNumber", Table::tgamma, tgamma_file("mild,0,,5.3,0,0\n"),
     "bad.csv:3: column 'upper_N_per_mm2': '' is not a number"},
    {"OutOfRange", Table::tgamma, tgamma_file("mild,0,1e999,5.3,0,0\n"),
     "bad.csv:3: column 'upper_N_per_mm2': '1e999' is not a number"},
    {"NaN", Table::tgamma, tgamma_file(kMild + "severe,10.4,77.2,0,nan,0\n"),
     "bad.csv:4: column 'intercept_ug_per_m_mm2': NaN is not a valid value"},
    {"InfiniteLower", Table::tgamma, tgamma_file("mild,inf,10.4,5.3,0,0\n"),
     "bad.csv:3: column 'lower_N_per_mm2': 'inf' must be finite"},
    {"Gap", Table::tgamma, tgamma_file(kMild + "severe,12,77.2,0,55,0\n" + kCatastrophic),
     "bad.csv:4: gap between regimes: this one starts at 12 N/mm^2, the one before (line 3) "
     "ends at 10.4"},
    {"Overlap", Table::tgamma, tgamma_file(kMild + kSevere + "catastrophic,70,inf,61.9,0,55\n"),
     "bad.csv:5: overlap between regimes: this one starts at 70 N/mm^2, the one before (line 4) "
     "ends at 77.2"},
    {"OutOfOrder", Table::tgamma, tgamma_file(kSevere + kMild),
     "bad.csv:3: the first regime must start at 0 N/mm^2, not at 10.4"},
    {"NoLastToInfinity", Table::tgamma, tgamma_file(kMild + kSevere),
     "bad.csv:4: the last regime must end at inf (T gamma / A has no upper limit), not at 77.2 "
     "N/mm^2"},
    {"EmptyRange", Table::tgamma, tgamma_file(kMild + "severe,10.4,10.4,0,55,0\n"),
     "bad.csv:4: empty regime: upper = 10.4 N/mm^2 is not above lower = 10.4"},
    {"NegativeRate", Table::tgamma, tgamma_file("mild,0,10,5,0,0\nfalling,10,inf,-1,60,0\n"),
     "bad.csv:4: negative wear rate: slope*x + intercept = -inf ug/(m mm^2) at x = inf N/mm^2 "
     "(set a positive floor to ask for max(floor, slope*x + intercept))"},
    {"NegativeRateInsideRange", Table::tgamma, tgamma_file("mild,0,10,5,0,0\nb,10,inf,1,-20,0\n"),
     "bad.csv:4: negative wear rate: slope*x + intercept = -10 ug/(m mm^2) at x = 10 N/mm^2 "
     "(set a positive floor to ask for max(floor, slope*x + intercept))"},
    {"NegativeFloor", Table::tgamma, tgamma_file("mild,0,inf,5,0,-1\n"),
     "bad.csv:3: negative wear rate: floor = -1 ug/(m mm^2) must be finite and >= 0"},
    {"WearWithoutWork", Table::tgamma, tgamma_file("flat,0,inf,0,2,0\n"),
     "bad.csv:3: wear rate at T gamma / A = 0 is 2 ug/(m mm^2): it must be 0 (no frictional "
     "work, no wear)"},
    {"DuplicateName", Table::tgamma, tgamma_file(kMild + "mild,10.4,inf,0,55,0\n"),
     "bad.csv:4: regime name 'mild' repeats that of line 3"},
    {"EmptyName", Table::tgamma, tgamma_file(",0,inf,5.3,0,0\n"),
     "bad.csv:3: regime name '' must be non-empty, without commas, line breaks or surrounding "
     "spaces, and not start with '#'"},
    {"ArchardGap", Table::archard, archard_file(kSeizure + kLow + kMid),
     "bad.csv: gap in the wear map: no region covers p/H in [0, 0.8) and sliding speed in "
     "[0.7, inf) m/s"},
    {"ArchardGapAtZero", Table::archard,
     archard_file(kSeizure + "low,0.1,0.8,0,0.2,5.5e-4\n" + kMid + kHigh),
     "bad.csv: gap in the wear map: no region covers p/H in [0, 0.1) and sliding speed in "
     "[0, 0.2) m/s"},
    {"ArchardOverlap", Table::archard,
     archard_file("seizure,0.7,inf,0,inf,0.035\n" + kLow + kMid + kHigh),
     "bad.csv:3: overlap: region 'low' and region 'seizure' (line 2) both cover p/H in "
     "[0.7, 0.8) and sliding speed in [0, 0.2) m/s"},
    {"ArchardNegativeK", Table::archard,
     archard_file(kSeizure + "low,0,0.8,0,0.2,-1e-4\n" + kMid + kHigh),
     "bad.csv:3: negative wear coefficient: k = -1e-04 must be finite and >= 0"},
    {"ArchardNaN", Table::archard,
     archard_file(kSeizure + kLow + "mid,0,0.8,nan,0.7,35e-4\n" + kHigh),
     "bad.csv:4: column 'sliding_speed_lower_m_per_s': NaN is not a valid value"},
    {"ArchardEmptySpeedRange", Table::archard,
     archard_file(kSeizure + kLow + "mid,0,0.8,0.7,0.2,35e-4\n" + kHigh),
     "bad.csv:4: empty sliding speed range: upper bound 0.2 is not above lower bound 0.7"},
    {"ArchardTooManyFields", Table::archard, archard_file(kSeizure + "low,0,0.8,0,0.2,5.5e-4,1\n"),
     "bad.csv:3: expected 6 comma-separated fields, got 7"},
};

// Names the case in gtest's output instead of dumping the struct's bytes.
void PrintTo(const BadCsv& bad, std::ostream* out) {
  *out << bad.label;
}

class WearLawBadCsv : public ::testing::TestWithParam<BadCsv> {};

TEST_P(WearLawBadCsv, IsRejectedWithItsSpecificMessage) {
  const BadCsv& bad = GetParam();
  std::istringstream in(bad.text);
  try {
    if (bad.table == Table::tgamma) {
      TgammaLaw::read_csv(in, "bad.csv");
    } else {
      ArchardLaw::read_csv(in, "bad.csv");
    }
    FAIL() << "accepted:\n" << bad.text;
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), bad.error);
  }
}

INSTANTIATE_TEST_SUITE_P(WearLaw, WearLawBadCsv, ::testing::ValuesIn(kBadCsvFiles),
                         [](const ::testing::TestParamInfo<BadCsv>& param_info) {
                           return std::string(param_info.param.label);
                         });

}  // namespace
}  // namespace wheelwear::wear
