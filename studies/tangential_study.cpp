// Where the wear lands and how much there is, by tangential method: one evaluation of the
// frozen-collective scene's collective (1000 states, S1002 on 60E1) on the new wheel with
// FASTSIM-SDEC, with "best" (FASTSIM-SDEC's distribution carried to the exact theory's totals
// by the book of tables) and with Kalker's exact theory on every patch, all on the scene's
// 30 x 30 grid. Writes bench/results/tangential_methods.csv (or the file given) with, per
// method:
//   method              fastsim | best | exact (the scene's tangential_method)
//   seconds             wall time of the evaluation on one thread (best of `repeats`)
//   patches, table_patches
//                       patches solved; of them, with totals from the tables
//   work_total_N        sum over patches of the frictional work per metre rolled [N = J/m]
//   worn_area_rate      worn cross-section per metre running [m^2/m] (weighted collective)
//   peak_rate, peak_s   the deepest wear rate [m/m] and its arc length on the wheel [m]
//   centroid_s          the wear's centroid in arc length [m]
//   l1_vs_exact         sum |rate - rate_exact| / sum rate_exact: how differently it spreads
//   work_ratio_p5, work_ratio_median, work_ratio_p95
//                       per-patch frictional work against the exact theory's, over patches
//                       with at least 1 % of the median work
//
//   build/studies/wheelwear_tangential_study [CSV] [--repeats N]

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/profiles/profile_source.hpp"

namespace {

using namespace wheelwear;

struct Outcome {
  std::string name;
  double seconds = 0.0;
  pipeline::CollectiveWear wear;
};

Outcome evaluate(pipeline::Scene scene, pipeline::TangentialMethod method, const char* name,
                 int repeats) {
  scene.tangential = method;
  const pipeline::CollectiveEvaluator evaluator(scene);
  const profiles::Profile wheel =
      profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
  Outcome out{name, 1e300, {}};
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    out.wear = evaluator.evaluate({&wheel});
    out.seconds = std::min(
        out.seconds, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return out;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::lround(p * static_cast<double>(v.size() - 1)))];
}

}  // namespace

// Every patch's frictional work [J/m] in the order state, wheel, patch (NaN where a patch was
// not solved): the same patches for every method, which share the geometry.
std::vector<double> patch_work(const pipeline::CollectiveWear& wear) {
  std::vector<double> work;
  for (const pipeline::StateOutcome& s : wear.states)
    for (const pipeline::WheelOutcome& w : s.wheels)
      for (const pipeline::PatchOutcome& p : w.patches)
        work.push_back(p.solved && w.usable() ? p.solution.frictional_work
                                              : std::numeric_limits<double>::quiet_NaN());
  return work;
}

int main(int argc, char** argv) {
  std::string csv = "bench/results/tangential_methods.csv";
  int repeats = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--repeats" && i + 1 < argc) {
      repeats = std::max(1, std::stoi(argv[++i]));
    } else if (!arg.empty() && arg[0] != '-') {
      csv = arg;
    } else {
      std::fprintf(stderr, "usage: wheelwear_tangential_study [CSV] [--repeats N]\n");
      return 2;
    }
  }
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const pipeline::Scene scene = pipeline::frozen_collective_scene();
  std::vector<Outcome> outcomes;
  for (const auto& [method, name] : {std::pair{pipeline::TangentialMethod::fastsim, "fastsim"},
                                     {pipeline::TangentialMethod::best, "best"},
                                     {pipeline::TangentialMethod::exact, "exact"}}) {
    outcomes.push_back(evaluate(scene, method, name, repeats));
    std::fprintf(stderr, "%s: %.2f s\n", name, outcomes.back().seconds);
  }
  const Outcome& exact = outcomes.back();
  const std::vector<double>& exact_rate = exact.wear.rate[0].depth;
  const std::vector<double> exact_work = patch_work(exact.wear);
  double median_exact_work = percentile(
      [&] {
        std::vector<double> w;
        for (double x : exact_work)
          if (std::isfinite(x)) w.push_back(x);
        return w;
      }(),
      0.5);

  std::ofstream out(csv);
  out << "method,seconds,patches,table_patches,work_total_N,worn_area_rate,peak_rate,peak_s,"
         "centroid_s,l1_vs_exact,work_ratio_p5,work_ratio_median,work_ratio_p95\n";
  for (const Outcome& o : outcomes) {
    const wear::WearDistribution& rate = o.wear.rate[0];
    double work = 0.0, sum = 0.0, moment = 0.0, l1 = 0.0, exact_sum = 0.0, peak = 0.0, peak_s = 0.0;
    for (double w : patch_work(o.wear))
      if (std::isfinite(w)) work += w;
    for (std::size_t k = 0; k < rate.depth.size(); ++k) {
      const double s = rate.s_first + static_cast<double>(k) * rate.ds;
      sum += rate.depth[k];
      moment += rate.depth[k] * s;
      l1 += std::abs(rate.depth[k] - exact_rate[k]);
      exact_sum += exact_rate[k];
      if (rate.depth[k] > peak) {
        peak = rate.depth[k];
        peak_s = s;
      }
    }
    std::vector<double> ratios;
    const std::vector<double> w = patch_work(o.wear);
    for (std::size_t k = 0; k < w.size(); ++k)
      if (std::isfinite(w[k]) && exact_work[k] > 0.01 * median_exact_work)
        ratios.push_back(w[k] / exact_work[k]);
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s,%.4g,%zu,%zu,%.6g,%.6g,%.6g,%.5f,%.5f,%.4f,%.4f,%.4f,%.4f\n", o.name.c_str(),
                  o.seconds, o.wear.patches, o.wear.table_patches, work, sum * rate.ds, peak,
                  peak_s, moment / sum, l1 / exact_sum, percentile(ratios, 0.05),
                  percentile(ratios, 0.5), percentile(ratios, 0.95));
    out << line;
    std::printf("%s", line);
  }
  return out ? 0 : 1;
}
