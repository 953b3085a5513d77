// Kalker's exact theory (steady rolling, FFT influence products) on the paper's reference
// case: g = 1, psi = 0.6, a = 4.25 mm, N = 37 830 N (p0 = 1000 MPa), mu = 0.35, G = 80 GPa,
// nu = 0.25, with the SDEC pressure prescribed, against grid size. "pure_spin": phi = 1 1/m
// (3/4 of the patch slips); "small_spin": phi = 0.2 1/m (mostly adhesion, the slowest to
// converge); "no_slip": the linear-theory solve vx = 1e-6 with mu = 1e6.
// The machine is shared: run with --benchmark_repetitions=5 and read the "min" rows.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "wheelwear/wear/exact/steady_rolling.hpp"

namespace {

using namespace wheelwear;

const contactgeom::Sdec kPatch{4.25e-3, 4.25e-3, 0.6};
const wear::Material kSteel{80e9, 0.25};

void run(benchmark::State& state, const wear::Creepages& v, const wear::ContactLoad& load) {
  wear::ExactOptions options;
  options.nx = options.ny = static_cast<int>(state.range(0));
  int iterations = 0, contact = 0;
  for (auto _ : state) {
    const wear::ExactSolution s = wear::exact_sdec(kPatch, v, load, kSteel, options);
    benchmark::DoNotOptimize(s.forces);
    iterations = s.iterations;
    contact = s.contact_elements;
  }
  state.counters["elements"] = static_cast<double>(options.nx * options.ny);
  state.counters["contact_elements"] = contact;
  state.counters["sweeps"] = iterations;
}

double minimum(const std::vector<double>& v) {
  return *std::min_element(v.begin(), v.end());
}

void BM_ExactSdecPureSpin(benchmark::State& state) {
  run(state, {0.0, 0.0, 1.0}, {37830.0, 0.35});
}
BENCHMARK(BM_ExactSdecPureSpin)
    ->Arg(20)
    ->Arg(40)
    ->Arg(80)
    ->Arg(120)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("min", minimum);

void BM_ExactSdecSmallSpin(benchmark::State& state) {
  run(state, {0.0, 0.0, 0.2}, {37830.0, 0.35});
}
BENCHMARK(BM_ExactSdecSmallSpin)
    ->Arg(40)
    ->Arg(80)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("min", minimum);

void BM_ExactSdecNoSlip(benchmark::State& state) {
  run(state, {1e-6, 0.0, 0.0}, {37830.0, 1e6});
}
BENCHMARK(BM_ExactSdecNoSlip)
    ->Arg(40)
    ->Arg(80)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("min", minimum);

}  // namespace

BENCHMARK_MAIN();
