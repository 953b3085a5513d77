// The co-simulation hook: an outside program makes every step's collective from the current
// profiles. References: the same collective given directly (the wear must be bit-identical),
// the run's own recorded profiles (the files the program is given), and the refusals.

#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/run_command.hpp"
#include "wear_run_support.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/profiles/profile_io.hpp"

namespace wheelwear::pipeline {
namespace {

// small_scene()'s states as a collective file (the hook's output format).
constexpr const char* kStatesCsv =
    "label,dy_m,yaw_rad,axle_load_N,load_left_N,load_right_N,lateral_force_right_N,speed_m_s,"
    "curve_radius_m,lateral_velocity_m_s,weight\n"
    "tangent,0.001,2e-4,110e3,,,,40,,0.01,3\n"
    "tangent,-0.002,-3e-4,110e3,,,,40,,,3\n"
    "R1000,0.004,1e-3,,60e3,50e3,,30,1000,,1\n"
    "R500,-0.0065,-2e-3,,50e3,60e3,25e3,22,-500,,1\n";

// small_scene() with its inline collective cut off, and `hook` (a [hook] table) in its place.
std::string hook_scene(double distance, double step, double max_depth, const std::string& hook) {
  std::string text = small_scene(distance, step, max_depth);
  text.erase(text.find("[[load_collective.state]]"));
  return text + hook;
}

// A [hook] table whose command is `sh -c script` (the scene names the shell itself: the run
// starts programs without one).
std::string shell_hook(const std::string& script, const std::string& extra = "") {
  return "[hook]\ncommand = [\"/bin/sh\", \"-c\", \"" + script + "\"]\n" + extra;
}

class HookRunTest : public WearRunTest {
 protected:
  RunSummary run_hook(const std::string& scene_text, const fs::path& out, bool allow = true) const {
    RunOptions options;
    options.allow_hook = allow;
    return run_scene(parse_scene(scene_text, dir_), scene_text, dir_, false, out, options);
  }
};

TEST_F(HookRunTest, TheHooksCollectiveWearsAsTheSameCollectiveGivenDirectly) {
  write("states.csv", kStatesCsv);
  const std::string direct =
      small_scene(20e3, 10e3, 1e-3).substr(0, small_scene(20e3, 10e3, 1e-3).find("[[")) +
      "[load_collective]\nfile = \"states.csv\"\n";
  run(direct, dir_ / "direct.h5");
  run_hook(hook_scene(20e3, 10e3, 1e-3,
                      "[hook]\ncommand = [\"cp\", \"states.csv\", \"{collective}\"]\n"),
           dir_ / "hook.h5");
  const ResultsFile a = ResultsFile::read(dir_ / "direct.h5"),
                    b = ResultsFile::read(dir_ / "hook.h5");
  ASSERT_EQ(a.completed_steps(), 3);
  ASSERT_EQ(b.completed_steps(), 3);
  std::size_t compared = 0;
  for (int step = 0; step < 3; ++step) {
    for (const char* name : {"wheel/wear_rate/depth", "wheel/y", "wheel/z", "step_distance"}) {
      const auto va = a.read_step_array(step, name), vb = b.read_step_array(step, name);
      ASSERT_EQ(va.size(), vb.size()) << name;
      for (std::size_t i = 0; i < va.size(); ++i, ++compared)
        ASSERT_EQ(va[i], vb[i]) << "step " << step << ' ' << name << '[' << i << ']';
    }
    // Called at every step but the last, which only records the final profile.
    EXPECT_EQ(b.read_step_array(step, "hook/called").at(0), step < 2 ? 1.0 : 0.0);
    if (step < 2) {
      EXPECT_EQ(b.read_text(ResultsFile::step_group(step) + "/hook/output").value_or(""),
                kStatesCsv);
    }
    EXPECT_EQ(b.read_step_array(step, "collective/weight").size(), 4u);
  }
  EXPECT_GT(compared, 1000u);
}

TEST_F(HookRunTest, TheProgramIsGivenTheStepsOwnProfiles) {
  write("states.csv", kStatesCsv);
  // Keeps a copy of every step's wheel and rail files beside the scene.
  const std::string scene =
      hook_scene(20e3, 10e3, 1e-3,
                 shell_hook("cp {wheel} seen_wheel_{step}.csv && cp {rail} seen_rail.csv && "
                            "cp states.csv {collective}"));
  run_hook(scene, dir_ / "run.h5");
  const ResultsFile file = ResultsFile::read(dir_ / "run.h5");
  ASSERT_EQ(file.completed_steps(), 3);
  std::size_t compared = 0;
  EXPECT_FALSE(fs::exists(dir_ / "seen_wheel_2.csv"));  // the last step makes no call
  for (int step = 0; step < 2; ++step) {
    const auto y = file.read_step_array(step, "wheel/y"), z = file.read_step_array(step, "wheel/z");
    const profiles::RawProfile seen =
        profiles::read_profile_file(dir_ / ("seen_wheel_" + std::to_string(step) + ".csv"));
    ASSERT_EQ(seen.points.size(), y.size()) << "step " << step;
    // Shortest round-trip decimals in mm: the points come back to within a few ulp.
    for (std::size_t i = 0; i < y.size(); ++i, compared += 2) {
      EXPECT_NEAR(seen.points[i].x(), y[i], 1e-15) << "step " << step << " point " << i;
      EXPECT_NEAR(seen.points[i].y(), z[i], 1e-15) << "step " << step << " point " << i;
    }
  }
  // The wheel does wear between the calls, so the files differ from step to step.
  const auto z0 = file.read_step_array(0, "wheel/z"), z2 = file.read_step_array(1, "wheel/z");
  double moved = 0.0;
  for (std::size_t i = 0; i < std::min(z0.size(), z2.size()); ++i)
    moved = std::max(moved, std::abs(z2[i] - z0[i]));
  EXPECT_GT(moved, 1e-6);
  EXPECT_TRUE(profiles::read_profile_file(dir_ / "seen_rail.csv").body == profiles::Body::rail);
  EXPECT_GT(compared, 1000u);
}

// profile_format = "simpack": the program gets SIMPACK files (.prw, .prr) that the project's
// own reader takes back to the run's profile.
TEST_F(HookRunTest, SimpackFilesCarryTheSameProfile) {
  write("states.csv", kStatesCsv);
  run_hook(hook_scene(10e3, 10e3, 1e-3,
                      "[hook]\ncommand = [\"cp\", \"states.csv\", \"{collective}\"]\n"
                      "profile_format = \"simpack\"\n"),
           dir_ / "run.h5");
  const fs::path step = hook_directory(dir_ / "run.h5") / "step_000000";
  ASSERT_TRUE(fs::exists(step / "wheel_left.prw"));
  ASSERT_TRUE(fs::exists(step / "rail.prr"));
  const ResultsFile file = ResultsFile::read(dir_ / "run.h5");
  const auto y = file.read_step_array(0, "wheel/y"), z = file.read_step_array(0, "wheel/z");
  const profiles::RawProfile seen = profiles::read_profile_file(step / "wheel_left.prw");
  ASSERT_EQ(seen.points.size(), y.size());
  EXPECT_TRUE(seen.body == profiles::Body::wheel);
  double worst = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i)
    worst =
        std::max({worst, std::abs(seen.points[i].x() - y[i]), std::abs(seen.points[i].y() - z[i])});
  EXPECT_LT(worst, 1e-12);  // shortest round-trip decimals in mm
  EXPECT_TRUE(profiles::read_profile_file(step / "rail.prr").body == profiles::Body::rail);
}

TEST_F(HookRunTest, ItIsCalledAgainOnlyOnceTheWearReachesItsDepth) {
  write("states.csv", kStatesCsv);
  // About 8 um of wear per 20 km step: a depth of 20 um lets two steps pass between calls.
  run_hook(hook_scene(200e3, 20e3, 0.1e-3,
                      "[hook]\ncommand = [\"cp\", \"states.csv\", \"{collective}\"]\n"
                      "resolve_depth_m = 20e-6\n"),
           dir_ / "run.h5");
  const ResultsFile file = ResultsFile::read(dir_ / "run.h5");
  ASSERT_GE(file.completed_steps(), 6);
  double since = 0.0;
  int calls = 0;
  for (int step = 0; step < file.completed_steps(); ++step) {
    const bool called = file.read_step_array(step, "hook/called").at(0) == 1.0;
    calls += called ? 1 : 0;
    const bool last = step == file.completed_steps() - 1;
    EXPECT_EQ(called, step == 0 || (since >= 20e-6 && !last)) << "step " << step;
    if (called) since = 0.0;
    const double depth = file.read_step_array(step, "hook/depth_since_call").at(0);
    EXPECT_GE(depth, since) << "step " << step;
    since = depth;
  }
  EXPECT_GE(calls, 2);
  EXPECT_LT(calls, file.completed_steps() - 1);
}

TEST_F(HookRunTest, WithoutAllowHookTheRunIsRefusedBeforeAnyFile) {
  write("states.csv", kStatesCsv);
  const std::string scene = hook_scene(
      20e3, 10e3, 1e-3, "[hook]\ncommand = [\"cp\", \"states.csv\", \"{collective}\"]\n");
  try {
    run_hook(scene, dir_ / "run.h5", false);
    FAIL() << "a hook ran without --allow-hook";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--allow-hook"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "run.h5"));
  EXPECT_FALSE(fs::exists(hook_directory(dir_ / "run.h5")));
}

TEST_F(HookRunTest, AFailingProgramStopsTheRunKeepingTheStepsBeforeAndResumeGoesOn) {
  write("states.csv", kStatesCsv);
  write("fail_once", "");
  // Fails at step 1 while fail_once exists, removing it: the resumed run's call succeeds.
  const std::string scene =
      hook_scene(30e3, 10e3, 1e-3,
                 shell_hook("if [ {step} -eq 1 ] && [ -e fail_once ]; then rm fail_once; "
                            "echo model diverged >&2; exit 3; fi; cp states.csv {collective}"));
  try {
    run_hook(scene, dir_ / "run.h5");
    FAIL() << "the run went past a failing hook";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("exited with status 3"), std::string::npos) << message;
    EXPECT_NE(message.find("model diverged"), std::string::npos) << message;
  }
  EXPECT_EQ(ResultsFile::read(dir_ / "run.h5").completed_steps(), 1);
  RunOptions options;
  options.allow_hook = true;
  resume_run(dir_ / "run.h5", options);
  run_hook(scene, dir_ / "whole.h5");
  const ResultsFile resumed = ResultsFile::read(dir_ / "run.h5"),
                    whole = ResultsFile::read(dir_ / "whole.h5");
  ASSERT_EQ(resumed.completed_steps(), 4);
  ASSERT_EQ(whole.completed_steps(), 4);
  for (int step = 0; step < 4; ++step) {
    const auto a = resumed.read_step_array(step, "wheel/z"),
               b = whole.read_step_array(step, "wheel/z");
    ASSERT_EQ(a, b) << "step " << step;
  }
}

TEST_F(HookRunTest, ProgramsThatHangDoNotStartOrWriteNothingAreNamed) {
  write("states.csv", kStatesCsv);
  struct Case {
    std::string hook, expected;
  };
  const std::vector<Case> cases{
      {shell_hook("sleep 20; cp states.csv {collective}", "timeout_s = 0.3\n"), "timeout"},
      {"[hook]\ncommand = [\"no-such-program-of-wheelwear\", \"{collective}\"]\n",
       "cannot start no-such-program-of-wheelwear"},
      {shell_hook("echo {collective}"), "wrote no collective"},
      {shell_hook("echo label,weight > {collective}"), "no state with a weight > 0"},
      {shell_hook("echo nonsense > {collective}"), "nonsense"},
  };
  int n = 0;
  for (const Case& c : cases) {
    const fs::path out = dir_ / ("run" + std::to_string(n++) + ".h5");
    try {
      run_hook(hook_scene(20e3, 10e3, 1e-3, c.hook), out);
      ADD_FAILURE() << "accepted: " << c.hook;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos)
          << c.hook << "\n -> " << e.what();
    }
  }
}

// A program that runs past its timeout is ended with everything it started: its process group.
TEST_F(HookRunTest, ATimeoutEndsWhatTheProgramStarted) {
  write("states.csv", kStatesCsv);
  try {
    run_hook(hook_scene(20e3, 10e3, 1e-3,
                        shell_hook("sleep 30 & echo $! > grandchild.pid; wait; "
                                   "cp states.csv {collective}",
                                   "timeout_s = 0.5\n")),
             dir_ / "run.h5");
    FAIL() << "the run went past a hook that hangs";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("timeout"), std::string::npos) << e.what();
  }
  std::ifstream in(dir_ / "grandchild.pid");
  long pid = 0;
  ASSERT_TRUE(in >> pid);
  // Gone, or a zombie nobody has reaped yet (its parent, the shell, was killed with it); SIGKILL
  // takes a moment to land, so look for up to 2 s.
  const fs::path stat = fs::path("/proc") / std::to_string(pid) / "stat";
  std::string state = "?";
  for (int i = 0; i < 200 && !(state.empty() || state == "Z"); ++i) {
    state.clear();
    if (std::ifstream proc(stat); proc) {
      std::string line;
      std::getline(proc, line);
      state = line.substr(line.rfind(')') + 2, 1);
    }
    if (!(state.empty() || state == "Z"))
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(state.empty() || state == "Z") << "the program's child is still running: " << state;
}

// A killed run resumed between two calls wears with the last call's collective as the program
// wrote it, creepage columns included (the step records leave those out), as the uninterrupted
// run does.
TEST_F(HookRunTest, AKilledRunResumedBetweenCallsKeepsTheProgramsCreepages) {
  write("states.csv",
        "label,dy_m,yaw_rad,axle_load_N,speed_m_s,vx_left,vy_left,spin_left_1_m,vx_right,"
        "vy_right,spin_right_1_m,weight\n"
        "tangent,0.001,2e-4,110e3,40,1e-3,-5e-4,0.1,-1e-3,5e-4,-0.1,3\n"
        "curve,0.004,1e-3,110e3,30,2e-3,-1e-3,0.3,-2e-3,1e-3,-0.3,1\n");
  // One call every 50 um of wear: several steps between calls.
  const std::string text = hook_scene(
      400e3, 10e3, 1e-3,
      "[hook]\ncommand = [\"cp\", \"states.csv\", \"{collective}\"]\nresolve_depth_m = 50e-6\n");
  const fs::path scene = write("hook.toml", text);
  const fs::path reference = dir_ / "reference.h5", killed = dir_ / "killed.h5";
  ASSERT_EQ(
      testing::run_wheelwear("run " + scene.string() + " -q --allow-hook -o " + reference.string())
          .exit_code,
      0);
  const ResultsFile whole = ResultsFile::read(reference);
  const int total = whole.completed_steps();
  ASSERT_GT(total, 10);
  int calls = 0;
  for (int step = 0; step < total; ++step)
    calls += whole.read_step_array(step, "hook/called").at(0) > 0.0;
  ASSERT_GE(calls, 2);
  ASSERT_LE(calls, total / 3);

  // Killed once two steps are published: the first call was at step 0, the next comes later.
  const int status = kill_run_after_steps(
      {"run", scene.string(), "-q", "--allow-hook", "-o", killed.string()}, killed, 2);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  const int kept = ResultsFile::read(killed).completed_steps();
  ASSERT_GE(kept, 2);
  ASSERT_LT(kept, total);
  ASSERT_EQ(whole.read_step_array(kept, "hook/called").at(0), 0.0)
      << "the resumed run's first step calls the program: the test compares nothing";
  const auto resumed = testing::run_wheelwear("run -q --allow-hook --resume " + killed.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const ResultsFile again = ResultsFile::read(killed);
  ASSERT_EQ(again.completed_steps(), total);
  std::size_t compared = 0;
  for (int step = kept; step < total; ++step)
    for (const char* name : {"wheel/wear_rate/depth", "wheel/z"}) {
      const auto a = whole.read_step_array(step, name), b = again.read_step_array(step, name);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t i = 0; i < a.size(); ++i, ++compared)
        ASSERT_EQ(a[i], b[i]) << "step " << step << ' ' << name << '[' << i << ']';
    }
  EXPECT_GT(compared, 1000u);
}

TEST(HookScene, BadHookTablesAreRefusedNamingTheKey) {
  const std::string base = hook_scene(20e3, 10e3, 1e-3, "");
  struct Case {
    std::string hook, expected;
  };
  const std::vector<Case> cases{
      {"[hook]\ncommand = \"cp states.csv {collective}\"\n", "list of strings"},
      {"[hook]\ncommand = []\n", "list of strings"},
      {"[hook]\ncommand = [\"cp\", 3]\n", "list of strings"},
      {"[hook]\ncommand = [\"cp\", \"a\", \"b\"]\n", "{collective}"},
      {"[hook]\ncommand = [\"cp\", \"{wheels}\", \"{collective}\"]\n",
       "unknown placeholder {wheels}"},
      {"[hook]\ntimeout_s = 5\n", "no command"},
      {"[hook]\ncommand = [\"cp\", \"{collective}\"]\nprofile_format = \"dxf\"\n",
       "profile_format"},
      {"[hook]\ncommand = [\"cp\", \"{collective}\"]\n[load_collective]\nfile = \"s.csv\"\n",
       "both give the run's states"},
  };
  for (const Case& c : cases) {
    try {
      parse_scene(base + c.hook, fs::temp_directory_path(),
                  [](const fs::path&) { return std::string(kStatesCsv); });
      ADD_FAILURE() << "accepted: " << c.hook;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos)
          << c.hook << "\n -> " << e.what();
    }
  }
}

TEST(HookScene, ARelativeProgramPathIsTakenFromTheScenesDirectory) {
  const Scene scene = parse_scene(
      hook_scene(20e3, 10e3, 1e-3,
                 "[hook]\ncommand = [\"./mbs/batch.sh\", \"{wheel}\", \"{collective}\"]\n"
                 "profile_format = \"simpack\"\nresolve_depth_m = 0.1e-3\n"),
      "/data/study");
  ASSERT_TRUE(scene.hook);
  EXPECT_EQ(fs::path(scene.hook->command.front()).lexically_normal(),
            fs::path("/data/study/mbs/batch.sh"));
  EXPECT_EQ(scene.hook->working_directory, fs::path("/data/study"));
  EXPECT_EQ(scene.hook->profile_format, HookProfileFormat::simpack);
  EXPECT_EQ(scene.hook->resolve_depth, 0.1e-3);
  // A bare name is looked up on PATH, as a shell would.
  EXPECT_EQ(parse_scene(
                hook_scene(20e3, 10e3, 1e-3, "[hook]\ncommand = [\"python3\", \"{collective}\"]\n"),
                "/data/study")
                .hook->command.front(),
            "python3");
}

}  // namespace
}  // namespace wheelwear::pipeline
