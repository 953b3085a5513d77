// The results file: round trips, durability of published steps, refusal to clobber.

#include "wheelwear/pipeline/results_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::pipeline {
namespace {

namespace fs = std::filesystem;

class ResultsFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() /
                 ("wheelwear_results_" + std::to_string(::getpid()) + "_" +
                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  fs::path file(const char* name) const { return directory_ / name; }

  static GroupRecord step(double distance) {
    GroupRecord g;
    g.arrays.push_back({"distance", {distance}, {}, "m", "running distance"});
    g.arrays.push_back({"wheel/yz", {1, 2, 3, 4, 5, 6}, {3, 2}, "m", "profile points"});
    g.texts.push_back({"law", "usfd", "wear law"});
    return g;
  }

 private:
  fs::path directory_;
};

TEST_F(ResultsFileTest, StepsRoundTripExactly) {
  ResultsFile out = ResultsFile::create(file("run.h5"), "name = 'x'\n", false);
  out.append_step(step(1000.0));
  out.append_step(step(2000.5));
  const ResultsFile in = ResultsFile::open(file("run.h5"));
  EXPECT_EQ(in.completed_steps(), 2);
  EXPECT_EQ(in.scene_text(), "name = 'x'\n");
  EXPECT_EQ(in.read_step_array(1, "distance"), std::vector<double>{2000.5});
  EXPECT_EQ(in.read_step_array(0, "wheel/yz"), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_THROW(in.read_step_array(2, "distance"), InputError);
}

TEST_F(ResultsFileTest, NeverClobbersAnExistingFileUnlessAsked) {
  {
    std::ofstream precious(file("run.h5"));
    precious << "earlier results";
  }
  EXPECT_THROW(ResultsFile::create(file("run.h5"), "", false), InputError);
  std::ifstream kept(file("run.h5"));
  std::string text;
  std::getline(kept, text);
  EXPECT_EQ(text, "earlier results");
  EXPECT_NO_THROW(ResultsFile::create(file("run.h5"), "", true));
}

// A run killed while it wrote a step leaves FILE.partial behind; FILE still holds every
// published step, and reopening discards the unfinished copy.
TEST_F(ResultsFileTest, AKilledStepLeavesThePublishedStepsIntact) {
  ResultsFile out = ResultsFile::create(file("run.h5"), "", false);
  out.append_step(step(1.0));
  {
    std::ofstream half(file("run.h5.partial"), std::ios::binary);
    half << "\x89HDF\r\n half a step";
  }
  const ResultsFile in = ResultsFile::open(file("run.h5"));
  EXPECT_EQ(in.completed_steps(), 1);
  EXPECT_FALSE(fs::exists(file("run.h5.partial")));
}

TEST_F(ResultsFileTest, RejectsMissingAndForeignFiles) {
  EXPECT_THROW(ResultsFile::open(file("absent.h5")), InputError);
  {
    std::ofstream junk(file("junk.h5"));
    junk << "not hdf5";
  }
  EXPECT_THROW(ResultsFile::open(file("junk.h5")), InputError);
}

// While a run goes on each step is a file of its own, linked into FILE: FILE stays small (the
// copy a step commits does not grow with the steps), the steps read through the links also
// from another working directory, and consolidation makes one file that reads the same.
TEST_F(ResultsFileTest, StepsAreFilesOfTheirOwnUntilConsolidated) {
  const fs::path path = file("run.h5");
  ResultsFile out = ResultsFile::create(path, "", false);
  GroupRecord big = step(0.0);
  big.arrays.push_back({"big", std::vector<double>(20000, 1.5), {20000}, "1", "bulk"});
  out.append_step(big);
  const auto first = fs::file_size(path);
  for (int k = 1; k < 20; ++k) {
    GroupRecord g = step(1000.0 * k);
    g.arrays.push_back({"big", std::vector<double>(20000, 0.5 * k), {20000}, "1", "bulk"});
    out.append_step(g);
  }
  const fs::path steps = ResultsFile::steps_directory(path);
  EXPECT_TRUE(fs::exists(steps / "000019.h5"));
  // 19 more links and no data: FILE grows by far less than one step's file.
  EXPECT_LT(fs::file_size(path) - first, fs::file_size(steps / "000019.h5"));
  const fs::path here = fs::current_path();
  fs::current_path("/");
  const ResultsFile running = ResultsFile::read(path);
  EXPECT_EQ(running.read_step_array(7, "distance"), std::vector<double>{7000.0});
  EXPECT_EQ(running.read_step_array(19, "big").at(19999), 9.5);
  fs::current_path(here);

  out.consolidate();
  EXPECT_FALSE(fs::exists(steps));
  const ResultsFile done = ResultsFile::read(path);
  EXPECT_EQ(done.completed_steps(), 20);
  EXPECT_EQ(done.read_step_array(19, "distance"), std::vector<double>{19000.0});
  EXPECT_EQ(done.read_step_array(3, "big").at(0), 1.5);
  EXPECT_EQ(done.read_text("/steps/000004/law"), std::optional<std::string>("usfd"));
  EXPECT_EQ(done.step_array_names(5), running.step_array_names(5));
}

// A step file written but not linked (a run killed between the two) is not a step: reopening
// the file removes it, and the resumed run writes that step afresh.
TEST_F(ResultsFileTest, AStepWrittenButNotLinkedIsDiscarded) {
  const fs::path path = file("run.h5");
  ResultsFile out = ResultsFile::create(path, "", false);
  out.append_step(step(1.0));
  const fs::path steps = ResultsFile::steps_directory(path);
  fs::copy_file(steps / "000000.h5", steps / "000001.h5");
  {
    std::ofstream half(steps / "000002.h5.partial", std::ios::binary);
    half << "\x89HDF";
  }
  ResultsFile again = ResultsFile::open(path);
  EXPECT_EQ(again.completed_steps(), 1);
  EXPECT_FALSE(fs::exists(steps / "000001.h5"));
  again.append_step(step(2.0));
  EXPECT_EQ(ResultsFile::read(path).read_step_array(1, "distance"), std::vector<double>{2.0});
}

// A running file renamed before it is resumed: its links still reach the old step folder, the
// resumed steps go to the new name's, and consolidation gathers both and removes both.
TEST_F(ResultsFileTest, ARenamedRunningFileConsolidatesThroughItsLinks) {
  ResultsFile out = ResultsFile::create(file("run.h5"), "", false);
  out.append_step(step(1.0));
  out.append_step(step(2.0));
  fs::rename(file("run.h5"), file("moved.h5"));
  ResultsFile moved = ResultsFile::open(file("moved.h5"));
  EXPECT_EQ(moved.read_step_array(1, "distance"), std::vector<double>{2.0});
  moved.append_step(step(3.0));
  EXPECT_TRUE(moved.has_linked_steps());
  moved.consolidate();
  EXPECT_FALSE(moved.has_linked_steps());
  EXPECT_FALSE(fs::exists(ResultsFile::steps_directory(file("run.h5"))));
  EXPECT_FALSE(fs::exists(ResultsFile::steps_directory(file("moved.h5"))));
  const ResultsFile done = ResultsFile::read(file("moved.h5"));
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(done.read_step_array(k, "distance"), std::vector<double>{k + 1.0}) << k;
}

}  // namespace
}  // namespace wheelwear::pipeline
