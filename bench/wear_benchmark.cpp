// Wear of one contact: FASTSIM-SDEC 50 x 50 with per-cell fields, the USFD or Archard law per
// cell, and the mapping of strip wear onto the wheel profile (an SDEC patch of a = 5 mm,
// b = 4 mm, psi = 0.4, N = 60 kN, mu = 0.3, vx = 1e-3, phi = 0.5 1/m, V = 20 m/s).
// Argument 0: the law (0 USFD, 1 Archard); argument 1: the field set (0 all, 1 wear).

#include <benchmark/benchmark.h>

#include <string>

#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/wear/wear_distribution.hpp"

namespace {

using namespace wheelwear;

void BM_WearPerContact(benchmark::State& state) {
  const contactgeom::Sdec patch{5e-3, 4e-3, 0.4};
  tangential::FastsimOptions options;
  options.nx = options.ny = 50;
  options.cell_fields = true;
  options.field_set = state.range(1) == 0 ? tangential::CellFieldSet::all : tangential::CellFieldSet::wear;
  const wear::WearLaw law = *wear::default_wear_law(state.range(0) == 0 ? "usfd" : "archard");
  wear::WearDistribution w = wear::WearDistribution::zeros(-20e-3, 0.1e-3, 401);
  tangential::TangentialSolution s;
  for (auto _ : state) {
    tangential::fastsim(tangential::FastsimMethod::sdec, patch, {1e-3, 0, 0.5}, {60e3, 0.3}, {80e9, 0.25},
                  options, s);
    wear::accumulate_wear(*s.fields, 20.0, law, {0.0, 0.46}, 1.0, w);
    benchmark::DoNotOptimize(w.depth.data());
  }
  state.SetLabel(std::string(state.range(0) == 0 ? "usfd" : "archard") +
                 (state.range(1) == 0 ? " all fields" : " wear fields"));
  state.counters["cells"] = options.nx * options.ny;
}
BENCHMARK(BM_WearPerContact)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->ArgNames({"law", "fields"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
