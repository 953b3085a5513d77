// The results file's layout as a reader meets it: units on every dataset, integers stored as
// integers, text as UTF-8 (docs/results.md).

#include <H5Cpp.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include "wear_run_support.hpp"
#include "wheelwear/pipeline/results_file.hpp"

namespace wheelwear::pipeline {
namespace {

TEST_F(WearRunTest, EveryDatasetHasUnits) {
  const fs::path out = dir_ / "units.h5";
  run(small_scene(10e3, 10e3, 1e-3), out);
  // h5dump lists the attributes of every dataset; count datasets and their units.
  const std::string listing = (dir_ / "listing.txt").string();
  ASSERT_EQ(std::system(("h5dump -H -A " + out.string() + " > " + listing).c_str()), 0);
  std::ifstream in(listing);
  std::string line;
  int datasets = 0, units = 0;
  while (std::getline(in, line)) {
    if (line.find("DATASET \"") != std::string::npos) ++datasets;
    if (line.find("ATTRIBUTE \"units\"") != std::string::npos) ++units;
  }
  EXPECT_GT(datasets, 30);
  EXPECT_EQ(units, datasets);
}

// Counts, flags and statuses are integers, with -1 where a slot is empty; every text and
// attribute is a variable-length UTF-8 string (h5py reads str, not bytes).
TEST_F(WearRunTest, IntegersAreStoredAsIntegersAndTextsAsUtf8) {
  const fs::path out = dir_ / "types.h5";
  // A wheelset against its left flange: two patches there, one on the right wheel.
  run(small_scene(10e3, 10e3, 1e-3) +
          "[[load_collective.state]]\ndy_m = 0.0068\naxle_load_N = 110e3\nspeed_m_s = 20\n"
          "weight = 1\n",
      out);
  H5::H5File file(out.string(), H5F_ACC_RDONLY);
  const std::string step = ResultsFile::step_group(0) + "/";
  int integers = 0;
  for (const char* name : {"states/status", "states/from_table", "states/patches", "patches",
                           "failed_contacts", "limits/stopped", "wheel/limits_reached"}) {
    EXPECT_EQ(file.openDataSet(step + name).getTypeClass(), H5T_INTEGER) << name;
    ++integers;
  }
  EXPECT_EQ(integers, 7);
  for (const char* name : {"distance", "failed_contacts_weight", "states/Fx", "wheel/y"})
    EXPECT_EQ(file.openDataSet(step + name).getTypeClass(), H5T_FLOAT) << name;
  // A patch slot beyond a wheel's count holds -1 where the float arrays hold NaN.
  const auto fx = ResultsFile::read(out).read_step_array(0, "states/Fx");
  const auto table = ResultsFile::read(out).read_step_array(0, "states/from_table");
  ASSERT_EQ(fx.size(), table.size());
  int empty = 0;
  for (std::size_t i = 0; i < fx.size(); ++i) {
    EXPECT_EQ(std::isnan(fx[i]), table[i] == -1.0) << i;
    empty += std::isnan(fx[i]);
  }
  EXPECT_GT(empty, 0);
  const H5::Attribute units = file.openDataSet(step + "distance").openAttribute("units");
  EXPECT_TRUE(units.getStrType().isVariableStr());
  EXPECT_EQ(units.getStrType().getCset(), H5T_CSET_UTF8);
  const H5::Attribute hash = file.openGroup("/").openAttribute("creep_table_sha256");
  EXPECT_EQ(hash.getStrType().getCset(), H5T_CSET_UTF8);
  EXPECT_EQ(file.openDataSet("/scene").getStrType().getCset(), H5T_CSET_UTF8);
}

}  // namespace
}  // namespace wheelwear::pipeline
