// Wear of one contact: FASTSIM-SDEC 50 x 50 with per-cell fields, the USFD law per cell, and
// the mapping of strip wear onto the wheel profile (an SDEC patch of a = 5 mm, b = 4 mm,
// psi = 0.4, N = 60 kN, mu = 0.3, vx = 1e-3, phi = 0.5 1/m, V = 20 m/s).

#include <benchmark/benchmark.h>

#include "wheelwear/wear/fastsim.hpp"
#include "wheelwear/wear/wear_distribution.hpp"

namespace {

using namespace wheelwear;

void BM_WearPerContact(benchmark::State& state) {
  const contactgeom::Sdec patch{5e-3, 4e-3, 0.4};
  wear::FastsimOptions options;
  options.nx = options.ny = 50;
  options.cell_fields = true;
  const wear::WearLaw law = *wear::default_wear_law(state.range(0) == 0 ? "usfd" : "archard");
  wear::WearDistribution w = wear::WearDistribution::zeros(-20e-3, 0.1e-3, 401);
  wear::TangentialSolution s;
  for (auto _ : state) {
    wear::fastsim(wear::FastsimMethod::sdec, patch, {1e-3, 0, 0.5}, {60e3, 0.3}, {80e9, 0.25},
                  options, s);
    wear::accumulate_wear(*s.fields, 20.0, law, {0.0, 0.46}, 1.0, w);
    benchmark::DoNotOptimize(w.depth.data());
  }
  state.SetLabel(state.range(0) == 0 ? "usfd" : "archard");
}
BENCHMARK(BM_WearPerContact)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
