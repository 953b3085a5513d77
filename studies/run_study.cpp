// The whole-run benchmark: the frozen-collective scene (1000 wheelset states, 20 wear steps of
// 5 km) run with 1 and with 2 threads; writes bench/results/run_study.csv (or the file given as
// the first argument) and prints states x steps per second and the speed-up.
//
//   build/studies/wheelwear_run_study [CSV] [--steps N]
//
// The results files go to the system's temporary directory and are removed afterwards; the
// two runs must agree bit for bit (checked here too, on the last profile).
//
// It also measures what the run saves by skipping work (bench/results/run_study_savings.csv):
// one evaluation of a collective in which every state recurs at a second speed, with and
// without reusing the contact geometry of equal positions; and a 2-step run with and without
// T gamma maps in the results file.

#include <tbb/global_control.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/wear_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"

namespace {

using namespace wheelwear;
namespace fs = std::filesystem;

struct Measurement {
  int threads = 0;
  pipeline::RunSummary summary;
  std::vector<double> last_profile;
};

Measurement measure(const pipeline::Scene& scene, int threads) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(threads));
  const fs::path out =
      fs::temp_directory_path() / ("wheelwear_run_study_" + std::to_string(::getpid()) + ".h5");
  Measurement m;
  m.threads = threads;
  m.summary =
      pipeline::run_scene(scene, pipeline::frozen_collective_text(), {}, false, out, {true, {}});
  const auto file = pipeline::ResultsFile::read(out);
  m.last_profile = file.read_step_array(file.completed_steps() - 1, "wheel/z");
  fs::remove(out);
  return m;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Seconds of one evaluation of `scene`'s collective on the new wheel, best of `repeats`.
double evaluation_seconds(const pipeline::Scene& scene, bool reuse, int repeats) {
  const pipeline::CollectiveEvaluator evaluator(scene, reuse);
  const profiles::Profile wheel =
      profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto result = evaluator.evaluate({&wheel});
    best = std::min(best, seconds_since(t0));
    if (result.rate.empty()) std::abort();
  }
  return best;
}

// Seconds of a 2-step run of `scene`, writing its results file.
double run_seconds(const pipeline::Scene& scene) {
  const fs::path out = fs::temp_directory_path() /
                       ("wheelwear_run_study_maps_" + std::to_string(::getpid()) + ".h5");
  const auto t0 = std::chrono::steady_clock::now();
  pipeline::run_scene(scene, "", {}, false, out, {true, {}});
  const double t = seconds_since(t0);
  std::printf("  (%s: %.1f MB)\n", out.filename().c_str(),
              static_cast<double>(fs::file_size(out)) / 1e6);
  fs::remove(out);
  return t;
}

void savings(const pipeline::Scene& base, const std::string& csv) {
  std::ofstream out(csv);
  out << "case,variant,seconds,note\n";
  // Every state twice, at its speed and at 80 % of it: the positions and loads repeat.
  pipeline::Scene twice = base;
  for (const auto& state : base.states) {
    auto slower = state;
    slower.speed *= 0.8;
    twice.states.push_back(slower);
  }
  const double with_reuse = evaluation_seconds(twice, true, 3);
  const double without = evaluation_seconds(twice, false, 3);
  std::printf("geometry reuse (2000 states, 1000 positions): %.3f s with, %.3f s without\n",
              with_reuse, without);
  out << "geometry_reuse,on," << with_reuse << ",2000 states at 1000 positions\n";
  out << "geometry_reuse,off," << without << ",2000 states at 1000 positions\n";

  pipeline::Scene two_steps = base;
  two_steps.distance = 2 * two_steps.step_distance;
  const double plain = run_seconds(two_steps);
  two_steps.tgamma_maps = true;
  const double maps = run_seconds(two_steps);
  std::printf("T gamma maps in the results file (2-step run): %.2f s without, %.2f s with\n", plain,
              maps);
  out << "tgamma_maps,off," << plain << ",2-step run of the frozen-collective scene\n";
  out << "tgamma_maps,on," << maps << ",2-step run of the frozen-collective scene\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string csv = "bench/results/run_study.csv";
  int steps = 20;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--steps" && i + 1 < argc) {
      steps = std::atoi(argv[++i]);
    } else {
      csv = arg;
    }
  }
  pipeline::Scene scene = pipeline::frozen_collective_scene();
  scene.distance = scene.step_distance * steps;
  std::printf("frozen-collective scene: %zu states, %d steps of %.0f m\n", scene.states.size(),
              steps, scene.step_distance);
  std::vector<Measurement> runs;
  for (int threads : {1, 2}) {
    runs.push_back(measure(scene, threads));
    const auto& s = runs.back().summary;
    std::printf("%d thread(s): %.2f s, %.0f states x steps per second, %zu geometries\n", threads,
                s.elapsed, static_cast<double>(s.evaluations) / s.elapsed, s.geometry_solves);
  }
  const double speedup = runs[0].summary.elapsed / runs[1].summary.elapsed;
  const bool identical = runs[0].last_profile == runs[1].last_profile;
  std::printf("speed-up 1 -> 2 threads: %.2f; results identical: %s\n", speedup,
              identical ? "yes" : "NO");
  std::ofstream out(csv);
  out << "threads,states,steps,evaluations,seconds,states_steps_per_second,speedup,"
         "geometry_solves,identical\n";
  for (const auto& m : runs) {
    out << m.threads << ',' << scene.states.size() << ',' << m.summary.steps << ','
        << m.summary.evaluations << ',' << m.summary.elapsed << ','
        << static_cast<double>(m.summary.evaluations) / m.summary.elapsed << ','
        << runs[0].summary.elapsed / m.summary.elapsed << ',' << m.summary.geometry_solves << ','
        << (identical ? 1 : 0) << '\n';
  }
  std::string savings_csv = csv;
  const auto dot = savings_csv.rfind(".csv");
  savings_csv.insert(dot == std::string::npos ? savings_csv.size() : dot, "_savings");
  savings(pipeline::frozen_collective_scene(), savings_csv);
  return identical ? 0 : 1;
}
