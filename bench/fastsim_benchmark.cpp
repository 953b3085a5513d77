// FASTSIM-SDEC throughput on the paper's reference case: g = 1, psi = 0.6, pure spin
// phi = 1 1/m, a = 4.25 mm, N = 37 830 N, mu = 0.35, G = 80 GPa (forces only).

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "wheelwear/tangential/fastsim.hpp"
#include "wheelwear/tangential/sdec_coefficients.hpp"

namespace {

using namespace wheelwear;

const contactgeom::Sdec kPatch{4.25e-3, 4.25e-3, 0.6};
const tangential::Creepages kSpin{0.0, 0.0, 1.0};
const tangential::ContactLoad kLoad{37830.0, 0.35};
const tangential::Material kSteel{80e9, 0.25};

void BM_FastsimSdec(benchmark::State& state) {
  tangential::FastsimOptions options;
  options.nx = options.ny = static_cast<int>(state.range(0));
  for (auto _ : state) {
    auto solution = tangential::fastsim(tangential::FastsimMethod::sdec, kPatch, kSpin, kLoad, kSteel, options);
    benchmark::DoNotOptimize(solution.forces);
  }
  state.counters["cells"] = static_cast<double>(options.nx * options.ny);
  state.SetItemsProcessed(state.iterations() * options.nx * options.ny);  // cells per second
}
BENCHMARK(BM_FastsimSdec)->Arg(20)->Arg(50)->Arg(100);

void BM_FastsimSdecSecondOrder(benchmark::State& state) {
  tangential::FastsimOptions options;
  options.nx = options.ny = static_cast<int>(state.range(0));
  options.scheme = tangential::FastsimScheme::second_order;
  for (auto _ : state) {
    auto solution = tangential::fastsim(tangential::FastsimMethod::sdec, kPatch, kSpin, kLoad, kSteel, options);
    benchmark::DoNotOptimize(solution.forces);
  }
  state.SetItemsProcessed(state.iterations() * options.nx * options.ny);
}
BENCHMARK(BM_FastsimSdecSecondOrder)->Arg(20)->Arg(50);

// The yardstick: the same algorithm as a plain scalar loop, strip by strip, cell by cell,
// with the square root and division of the saturation test in every cell.
double scalar_fastsim_sdec_fx(int n) {
  const double a = kPatch.a, b = kPatch.b, psi = kPatch.psi, c = std::sqrt(a * b);
  const auto k = tangential::sdec_coefficients(kPatch, kSteel.nu);
  const double G = kSteel.G;
  const double l11 = 8 * a / (3 * G * k.c11s), l22 = 8 * a / (3 * G * k.c22s);
  const double l23 = std::numbers::pi * a * a / (4 * G * c * k.c23s), l13 = 2 * c / (G * k.row.k13);
  const double kb = kLoad.mu * 2 * kLoad.N / (std::numbers::pi * a * a * a * b);
  const double dy = 2 * b / n;
  double fx = 0, fy = 0;
  for (int j = 0; j < n; ++j) {
    const double y = -b * (1 - psi) + (j + 0.5) * dy;
    const double half = y > 0 ? b * (1 + psi) : b * (1 - psi);
    const double xl = a * std::sqrt(std::max(0.0, 1 - y * y / (half * half)));
    const double dx = 2 * xl / n;
    double px = 0, py = 0;
    for (int i = 0; i < n; ++i) {
      const double x = xl - (i + 1) * dx;
      px -= dx * (kSpin.vx / l11 - kSpin.phi * y / l13);
      py -= dx * (kSpin.vy / l22 + kSpin.phi * (x + 0.5 * dx) / l23);
      const double g = kb * (xl * xl - x * x);
      const double p = std::sqrt(px * px + py * py);
      if (p > g) {
        px *= g / p;
        py *= g / p;
      }
      fx += px * dx * dy;
      fy += py * dx * dy;
    }
  }
  return fx + 1e-30 * fy;
}

void BM_FastsimSdecScalarLoop(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(scalar_fastsim_sdec_fx(n));
}
BENCHMARK(BM_FastsimSdecScalarLoop)->Arg(20)->Arg(50)->Arg(100);

void BM_FastsimSdecWithFields(benchmark::State& state) {
  tangential::FastsimOptions options;
  options.nx = options.ny = static_cast<int>(state.range(0));
  options.cell_fields = true;
  for (auto _ : state) {
    auto solution = tangential::fastsim(tangential::FastsimMethod::sdec, kPatch, kSpin, kLoad, kSteel, options);
    benchmark::DoNotOptimize(solution.frictional_work);
  }
}
BENCHMARK(BM_FastsimSdecWithFields)->Arg(20)->Arg(50);

// The same with the solution's storage reused from call to call, as a loop over contacts does:
// no allocation per call.
void BM_FastsimSdecWithFieldsReused(benchmark::State& state) {
  tangential::FastsimOptions options;
  options.nx = options.ny = static_cast<int>(state.range(0));
  options.cell_fields = true;
  tangential::TangentialSolution solution;
  for (auto _ : state) {
    tangential::fastsim(tangential::FastsimMethod::sdec, kPatch, kSpin, kLoad, kSteel, options, solution);
    benchmark::DoNotOptimize(solution.frictional_work);
  }
  state.SetItemsProcessed(state.iterations() * options.nx * options.ny);
}
BENCHMARK(BM_FastsimSdecWithFieldsReused)->Arg(50);

}  // namespace
