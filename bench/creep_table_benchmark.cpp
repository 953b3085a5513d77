// The built-in book of creep-force tables (tangential::creep_table_forces): time of one call, goal
// <= 2 us. The calls cycle through a fixed set of 200 inputs inside the table's range: a/b
// from 0.3 to 4, psi of both signs, creepages in eight directions (longitudinal, lateral, spin
// and mixtures, with both signs of vx) at normalised magnitudes r = |(xi, eta, chi)| from 0.05
// (nearly linear) to 4 (mostly slip), so the stencils land in different cells of the table and
// the psi < 0 and vx < 0 symmetry branches are taken, as in a run over many contacts.
// BM_CreepTableTowardsSliding: the same call beyond the table's creepages, where it extrapolates
// towards full sliding (two lookups and one sum over the table's grid for the patch): wheel
// tread and flange patches (a/b 0.5 ... 25) under translational creepage at 1.2 ... 2.5 times
// the table's r_max. Inside the table, calls near full sliding (|F| above half the full-sliding
// limit's) also sum that limit over the table's grid: among BM_CreepTable's inputs, those at
// r = 2 and 4 in translation.
// The machine may be shared: run with --benchmark_repetitions=5 and read the "min" row.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "wheelwear/tangential/creep_table.hpp"

namespace {

using namespace wheelwear;

const tangential::Material kSteel{80e9, 0.25};

struct TableInput {
  contactgeom::Sdec patch;
  tangential::Creepages creepages;
  tangential::ContactLoad load;
};

// The inputs, each direction scaled to its target magnitude r and the shapes clamped into the
// table's range, so the set stays valid when the table is regenerated with another range.
// Empty without a built-in table.
std::vector<TableInput> table_inputs() {
  const tangential::CreepTableRange range = tangential::creep_table_range();
  std::vector<TableInput> inputs;
  if (range.r_max <= 0.0) return inputs;
  const tangential::ContactLoad load{40e3, 0.35};
  const double c = 5e-3;  // sqrt(ab) [m], a wheel-tread patch
  // Directions (vx [-], vy [-], phi [1/m]) before scaling; phi c is comparable with vx, vy.
  const std::array<tangential::Creepages, 8> directions = {{{1, 0, 0},
                                                            {0, 1, 0},
                                                            {0, 0, 1 / c},
                                                            {1, 1, 0},
                                                            {-1, 0.5, 0},
                                                            {0.3, -1, 0.5 / c},
                                                            {-0.5, 0.2, -1 / c},
                                                            {0.2, 0.4, 1 / c}}};
  const std::array<double, 5> magnitudes = {0.05, 0.3, 1.0, 2.0, 4.0};
  std::size_t k = 0;
  for (const double g : {0.3, 0.6, 1.0, 2.0, 4.0}) {
    const double a_over_b = std::clamp(g, range.a_over_b_min, range.a_over_b_max);
    for (const double psi : {-0.7, -0.3, 0.0, 0.4, 0.75}) {
      const contactgeom::Sdec patch{c * std::sqrt(a_over_b), c / std::sqrt(a_over_b),
                                    std::clamp(psi, -range.psi_max, range.psi_max)};
      for (const tangential::Creepages& d : directions) {
        const double target = std::min(magnitudes[k++ % magnitudes.size()], 0.9 * range.r_max);
        // r is linear in the creepages: scale the direction onto the target.
        const double s = target / tangential::creep_table_magnitude(patch, d, load, kSteel);
        inputs.push_back({patch, {s * d.vx, s * d.vy, s * d.phi}, load});
      }
    }
  }
  return inputs;
}

double minimum(const std::vector<double>& v) {
  return *std::min_element(v.begin(), v.end());
}

// One creep_table_forces call per iteration, cycling through the inputs: the reported time is
// the time per call.
void time_calls(benchmark::State& state, const std::vector<TableInput>& inputs) {
  std::size_t k = 0;
  for (auto _ : state) {
    const TableInput& in = inputs[k];
    k = k + 1 == inputs.size() ? 0 : k + 1;
    benchmark::DoNotOptimize(
        tangential::creep_table_forces(in.patch, in.creepages, in.load, kSteel));
  }
  state.counters["inputs"] = static_cast<double>(inputs.size());
}

void BM_CreepTable(benchmark::State& state) {
  const std::vector<TableInput> inputs = table_inputs();
  for (const TableInput& in : inputs) {
    if (!tangential::creep_table_covers(in.patch, in.creepages, in.load, kSteel)) {
      state.SkipWithError("an input is outside the creep table's range");
      return;
    }
  }
  time_calls(state, inputs);
}
BENCHMARK(BM_CreepTable)->Unit(benchmark::kMicrosecond)->ComputeStatistics("min", minimum);

// Inputs beyond r_max that the table answers (near full sliding); empty without a table.
std::vector<TableInput> sliding_inputs() {
  const tangential::CreepTableRange range = tangential::creep_table_range();
  std::vector<TableInput> inputs;
  if (range.r_max <= 0.0) return inputs;
  const tangential::ContactLoad load{40e3, 0.35};
  const double c = 5e-3;
  const std::array<tangential::Creepages, 4> directions = {
      {{1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {-1, 0.5, 0}}};
  for (const double g : {0.5, 1.0, 3.0, 10.0, 25.0}) {
    const double a_over_b = std::clamp(g, range.a_over_b_min, range.a_over_b_max);
    for (const double psi : {-0.4, 0.0, 0.6}) {
      const contactgeom::Sdec patch{c * std::sqrt(a_over_b), c / std::sqrt(a_over_b), psi};
      for (const tangential::Creepages& d : directions)
        for (const double beyond : {1.2, 1.6, 2.5}) {
          const double s =
              beyond * range.r_max / tangential::creep_table_magnitude(patch, d, load, kSteel);
          const TableInput in{patch, {s * d.vx, s * d.vy, s * d.phi}, load};
          if (tangential::creep_table_covers(in.patch, in.creepages, in.load, kSteel))
            inputs.push_back(in);
        }
    }
  }
  return inputs;
}

void BM_CreepTableTowardsSliding(benchmark::State& state) {
  const std::vector<TableInput> inputs = sliding_inputs();
  if (inputs.empty()) {
    state.SkipWithError("the table answers none of the inputs beyond its creepages");
    return;
  }
  time_calls(state, inputs);
}
BENCHMARK(BM_CreepTableTowardsSliding)
    ->Unit(benchmark::kMicrosecond)
    ->ComputeStatistics("min", minimum);

}  // namespace
