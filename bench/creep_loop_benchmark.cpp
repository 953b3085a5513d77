// The yardstick of the Python module's creep() overhead (bench/python_overhead.py): a creep
// curve of 1000 points, FASTSIM-SDEC on 50 x 50 cells, as a plain C++ loop over solve_patch on
// one thread, and the same through the front ends' CreepSolver (the checks both front ends make).

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "creep_request.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace {

using namespace wheelwear;

constexpr int kPoints = 1000;
const contactgeom::Sdec kPatch{6e-3, 3e-3, 0.4};
const tangential::ContactLoad kLoad{50e3, 0.3};
const tangential::Material kSteel{80e9, 0.25};

// Spin from 0 to 2 1/m: the curve python_overhead.py asks for.
double spin(int i) {
  return 2.0 * i / (kPoints - 1);
}

void BM_CreepCurveSolvePatch(benchmark::State& state) {
  const tangential::SolveOptions options;  // FASTSIM 50 x 50, as creep()'s default
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < kPoints; ++i)
      sum += tangential::solve_patch(tangential::Method::fastsim_sdec, kPatch, {0.0, 0.0, spin(i)},
                                     kLoad, kSteel, options)
                 .forces.Fy;
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(BM_CreepCurveSolvePatch)->Unit(benchmark::kMillisecond);

void BM_CreepCurveFrontEnd(benchmark::State& state) {
  const cli::CreepSolver solver(cli::CreepOptions{});
  std::vector<std::string> warnings;
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < kPoints; ++i) {
      const tangential::Creepages c{0.0, 0.0, spin(i)};
      cli::check_creep_inputs(kPatch, c, kLoad, warnings);
      sum += solver.solve(kPatch, c, kLoad, kSteel).forces.Fy;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
}
BENCHMARK(BM_CreepCurveFrontEnd)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
