// A wear-evolution run killed or stopped and resumed ends as the uninterrupted run, bit for bit;
// a file of another layout version is not continued.

#include <H5Cpp.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/run_command.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/wear_run.hpp"

namespace wheelwear::pipeline {
namespace {

namespace fs = std::filesystem;

// Killed at twenty moments spread over a run — starting, computing, writing a step's file,
// linking it, consolidating — and resumed (or run anew where no file was published yet), the
// run ends with the uninterrupted run's results, bit for bit, and as one file.
TEST_F(WearRunTest, KilledAtAnyMomentResumesToIdenticalResults) {
  // Thirteen steps, so that most kill moments fall after the file was created.
  const fs::path scene = write("s.toml", small_scene(60e3, 5e3, 1e-3));
  const fs::path reference = dir_ / "reference.h5", killed = dir_ / "killed.h5";
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_EQ(
      testing::run_wheelwear("run " + scene.string() + " -q --threads 1 -o " + reference.string())
          .exit_code,
      0);
  const double whole = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  int resumed = 0, completed = 0;
  for (int i = 0; i < 20; ++i) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::execl(WHEELWEAR_EXE, WHEELWEAR_EXE, "run", scene.c_str(), "-q", "--threads", "1", "-o",
              killed.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::usleep(static_cast<useconds_t>(1e6 * whole * (i + 0.5) / 20.0));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    const bool finished = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (finished) {
      ++completed;
    } else if (fs::exists(killed)) {
      // Exit 0, or 2 where the kill came after the last step (the run is complete).
      const int code = testing::run_wheelwear("run --resume " + killed.string() + " -q").exit_code;
      EXPECT_TRUE(code == 0 || code == 2) << "kill " << i << ": exit " << code;
      ++resumed;
    } else {
      ASSERT_EQ(
          testing::run_wheelwear("run " + scene.string() + " -q -o " + killed.string()).exit_code,
          0);
    }
    expect_identical_runs(reference, killed);
    EXPECT_FALSE(fs::exists(ResultsFile::steps_directory(killed))) << "kill " << i;
    for (const char* suffix : {"", ".partial", ".lock"}) fs::remove(killed.string() + suffix);
    fs::remove_all(ResultsFile::steps_directory(killed));
    if (HasFatalFailure()) return;
  }
  std::printf("run %.2f s; 20 kills: %d resumed, %d after the run had finished\n", whole, resumed,
              completed);
  EXPECT_GE(resumed, 5);  // most kills fall after the file exists (11 of 20 measured)
}

// SIGTERM (as a batch scheduler sends it) ends a run with a line saying where its results are
// and how to continue, and with the signal's own exit status; the resumed run then ends as an
// uninterrupted one.
TEST_F(WearRunTest, ASignalEndsARunSayingHowToResume) {
  const fs::path scene = write("s.toml", small_scene(60e3, 5e3, 1e-3));
  const fs::path reference = dir_ / "reference.h5", stopped = dir_ / "stopped.h5";
  const fs::path err = dir_ / "stderr.txt";
  ASSERT_EQ(
      testing::run_wheelwear("run " + scene.string() + " -q -o " + reference.string()).exit_code,
      0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDERR_FILENO);
    ::execl(WHEELWEAR_EXE, WHEELWEAR_EXE, "run", scene.c_str(), "--threads", "1", "-o",
            stopped.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Once its second step is on disk.
  const fs::path second = ResultsFile::steps_directory(stopped) / "000001.h5";
  for (int i = 0; i < 2000 && !fs::exists(second); ++i) ::usleep(5000);
  ::kill(pid, SIGTERM);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  std::ifstream in(err);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(text.find("wheelwear: stopped by SIGTERM; the steps finished so far are in " +
                      stopped.string() + "; continue with: wheelwear run --resume " +
                      stopped.string() + "\n"),
            std::string::npos)
      << text;
  ASSERT_EQ(testing::run_wheelwear("run --resume " + stopped.string() + " -q").exit_code, 0);
  expect_identical_runs(reference, stopped);
}

// A results file of another layout version is not continued: its steps would not match the
// ones this program appends.
TEST_F(WearRunTest, ResumeRefusesAnotherLayoutVersion) {
  const fs::path out = dir_ / "old.h5";
  run(small_scene(30e3, 10e3, 1e-3), out);
  {
    H5::H5File file(out.string(), H5F_ACC_RDWR);
    H5::Attribute version = file.openGroup("/").openAttribute("format_version");
    const int one = 1;
    version.write(H5::PredType::NATIVE_INT, &one);
  }
  try {
    resume_run(out, {});
    FAIL() << "a version-1 file was resumed";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("layout version 1"), std::string::npos)
        << error.what();
  }
}

// A run of the built-in scene records no scene file: it is continued only by a program whose
// built-in scene is the one it ran (the built-in scene changed once, from a hand-set collective
// to the vehicle on its route).
TEST_F(WearRunTest, ResumeRefusesAnotherBuiltInScene) {
  const fs::path out = dir_ / "builtin.h5";
  const std::string text = small_scene(30e3, 10e3, 1e-3);
  RunOptions stop_after_a_step;
  stop_after_a_step.progress = [](const RunProgress&) { throw std::runtime_error("stopped"); };
  EXPECT_THROW(run_scene(parse_scene(text, dir_), text, {}, true, out, stop_after_a_step),
               std::runtime_error);
  try {
    resume_run(out, {});
    FAIL() << "a run of another built-in scene was resumed";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("another built-in scene"), std::string::npos)
        << error.what();
  }
}

TEST_F(WearRunTest, KilledRunResumesToIdenticalResults) {
  // Enough steps that the run is still going when it is killed after its second step.
  const fs::path scene = write("s.toml", small_scene(400e3, 10e3, 1e-3));
  const fs::path reference = dir_ / "reference.h5", killed = dir_ / "killed.h5";
  ASSERT_EQ(
      testing::run_wheelwear("run " + scene.string() + " -q -o " + reference.string()).exit_code,
      0);
  const int total = ResultsFile::read(reference).completed_steps();
  ASSERT_EQ(total, 41);

  // Killed without warning once two steps are published.
  const int status =
      kill_run_after_steps({"run", scene.string(), "-q", "-o", killed.string()}, killed, 2);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  const int kept = ResultsFile::read(killed).completed_steps();
  ASSERT_GE(kept, 2);
  ASSERT_LT(kept, total);

  const auto resumed = testing::run_wheelwear("run -q --resume " + killed.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  expect_identical_runs(reference, killed);
  // A complete run is not resumed again.
  EXPECT_EQ(testing::run_wheelwear("run -q --resume " + killed.string()).exit_code, 2);
}

}  // namespace
}  // namespace wheelwear::pipeline
