// wheelwear sweep: the runs it makes (grid and zip), each run equal to running its scene alone,
// the summary against the run's own numbers, resuming, and the refusals.

#include "wheelwear/pipeline/sweep.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"
#include "thread_group.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/pipeline/run_headline.hpp"
#include "wheelwear/pipeline/scene.hpp"

namespace wheelwear::pipeline {
namespace {

class SweepTest : public WearRunTest {
 protected:
  // The small scene, two 20 km steps, as the sweep's base.
  fs::path base() const { return write("base.toml", small_scene(40e3, 20e3, 1e-3)); }
  fs::path sweep_file(const std::string& vary, const std::string& combine = "grid") const {
    base();
    return write("sweep.toml", "scene = \"base.toml\"\noutput_dir = \"runs\"\ncombine = \"" +
                                   combine + "\"\n[vary]\n" + vary);
  }
  // The rows of a CSV file; a quoted cell may hold commas and doubled quotes (RFC 4180).
  static std::vector<std::vector<std::string>> csv(const fs::path& file) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
      std::vector<std::string> cells(1);
      bool quoted = false;
      for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
          cells.back() += '"';
          ++i;
        } else if (c == '"') {
          quoted = !quoted;
        } else if (c == ',' && !quoted) {
          cells.emplace_back();
        } else {
          cells.back() += c;
        }
      }
      rows.push_back(cells);
    }
    return rows;
  }
};

TEST_F(SweepTest, AGridTakesEveryCombinationWithTheLastKeyFastest) {
  const Sweep s =
      read_sweep(sweep_file("\"contact.friction\" = [0.25, 0.35]\n\"run.distance_m\" = [1e3, "
                            "2e3, 3e3]\n"));
  ASSERT_EQ(s.runs.size(), 6u);
  EXPECT_EQ(s.keys, (std::vector<std::string>{"contact.friction", "run.distance_m"}));
  EXPECT_EQ(s.runs[0], (std::vector<std::string>{"0.25", "1e3"}));
  EXPECT_EQ(s.runs[2], (std::vector<std::string>{"0.25", "3e3"}));
  EXPECT_EQ(s.runs[3], (std::vector<std::string>{"0.35", "1e3"}));
  EXPECT_EQ(sweep_run_file(s, 5).filename(), "run_0006.h5");
  // The run's scene has the values where the base scene had others.
  const std::string text = sweep_scene_text(s, core::read_text_file(s.base_scene), 4);
  const Scene scene = parse_scene(text, dir_);
  EXPECT_DOUBLE_EQ(scene.friction, 0.35);
  EXPECT_DOUBLE_EQ(scene.distance, 2e3);
  EXPECT_EQ(scene.states.size(), 4u);  // the rest of the base scene kept
}

TEST_F(SweepTest, ZipTakesTheIthValuesTogetherAndWantsListsOfOneLength) {
  const Sweep s = read_sweep(sweep_file(
      "\"contact.friction\" = [0.25, 0.35]\n\"wear.law\" = [\"usfd\", \"archard\"]\n", "zip"));
  ASSERT_EQ(s.runs.size(), 2u);
  EXPECT_EQ(s.runs[1], (std::vector<std::string>{"0.35", "\"archard\""}));
  try {
    read_sweep(
        sweep_file("\"contact.friction\" = [0.25, 0.35]\n\"wear.law\" = [\"usfd\"]\n", "zip"));
    FAIL() << "lists of two lengths were taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sweep line 6: wear.law: combine = \"zip\" takes lists "
                                         "of one length; this has 1, the first 2"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(SweepTest, KeysVaryInTheOrderTheFileListsThem) {
  // toml++ iterates a table's keys sorted; the sweep follows the file.
  const Sweep s =
      read_sweep(sweep_file("\"wear.law\" = [\"usfd\", \"archard\"]\n\"contact.friction\" = "
                            "[0.25, 0.35, 0.45]\n"));
  EXPECT_EQ(s.keys, (std::vector<std::string>{"wear.law", "contact.friction"}));
  ASSERT_EQ(s.runs.size(), 6u);
  EXPECT_EQ(s.runs[1], (std::vector<std::string>{"\"usfd\"", "0.35"}));
  EXPECT_EQ(s.runs[3], (std::vector<std::string>{"\"archard\"", "0.25"}));
  EXPECT_EQ(sweep_summary_columns(s)[2], "wear.law");
}

TEST_F(SweepTest, BadSweepsAreRefusedNamingTheKey) {
  const auto message = [&](const std::string& text) {
    try {
      read_sweep(write("bad.toml", text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("scene = \"b.toml\"\nfriction = 0.3\n").find("line 2: friction: unknown key"),
            std::string::npos);
  EXPECT_NE(message("scene = \"b.toml\"\n").find("no [vary] table"), std::string::npos);
  EXPECT_NE(message("[vary]\n\"contact.friction\" = [0.3]\n").find("no scene = "),
            std::string::npos);
  EXPECT_NE(message("scene = \"b.toml\"\n[vary]\n\"contact.friction\" = []\n")
                .find("line 3: contact.friction: give a non-empty list"),
            std::string::npos);
  EXPECT_NE(message("scene = \"b.toml\"\ncombine = \"all\"\n[vary]\nx = [1]\n")
                .find("use \"grid\" (every combination) or \"zip\""),
            std::string::npos);
  EXPECT_NE(message("scene = \"b.toml\"\n[vary]\nx = [[1, 2]]\n")
                .find("must be a number, a string or a boolean"),
            std::string::npos);
}

TEST_F(SweepTest, ARunWithABadValueIsRefusedBeforeAnyRunStarts) {
  const Sweep s = read_sweep(sweep_file("\"contact.friction\" = [0.3, -1.0]\n"));
  try {
    run_sweep(s, {});
    FAIL() << "a friction of -1 was run";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run 2 (contact.friction = -1.0): scene line"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(s.output_dir / "run_0001.h5"));  // nothing ran
}

TEST_F(SweepTest, EachRunIsItsSceneRunAloneAndTheSummaryIsItsHeadline) {
  const Sweep s = read_sweep(sweep_file("\"contact.friction\" = [0.25, 0.4]\n"));
  const std::vector<SweepRow> rows = run_sweep(s, {});
  ASSERT_EQ(rows.size(), 2u);
  const std::string base_text = core::read_text_file(s.base_scene);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(rows[i].status, "done");
    const std::string text = sweep_scene_text(s, base_text, i);
    const fs::path alone = dir_ / ("alone_" + std::to_string(i) + ".h5");
    const RunSummary summary = run(text, alone);
    expect_identical_runs(alone, sweep_run_file(s, i));
    // The headline's worn area (the cumulative depth integrated along the new profile) against
    // the run's own (the area between the new and the worn profile): two computations of one
    // area, within 1 % (the normal and vertical measures differ on the steep flank).
    ASSERT_TRUE(rows[i].has_headline);
    EXPECT_NEAR(rows[i].headline.worn_area, summary.worn_area, 0.01 * summary.worn_area);
    EXPECT_DOUBLE_EQ(rows[i].headline.distance, 40e3);
  }
  // More friction, more wear: the sweep's point.
  EXPECT_GT(rows[1].headline.worn_area, rows[0].headline.worn_area);
  const auto table = csv(s.output_dir / "summary.csv");
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table[0], sweep_summary_columns(s));
  EXPECT_EQ(table[1][2], "0.25");
  EXPECT_EQ(table[2][3], "done");
  // The summary prints 9 significant digits: half a unit in the ninth is at most 5e-9 of it.
  EXPECT_NEAR(std::stod(table[2][7]), rows[1].headline.Sd_end, 5e-9 * rows[1].headline.Sd_end);
}

TEST_F(SweepTest, ARepeatedSweepSkipsCompleteRunsAndRunsTheMissingOne) {
  const Sweep s = read_sweep(sweep_file("\"contact.friction\" = [0.25, 0.4]\n"));
  const std::vector<SweepRow> first = run_sweep(s, {});
  const fs::path kept = sweep_run_file(s, 0);
  const auto written = fs::last_write_time(kept);
  fs::copy_file(sweep_run_file(s, 1), dir_ / "reference.h5");
  fs::remove(sweep_run_file(s, 1));
  const std::vector<SweepRow> again = run_sweep(s, {});
  EXPECT_EQ(again[0].status, "skipped");
  EXPECT_EQ(again[1].status, "done");
  EXPECT_EQ(fs::last_write_time(kept), written);  // a complete run's file is not touched
  expect_identical_runs(dir_ / "reference.h5", sweep_run_file(s, 1));
  EXPECT_DOUBLE_EQ(again[1].headline.Sd_end, first[1].headline.Sd_end);
}

// The command: a run that fails (a folder stands where its results file would be) is recorded,
// the other completes, and the command exits with status 3.
TEST_F(SweepTest, TheCommandRecordsAFailedRunFinishesTheOthersAndExitsWithThree) {
  const fs::path file = sweep_file("\"contact.friction\" = [0.25, 0.4]\n");
  const Sweep s = read_sweep(file);
  fs::create_directories(sweep_run_file(s, 1));  // run 2's results file is a folder
  const auto r = testing::run_wheelwear("sweep " + file.string() + " --json --threads 2");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.out.find("\"runs_failed\": 1"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("1 of 2 runs failed"), std::string::npos) << r.err;
  const auto table = csv(s.output_dir / "summary.csv");
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table[1][3], "done");
  EXPECT_EQ(table[2][3].rfind("failed: ", 0), 0u) << table[2][3];
  EXPECT_TRUE(ResultsFile::read(sweep_run_file(s, 0)).has("/final"));
}

// A sweep killed while its first run had written one step: started again, it resumes that run
// to the file the run writes alone, and runs the other.
TEST_F(SweepTest, AKilledSweepResumesItsPartialRun) {
  const fs::path file = sweep_file("\"contact.friction\" = [0.25, 0.4]\n");
  // Twenty steps, so that the kill lands while the first run is under way.
  write("base.toml", small_scene(400e3, 20e3, 1e-3));
  const Sweep s = read_sweep(file);
  const int status = kill_run_after_steps({"sweep", file.string(), "--threads", "1", "-q"},
                                          sweep_run_file(s, 0), 1);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_LT(ResultsFile::read(sweep_run_file(s, 0)).completed_steps(), 21);
  // Resumed by the program that started it (a run's steps come from one program).
  const auto again = testing::run_wheelwear("sweep " + file.string() + " --threads 1");
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.err.find("run 1 (contact.friction = 0.25): done"), std::string::npos)
      << again.err;
  const fs::path alone = dir_ / "alone.h5";
  run(sweep_scene_text(s, core::read_text_file(s.base_scene), 0), alone);
  expect_identical_runs(alone, sweep_run_file(s, 0));
}

// A file left by a sweep whose values have changed since is not taken for this run.
TEST_F(SweepTest, AFileOfAnotherSceneFailsItsRunNamingTheFix) {
  run_sweep(read_sweep(sweep_file("\"contact.friction\" = [0.25]\n")), {});
  const Sweep changed = read_sweep(sweep_file("\"contact.friction\" = [0.3]\n"));
  const std::vector<SweepRow> rows = run_sweep(changed, {});
  EXPECT_NE(rows[0].status.find("holds a run of another scene (the sweep's values changed since "
                                "it was written): move it away, or give the sweep another "
                                "output_dir"),
            std::string::npos)
      << rows[0].status;
}

}  // namespace
}  // namespace wheelwear::pipeline

namespace wheelwear::pipeline {
namespace {

// Spread over processes (threads standing in for them), the runs are shared out and process 0
// writes the summary of all; a process that refuses the inputs stops all of them before any run
// starts (none left waiting for it), and process 0 says which process and why.
TEST_F(SweepTest, SpreadOverProcessesAllRunOrAllStop) {
  const Sweep sweep = read_sweep(sweep_file("\"contact.friction\" = [0.25, 0.3, 0.4]\n"));
  std::vector<std::vector<SweepRow>> rows(2);
  run_thread_group(
      2,
      [&](ProcessGroup& group) {
        SweepOptions options;
        options.group = &group;
        try {
          rows[0] = run_sweep(sweep, options);
        } catch (const std::exception& e) {
          ADD_FAILURE() << e.what();
        }
      },
      [&](ProcessGroup& group) {
        SweepOptions options;
        options.group = &group;
        rows[1] = run_sweep(sweep, options);
      });
  ASSERT_EQ(rows[0].size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(rows[0][i].status, "done") << i;
    EXPECT_EQ(rows[0][i].index, i);
    EXPECT_TRUE(rows[0][i].has_headline) << i;  // process 0 read process 1's run's file too
    EXPECT_TRUE(rows[0][i].headline.complete) << i;
  }
  EXPECT_EQ(rows[1][1].status, "done");  // process 1 ran run 2, and only that one
  EXPECT_TRUE(rows[1][0].status.empty());
  EXPECT_EQ(csv(dir_ / "runs" / "summary.csv").size(), 4u);

  // Process 1 cannot read the base scene (as on a node without the shared file system).
  Sweep elsewhere = sweep;
  elsewhere.base_scene = dir_ / "missing" / "base.toml";
  elsewhere.output_dir = dir_ / "runs2";
  Sweep here = sweep;
  here.output_dir = dir_ / "runs2";
  std::string said;
  bool other_stopped = false;
  run_thread_group(
      2,
      [&](ProcessGroup& group) {
        SweepOptions options;
        options.group = &group;
        try {
          run_sweep(here, options);
        } catch (const InputError& e) {
          said = e.what();
        }
      },
      [&](ProcessGroup& group) {
        SweepOptions options;
        options.group = &group;
        try {
          run_sweep(elsewhere, options);
        } catch (const std::exception&) {
          other_stopped = true;
        }
      });
  EXPECT_TRUE(other_stopped);
  EXPECT_NE(said.find("process 1: "), std::string::npos) << said;
  EXPECT_NE(said.find("missing"), std::string::npos) << said;
  EXPECT_FALSE(fs::exists(dir_ / "runs2" / "run_0001.h5"));  // no run started
}

}  // namespace
}  // namespace wheelwear::pipeline
