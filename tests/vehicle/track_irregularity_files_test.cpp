// Track irregularity records: linear interpolation between their samples, the file format's
// exact round trip, its comments, delimiters and column order, and its errors naming the file,
// line and fix.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/input_errors.hpp"
#include "support/same_bits.hpp"
#include "wheelwear/vehicle/track_irregularities.hpp"

namespace wheelwear::vehicle {
namespace {

using wheelwear::testing::contains;
using wheelwear::testing::error_of;
using wheelwear::testing::same_bits;

// Linear interpolation: exact at the samples, the mean at midpoints; outside the record it throws.
TEST(TrackIrregularityFiles, InterpolatesLinearlyBetweenSamples) {
  const TrackIrregularities r = generate_irregularities(IrregularitySpec{}, 50.0, 0.25, 9);
  int compared = 0;
  for (std::size_t i = 0; i + 1 < r.distance.size(); ++i) {
    EXPECT_EQ(r.alignment_at(r.distance[i]), r.alignment[i]);
    EXPECT_EQ(r.cross_level_at(r.distance[i]), r.cross_level[i]);
    const double mid = 0.5 * (r.distance[i] + r.distance[i + 1]);
    // 1e-18 m: a few roundings of values below 1e-2 m.
    EXPECT_NEAR(r.alignment_at(mid), 0.5 * (r.alignment[i] + r.alignment[i + 1]), 1e-18);
    EXPECT_NEAR(r.cross_level_at(mid), 0.5 * (r.cross_level[i] + r.cross_level[i + 1]), 1e-18);
    compared += 4;
  }
  EXPECT_EQ(r.alignment_at(50.0), r.alignment.back());
  EXPECT_TRUE(contains(error_of([&] { r.alignment_at(50.5); }), "distance = 50.5"));
  EXPECT_TRUE(contains(error_of([&] { r.cross_level_at(-1.0); }), "distance = -1"));
  compared += 3;
  EXPECT_EQ(compared, 4 * 200 + 3);
}

std::filesystem::path temp_file(const std::string& name, const std::string& text) {
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / ("wheelwear_irregularities_" + name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A generated record written and read back: the same doubles, bit for bit.
TEST(TrackIrregularityFiles, RoundTripIsExact) {
  IrregularitySpec spec;
  spec.spectrum = ErriSpectrum::high();
  spec.run_in = 20.0;
  const TrackIrregularities r = generate_irregularities(spec, 500.0, 0.1, 77);
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / "wheelwear_irregularities_round_trip.csv";
  write_irregularities(r, path);
  const TrackIrregularities back = read_irregularities(path);
  EXPECT_TRUE(same_bits(back.distance, r.distance));
  EXPECT_TRUE(same_bits(back.alignment, r.alignment));
  EXPECT_TRUE(same_bits(back.cross_level, r.cross_level));
  EXPECT_EQ(back.source, path.string());
  std::filesystem::remove(path);
  // 4 comparisons of 5001 samples each.
}

// Comments, blank lines, CRLF, blanks or tabs between fields, the columns in another order and
// an extra column; interpolation on uneven distances.
TEST(TrackIrregularityFiles, ReadsCommentsDelimitersAndAnyColumnOrder) {
  const std::string text =
      "# measured on line 4711, converted to metres\r\n"
      "\r\n"
      "cross_level_m\tgauge_m  distance_m alignment_m   # header\r\n"
      "0.001\t1.435 0.0 -0.002\r\n"
      "# a comment between rows\r\n"
      "0.003 1.436 2.0 0.004  # trailing comment\r\n"
      "-0.001,1.434,10.0,0.0\r\n";
  const TrackIrregularities r = parse_irregularities(text, "line4711.txt");
  ASSERT_EQ(r.distance.size(), 3u);
  EXPECT_EQ(r.distance[2], 10.0);
  EXPECT_EQ(r.alignment[0], -0.002);
  EXPECT_EQ(r.cross_level[1], 0.003);
  EXPECT_DOUBLE_EQ(r.alignment_at(1.0), 0.001);    // halfway from -0.002 to 0.004
  EXPECT_DOUBLE_EQ(r.cross_level_at(6.0), 0.001);  // halfway from 0.003 to -0.001
  // 6 comparisons.
}

// Each kind of bad input: the message names the file and line, what is wrong and the fix.
TEST(TrackIrregularityFiles, BadInputNamesTheFileLineAndFix) {
  const std::string header = "distance_m,alignment_m,cross_level_m\n";
  struct Case {
    std::string name, text, expected, fix;
  };
  const Case cases[] = {
      {"nan.csv", header + "0,0,0\n1,nan,0\n", "nan.csv:3: alignment_m = nan", "finite"},
      {"inf.csv", header + "0,0,0\n1,0,inf\n", "inf.csv:3: cross_level_m = inf", "finite"},
      {"word.csv", header + "0,0,0\n1,0.5mm,0\n", "word.csv:3: alignment_m = \"0.5mm\"",
       "in metres"},
      {"equal.csv", header + "0,0,0\n1,0,0\n1,0,0\n", "equal.csv:4: distance_m = 1 does not",
       "strictly increasing"},
      {"down.csv", header + "0,0,0\n2,0,0\n1,0,0\n", "down.csv:4: distance_m = 1 does not",
       "sort the rows"},
      {"missing.csv", "distance_m,alignment_m\n0,0\n1,0\n",
       "missing.csv:1: the header names no "
       "column cross_level_m",
       "distance_m, alignment_m and cross_level_m"},
      {"mm.csv", "distance_m,alignment_mm,cross_level_mm\n", "no column alignment_m",
       "convert millimetres"},
      {"twice.csv", "distance_m,alignment_m,cross_level_m,alignment_m\n",
       "twice.csv:1: the header names the column alignment_m twice", "once"},
      {"noheader.csv", "# comment\n0,0,0\n1,0,0\n", "noheader.csv:2: \"0,0,0\" is a row of numbers",
       "header"},
      {"truncated.csv", header + "0,0,0\n1,0\n", "truncated.csv:3: 2 values", "truncated"},
      {"empty.csv", "# nothing but comments\n\n", "empty.csv: no header and no rows", "header"},
      {"one.csv", header + "0,0,0\n", "one.csv: 1 rows", "at least two"},
  };
  int compared = 0;
  for (const Case& c : cases) {
    const std::filesystem::path path = temp_file(c.name, c.text);
    const std::string message = error_of([&] { read_irregularities(path); });
    EXPECT_TRUE(contains(message, c.expected)) << c.name << ": " << message;
    EXPECT_TRUE(contains(message, c.fix)) << c.name << ": " << message;
    std::filesystem::remove(path);
    compared += 2;
  }
  // A file that is not there, and one of zero bytes.
  const std::filesystem::path absent =
      std::filesystem::path(::testing::TempDir()) / "wheelwear_irregularities_absent.csv";
  EXPECT_TRUE(contains(error_of([&] { read_irregularities(absent); }), absent.string()));
  const std::filesystem::path zero = temp_file("zero.csv", "");
  EXPECT_TRUE(contains(error_of([&] { read_irregularities(zero); }), zero.string()));
  std::filesystem::remove(zero);
  compared += 2;
  EXPECT_EQ(compared, 2 * 12 + 2);
}

}  // namespace
}  // namespace wheelwear::vehicle
