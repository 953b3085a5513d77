// The per-state kernel (pipeline::StateKernel): one wheelset state of the built-in default
// scene's kind on S1002/60E1 1:40, from its position to both wheels' contacts, tangential
// solutions and wear (30 x 30 FASTSIM-SDEC, USFD law). Arguments: the wheelset shift in 0.1 mm
// (0: tread on both wheels; 50: the left wheel in two-point contact; 72: on its flank), and the
// normal method (0 Kik-Piotrowski, 1 Hertz-calibrated).

#include <benchmark/benchmark.h>

#include <string>

#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/profiles/profile_source.hpp"

namespace {

using namespace wheelwear;

void BM_StateKernel(benchmark::State& state) {
  const double dy = static_cast<double>(state.range(0)) * 1e-4;
  const std::string method = state.range(1) == 1 ? "hertz-calibrated" : "kik-piotrowski";
  const pipeline::Scene scene =
      pipeline::parse_scene("[contact]\nnormal_method = \"" + method +
                                "\"\n[[load_collective.state]]\ndy_m = " + std::to_string(dy) +
                                "\naxle_load_N = 110e3\nspeed_m_s = 30\nyaw_rad = 1e-3\n",
                            {});
  const pipeline::StateKernel kernel(scene);
  const profiles::Profile wheel =
      profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
  const contactgeom::WheelsetOnTrack track{kernel.pair(wheel), kernel.pair(wheel)};
  std::size_t patches = 0;
  for (auto _ : state) {
    const pipeline::StateOutcome out = kernel.evaluate(track, scene.states[0]);
    patches = out.wheels[0].patches.size() + out.wheels[1].patches.size();
    benchmark::DoNotOptimize(out.roll);
  }
  state.counters["patches"] = static_cast<double>(patches);
  state.counters["states/s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_StateKernel)->ArgsProduct({{0, 50, 72}, {0, 1}})->Unit(benchmark::kMicrosecond);

}  // namespace
BENCHMARK_MAIN();
