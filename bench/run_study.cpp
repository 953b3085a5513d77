// The whole-run benchmark: the built-in default scene (1000 wheelset states, 20 wear steps of
// 5 km) run with 1 and with 2 threads; writes bench/results/run_study.csv (or the file given as
// the first argument) and prints states x steps per second and the speed-up.
//
//   build/bench/wheelwear_run_study [CSV] [--steps N]
//
// The results files go to the system's temporary directory and are removed afterwards; the
// two runs must agree bit for bit (checked here too, on the last profile).

#include <tbb/global_control.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "wheelwear/pipeline/results_file.hpp"
#include "wheelwear/pipeline/wear_run.hpp"

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
  const fs::path out = fs::temp_directory_path() / ("wheelwear_run_study_" +
                                                    std::to_string(::getpid()) + ".h5");
  Measurement m;
  m.threads = threads;
  m.summary = pipeline::run_scene(scene, pipeline::default_scene_text(), {}, true, out,
                                  {true, {}});
  const auto file = pipeline::ResultsFile::read(out);
  m.last_profile = file.read_step_array(file.completed_steps() - 1, "wheel/z");
  fs::remove(out);
  return m;
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
  pipeline::Scene scene = pipeline::default_scene();
  scene.distance = scene.step_distance * steps;
  std::printf("default scene: %zu states, %d steps of %.0f m\n", scene.states.size(), steps,
              scene.step_distance);
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
  return identical ? 0 : 1;
}
