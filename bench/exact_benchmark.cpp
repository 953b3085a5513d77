// Kalker's exact theory (steady rolling, FFT influence products) on the paper's reference
// case: g = 1, psi = 0.6, a = 4.25 mm, N = 37 830 N (p0 = 1000 MPa), mu = 0.35, G = 80 GPa,
// nu = 0.25, with the SDEC pressure prescribed, against grid size. "pure_spin": phi = 1 1/m
// (3/4 of the patch slips); "small_spin": phi = 0.2 1/m (mostly adhesion, the slowest to
// converge); "no_slip": the linear-theory solve vx = 1e-6 with mu = 1e6.
// The machine is shared: run with --benchmark_repetitions=5 and read the "min" rows.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "wheelwear/contactgeom/undeformed_distance.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/exact/wheel_rail_exact.hpp"

namespace {

using namespace wheelwear;

const contactgeom::Sdec kPatch{4.25e-3, 4.25e-3, 0.6};
const tangential::Material kSteel{80e9, 0.25};

void run(benchmark::State& state, const tangential::Creepages& v, const tangential::ContactLoad& load) {
  tangential::SdecGridOptions options;
  options.nx = options.ny = static_cast<int>(state.range(0));
  int iterations = 0, contact = 0;
  for (auto _ : state) {
    const tangential::ExactSolution s = tangential::exact_sdec(kPatch, v, load, kSteel, options);
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

// Kalker's exact theory on a wheel/rail patch (wheel_rail_exact.hpp): S1002 on 60E1 1:40, the
// wheelset 4 mm towards the field side (a tread patch, Fz = 55 kN), vx = 1e-3, phi = -0.1 1/m,
// mu = 0.35, range(0) x range(0) elements over 1.3 times the Kik-Piotrowski patch. The time
// holds the gap's sampling (one undeformed_distance per element), the normal problem twice
// (once to check the grid) and the tangential problem; "Gap" times the sampling alone.
namespace {

struct WheelRailCase {
  contactgeom::WheelRailPair pair{profiles::s1002(), profiles::rail_60e1()};
  contactgeom::WheelsetPose pose;
  contactgeom::WheelRailPatch patch;
  WheelRailCase() {
    pose.dy = -4e-3;
    patch = contactgeom::solve_wheel_rail(pair, pose, 55e3).patches.at(0);
  }
};

const WheelRailCase& wheel_rail_case() {
  static const WheelRailCase c;
  return c;
}

void BM_WheelRailExact(benchmark::State& state) {
  const WheelRailCase& c = wheel_rail_case();
  tangential::WheelRailExactOptions options;
  options.nx = options.ny = static_cast<int>(state.range(0));
  tangential::WheelRailExactSolution s;
  for (auto _ : state) {
    s = tangential::wheel_rail_exact(c.pair, c.pose, c.patch, {1e-3, 0.0, -0.1}, 0.35, options);
    benchmark::DoNotOptimize(s.rolling.forces);
  }
  state.counters["elements"] = static_cast<double>(options.nx * options.ny);
  state.counters["contact_elements"] = s.rolling.contact_elements;
  state.counters["normal_iterations"] = s.normal_iterations;
  state.counters["sweeps"] = s.rolling.iterations;
}
BENCHMARK(BM_WheelRailExact)
    ->Arg(40)
    ->Arg(80)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("min", minimum);

void BM_WheelRailExactGap(benchmark::State& state) {
  const WheelRailCase& c = wheel_rail_case();
  tangential::WheelRailExactOptions options;
  options.nx = options.ny = static_cast<int>(state.range(0));
  const tangential::ElementGrid grid = tangential::wheel_rail_exact_grid(c.patch, 0.0, options);
  const double y_O = -c.patch.y_rail, cos_delta = std::cos(c.patch.contact_angle);
  for (auto _ : state) {
    double sum = 0.0;
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        sum +=
            contactgeom::undeformed_distance(c.pair, c.pose, grid.x(i), y_O - grid.y(j) * cos_delta)
                .value_or(0.0);
    benchmark::DoNotOptimize(sum);
  }
  state.counters["elements"] = static_cast<double>(grid.size());
}
BENCHMARK(BM_WheelRailExactGap)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("min", minimum);

}  // namespace

BENCHMARK_MAIN();
