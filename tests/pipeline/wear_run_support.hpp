#pragma once
// What the wear-run tests share: a small scene, a fixture with its own folder, and profile
// geometry to check worn areas with.

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/wear_run.hpp"
#include "wheelwear/profiles/profile.hpp"

extern char** environ;

namespace wheelwear::pipeline {

namespace fs = std::filesystem;

// A small scene: tangent and curve states on both hands, flange contact with a lateral force.
inline std::string small_scene(double distance, double step, double max_depth, int grid = 12) {
  return "[contact]\ngrid_nx = " + std::to_string(grid) + "\ngrid_ny = " + std::to_string(grid) +
         "\nstrip_width_m = 0.2e-3\n"
         "[run]\ndistance_m = " +
         std::to_string(distance) + "\nstep_distance_m = " + std::to_string(step) +
         "\nmax_depth_step_m = " + std::to_string(max_depth) +
         "\n"
         "[[load_collective.state]]\nlabel = \"tangent\"\ndy_m = 0.001\nyaw_rad = 2e-4\n"
         "axle_load_N = 110e3\nspeed_m_s = 40\nlateral_velocity_m_s = 0.01\nweight = 3\n"
         "[[load_collective.state]]\nlabel = \"tangent\"\ndy_m = -0.002\nyaw_rad = -3e-4\n"
         "axle_load_N = 110e3\nspeed_m_s = 40\nweight = 3\n"
         "[[load_collective.state]]\nlabel = \"R1000\"\ndy_m = 0.004\nyaw_rad = 1e-3\n"
         "load_left_N = 60e3\nload_right_N = 50e3\nspeed_m_s = 30\ncurve_radius_m = 1000\n"
         "weight = 1\n"
         "[[load_collective.state]]\nlabel = \"R500\"\ndy_m = -0.0065\nyaw_rad = -2e-3\n"
         "load_left_N = 50e3\nload_right_N = 60e3\nlateral_force_right_N = 25e3\n"
         "speed_m_s = 22\ncurve_radius_m = -500\nweight = 1\n";
}

class WearRunTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("wheelwear_run_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  RunSummary run(const std::string& scene_text, const fs::path& out) const {
    return run_scene(parse_scene(scene_text, dir_), scene_text, dir_, false, out, {});
  }
  fs::path dir_;
};

// Runs `wheelwear` with `arguments` (after the executable) writing `output`, and kills it
// without warning once `steps` steps are published. Returns its wait status (WIFSIGNALED when it
// was killed, not ended on its own).
inline int kill_run_after_steps(const std::vector<std::string>& arguments, const fs::path& output,
                                int steps) {
  const std::string exe = WHEELWEAR_EXE;
  std::vector<std::string> words{exe};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (::posix_spawn(&pid, exe.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return 0;
  int published = 0;
  for (int i = 0; i < 3000 && published < steps; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (!fs::exists(output)) continue;
    try {
      published = ResultsFile::read(output).completed_steps();
    } catch (const InputError&) {
      // The file is being replaced right now: try again.
    }
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

// Every array of step `step` whose name starts with `prefix` holds the same values in `res` as
// in `ref`, NaN where NaN; `compared` counts the values.
inline void expect_same_arrays(const ResultsFile& ref, const ResultsFile& res, int step,
                               const std::string& prefix, int& compared) {
  for (const std::string& name : ref.step_array_names(step)) {
    if (name.rfind(prefix, 0) != 0) continue;
    const auto a = ref.read_step_array(step, name), b = res.read_step_array(step, name);
    ASSERT_EQ(a.size(), b.size()) << name;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (std::isnan(a[i]) && std::isnan(b[i])) continue;
      ASSERT_EQ(a[i], b[i]) << "step " << step << ' ' << name << '[' << i << ']';
      ++compared;
    }
  }
}

// Two runs' results are the same: as many steps, the same scene, and every array of every step
// bit for bit (expect_same_arrays).
inline void expect_identical_runs(const fs::path& a, const fs::path& b) {
  const ResultsFile fa = ResultsFile::read(a), fb = ResultsFile::read(b);
  ASSERT_EQ(fa.completed_steps(), fb.completed_steps());
  EXPECT_EQ(fa.scene_text(), fb.scene_text());
  int compared = 0;
  for (int step = 0; step < fa.completed_steps(); ++step) {
    expect_same_arrays(fa, fb, step, "", compared);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(compared, 0);
}

inline profiles::PointList points(const std::vector<double>& y, const std::vector<double>& z) {
  profiles::PointList p;
  for (std::size_t i = 0; i < y.size(); ++i) p.emplace_back(y[i], z[i]);
  return p;
}

// Arc length on `profile` between lateral positions y0 < y1 (on its upward-facing part).
inline double arc_between(const profiles::Profile& profile, double y0, double y1) {
  const auto a = profile.surface_at(y0), b = profile.surface_at(y1);
  return b->s - a->s;
}

// Area of the polygon between two profiles that share their unworn ends [m^2].
inline double area_between(const std::vector<double>& y0, const std::vector<double>& z0,
                           const std::vector<double>& y1, const std::vector<double>& z1) {
  std::vector<double> y = y0, z = z0;
  y.insert(y.end(), y1.rbegin(), y1.rend());
  z.insert(z.end(), z1.rbegin(), z1.rend());
  double twice = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const std::size_t j = (i + 1) % y.size();
    twice += y[i] * z[j] - y[j] * z[i];
  }
  return std::abs(0.5 * twice);
}

}  // namespace wheelwear::pipeline
