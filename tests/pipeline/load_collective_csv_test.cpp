// Load-collective CSV files as RFC 4180 writes them, with what hand-written ones add (comment
// lines, a UTF-8 byte-order mark): quoted fields, doubled quotes, line breaks inside quotes (the
// records' line numbers still right), a duplicated column refused, and every label the writer
// quotes read back as written.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "wheelwear/core/csv.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"

namespace wheelwear::pipeline {
namespace {

namespace fs = std::filesystem;
using core::read_csv;

TEST(Csv, QuotedFieldsCommentsAndLineNumbers) {
  const std::string text =
      "\xEF\xBB\xBFlabel, dy_m\r\n"
      "# a comment\r\n"
      "\r\n"
      "\"R500, outer\", 0.001\r\n"
      "\"say \"\"hi\"\"\",2\n"
      "\"two\nlines\",3\n"
      "  plain  ,4";
  const std::vector<core::CsvRecord> r = read_csv(text, "t.csv");
  ASSERT_EQ(r.size(), 5u);
  EXPECT_EQ(r[0].fields, (std::vector<std::string>{"label", "dy_m"}));
  EXPECT_EQ(r[0].line, 1);
  EXPECT_EQ(r[1].fields, (std::vector<std::string>{"R500, outer", "0.001"}));
  EXPECT_EQ(r[1].line, 4);
  EXPECT_EQ(r[2].fields, (std::vector<std::string>{"say \"hi\"", "2"}));
  EXPECT_EQ(r[3].fields, (std::vector<std::string>{"two\nlines", "3"}));
  EXPECT_EQ(r[3].line, 6);
  EXPECT_EQ(r[4].fields, (std::vector<std::string>{"plain", "4"}));
  EXPECT_EQ(r[4].line, 8);  // after the record that spans two lines
}

TEST(Csv, UnclosedQuotesAndTextAfterThemAreRefusedNamingTheLine) {
  try {
    read_csv("a,b\n1,\"open\n2,3\n", "t.csv");
    ADD_FAILURE() << "an unclosed quote was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.csv line 2: a quoted field is never closed"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(read_csv("a,b\n\"x\"y,1\n", "t.csv"), InputError);
}

TEST(Csv, EveryFieldTheWriterQuotesReadsBackAsWritten) {
  const std::vector<std::string> fields{"plain",          "a, b",       "say \"hi\"", "two\nlines",
                                        "#not a comment", "  padded  ", "",           "\"",
                                        "crlf\r\n"};
  int compared = 0;
  for (const std::string& f : fields) {
    const auto r = read_csv(core::csv_field(f) + ",1\n", "t.csv");
    ASSERT_EQ(r.size(), 1u) << f;
    ASSERT_EQ(r[0].fields.size(), 2u) << f;
    // A line break inside quotes keeps its LF; the CR of a CRLF is a line end's, not the field's.
    EXPECT_EQ(r[0].fields[0], f == "crlf\r\n" ? std::string("crlf\n") : f);
    ++compared;
  }
  EXPECT_EQ(compared, 9);
}

// The collective of a scene, read from `csv` written beside it.
Scene scene_with(const std::string& csv) {
  const fs::path dir = fs::temp_directory_path() / ("wheelwear_csv_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "c.csv", std::ios::binary) << csv;
  try {
    Scene s = parse_scene("[load_collective]\nfile = \"c.csv\"\n", dir);
    fs::remove_all(dir);
    return s;
  } catch (...) {
    fs::remove_all(dir);
    throw;
  }
}

TEST(LoadCollectiveCsv, QuotedLabelsAByteOrderMarkAndADuplicatedColumn) {
  const std::string rows = "\"R500, outer\",0.001,5e4,5e4,30\n\"two\nlines\",0.002,5e4,5e4,30\n";
  const std::string header = "label,dy_m,load_left_N,load_right_N,speed_m_s\n";
  const std::vector<WheelsetStateSpec> states = scene_with("\xEF\xBB\xBF" + header + rows).states;
  ASSERT_EQ(states.size(), 2u);
  EXPECT_EQ(states[0].label, "R500, outer");
  EXPECT_EQ(states[0].dy, 0.001);
  EXPECT_EQ(states[1].label, "two lines");  // a label is one line
  EXPECT_EQ(states[1].line, 3);
  try {
    scene_with("dy_m,load_left_N,load_right_N,speed_m_s,dy_m\n0,5e4,5e4,30,0\n");
    ADD_FAILURE() << "a duplicated column was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("column 'dy_m' appears twice (columns 1 and 5)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace wheelwear::pipeline
