// The per-state kernel (pipeline::StateKernel): one wheelset state of the frozen-collective
// scene's kind on S1002/60E1 1:40, from its position to both wheels' contacts, tangential
// solutions and wear (30 x 30 FASTSIM-SDEC, USFD law). BM_StateKernel's arguments: the wheelset
// shift in 0.1 mm (0: tread on both wheels; 50: the left wheel in two-point contact; 72: on its
// flank), and the normal method (0 Kik-Piotrowski, 1 Hertz-calibrated). BM_StateKernelFromTable
// takes the contact from the wheelset's contact table instead (shift 60: the flange root), whose
// build BM_ContactTableBuild measures.

#include <benchmark/benchmark.h>

#include <string>

#include "wheelwear/contactgeom/wheelset_table.hpp"
#include "wheelwear/pipeline/state_kernel.hpp"
#include "wheelwear/profiles/profile_source.hpp"

namespace {

using namespace wheelwear;

// One state (110 kN, 30 m/s, 1 mrad of yaw) at shift `dy` [m] on the built-in S1002/60E1 1:40,
// with the kernel, the wheel and its wheelset on the track.
struct DefaultState {
  pipeline::Scene scene;
  pipeline::StateKernel kernel;
  profiles::Profile wheel;
  contactgeom::WheelsetOnTrack track;

  DefaultState(double dy, const std::string& method)
      : scene(pipeline::parse_scene(
            "[contact]\nnormal_method = \"" + method + "\"\n[[load_collective.state]]\ndy_m = " +
                std::to_string(dy) + "\naxle_load_N = 110e3\nspeed_m_s = 30\nyaw_rad = 1e-3\n",
            {})),
        kernel(scene),
        wheel(profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file)),
        track{kernel.pair(wheel), kernel.pair(wheel)} {}
  const pipeline::WheelsetStateSpec& spec() const { return scene.states[0]; }
};

void BM_StateKernel(benchmark::State& state) {
  const DefaultState s(static_cast<double>(state.range(0)) * 1e-4,
                       state.range(1) == 1 ? "hertz-calibrated" : "kik-piotrowski");
  std::size_t patches = 0;
  for (auto _ : state) {
    const pipeline::StateOutcome out = s.kernel.evaluate(s.track, s.spec());
    patches = out.wheels[0].patches.size() + out.wheels[1].patches.size();
    benchmark::DoNotOptimize(out.roll);
  }
  state.counters["patches"] = static_cast<double>(patches);
  state.counters["states/s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_StateKernel)->ArgsProduct({{0, 50, 72}, {0, 1}})->Unit(benchmark::kMicrosecond);

// The table of the default wheelset (WheelsetTableOptions' defaults: shifts of +-16 mm refined
// where interpolation misses, 10 to 200 kN of wheel load), built once.
const contactgeom::WheelsetContactTable& default_table(const DefaultState& s) {
  static const contactgeom::WheelsetContactTable table(s.track, s.kernel.contact_options());
  return table;
}

// The same states with their contact interpolated in that table, as a vehicle run's step
// evaluates its states ([vehicle] wear_from_table): the table's build is BM_ContactTableBuild's,
// counted apart.
void BM_StateKernelFromTable(benchmark::State& state) {
  const DefaultState s(static_cast<double>(state.range(0)) * 1e-4, "hertz-calibrated");
  const contactgeom::WheelsetContactTable& table = default_table(s);
  bool interpolated = false;
  for (auto _ : state) {
    const contactgeom::WheelsetContact both =
        s.kernel.contact(s.track, s.spec(), &table, &interpolated);
    for (int side = 0; side < 2; ++side) {
      const pipeline::WheelOutcome out = s.kernel.wheel(both, side, s.spec(), s.wheel);
      benchmark::DoNotOptimize(out.dy);
    }
  }
  if (!interpolated) state.SkipWithError("the table did not answer");
  state.counters["wheels/s"] =
      benchmark::Counter(2.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_StateKernelFromTable)->Arg(0)->Arg(50)->Arg(60)->Unit(benchmark::kMicrosecond);

// Building that table, on every core.
void BM_ContactTableBuild(benchmark::State& state) {
  const DefaultState s(0.0, "hertz-calibrated");
  std::size_t nodes = 0;
  for (auto _ : state) {
    const contactgeom::WheelsetContactTable table(s.track, s.kernel.contact_options());
    nodes = table.shifts().size() * table.loads().size();
  }
  state.counters["nodes"] = static_cast<double>(nodes);
}
BENCHMARK(BM_ContactTableBuild)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
BENCHMARK_MAIN();
