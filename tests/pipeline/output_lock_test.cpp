// One writer per results file: a second run, resume or command line given an output that a run
// is writing stops with one line naming it, and leaves the file as it was; outputs that cannot
// be written (a folder, a missing folder) are refused before anything is written.

#include "wheelwear/pipeline/output_lock.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>

#include "support/run_command.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::pipeline {
namespace {

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The message of the InputError (bad input) or IoError (a lock held, a folder that refuses
// the file) `make` throws, or "" when it throws none.
template <class Make>
std::string refusal(Make make) {
  try {
    make();
  } catch (const InputError& e) {
    return e.what();
  } catch (const IoError& e) {
    return e.what();
  }
  return "";
}

class OutputLockTest : public WearRunTest {};

TEST_F(OutputLockTest, ASecondWriterIsRefusedUntilTheFirstIsDone) {
  const fs::path output = dir_ / "run.h5";
  {
    const OutputLock first(output);
    EXPECT_TRUE(fs::exists(lock_path(output)));
    const std::string message = refusal([&] { OutputLock second(output); });
    EXPECT_NE(message.find("another run is writing it (process " + std::to_string(::getpid())),
              std::string::npos)
        << message;
  }
  // Released and removed with the first: the next writer takes it.
  EXPECT_FALSE(fs::exists(lock_path(output)));
  EXPECT_EQ(refusal([&] { OutputLock again(output); }), "");
}

TEST_F(OutputLockTest, UnwritableOutputsAreRefusedNamingTheCause) {
  EXPECT_NE(refusal([&] { OutputLock l(dir_); }).find("is a folder"), std::string::npos);
  EXPECT_NE(refusal([&] { OutputLock l(dir_ / "missing" / "run.h5"); }).find("does not exist"),
            std::string::npos);
  write("plain.txt", "not a folder");
  EXPECT_NE(refusal([&] { OutputLock l(dir_ / "plain.txt" / "run.h5"); }).find("is not a folder"),
            std::string::npos);
  // Nothing was written: the folder holds the plain file alone, as it was.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
  EXPECT_EQ(bytes_of(dir_ / "plain.txt"), "not a folder");
}

// A run, a resume and the command line, each given the output a run is writing: refused, the
// file byte for byte as it was, no stray copy left.
TEST_F(OutputLockTest, RunsAndResumesOfALockedOutputLeaveItUntouched) {
  const std::string text = small_scene(20e3, 10e3, 1e-3);
  const fs::path output = dir_ / "run.h5";
  RunOptions stop;
  stop.progress = [](const RunProgress& p) {
    if (p.step == 1) throw std::runtime_error("interrupted");
  };
  EXPECT_THROW(run_scene(parse_scene(text, dir_), text, dir_, false, output, stop),
               std::runtime_error);
  const std::string before = bytes_of(output);
  ASSERT_FALSE(before.empty());
  {
    const OutputLock held(output);
    RunOptions overwrite;
    overwrite.overwrite = true;
    EXPECT_NE(refusal([&] {
                run_scene(parse_scene(text, dir_), text, dir_, false, output, overwrite);
              }).find("another run is writing it"),
              std::string::npos);
    EXPECT_NE(refusal([&] { resume_run(output, {}); }).find("another run is writing it"),
              std::string::npos);
    const testing::CommandResult cli = testing::run_wheelwear("run --resume " + output.string());
    EXPECT_EQ(cli.exit_code, 4);  // a system failure, not bad input (docs/cli.md)
    EXPECT_NE(cli.err.find("another run is writing it"), std::string::npos) << cli.err;
    EXPECT_EQ(std::count(cli.err.begin(), cli.err.end(), '\n'), 1) << cli.err;
    EXPECT_EQ(bytes_of(output), before);
    EXPECT_FALSE(fs::exists(dir_ / "run.h5.partial"));
  }
  // Once released the resume goes on.
  EXPECT_EQ(resume_run(output, {}).steps, 2);
}

}  // namespace
}  // namespace wheelwear::pipeline
