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

}  // namespace
}  // namespace wheelwear::pipeline
