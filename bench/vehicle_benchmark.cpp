// The vehicle: one wheelset's forces (both wheels' contacts, their loads met, FASTSIM-SDEC on
// every patch) and the quasi-static curving of the whole vehicle (18 unknowns), by direct
// evaluation of the contact chain and with a contact look-up table (and the table's build), on
// S1002 / 60E1 1:40.

#include <benchmark/benchmark.h>

#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/vehicle/quasi_static_curving.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"

namespace {

using namespace wheelwear;

vehicle::WheelsetModel standard_wheelset() {
  profiles::Rail60E1Options rail_options;
  rail_options.inclination = 0.025;
  const profiles::Profile rail = profiles::rail_60e1(rail_options);
  const profiles::Profile wheel = profiles::s1002();
  vehicle::WheelsetModel model{
      {contactgeom::WheelRailPair(wheel, rail), contactgeom::WheelRailPair(wheel, rail)}};
  for (contactgeom::WheelRailPair* p : {&model.track.left, &model.track.right}) {
    p->wheel_radius = 0.46;
    p->youngs_modulus = 200e9;
    p->poisson = 0.25;
  }
  return model;
}

vehicle::WheelsetModel tabulated(vehicle::WheelsetModel m) {
  m.table = std::make_shared<const contactgeom::WheelsetContactTable>(m.track, m.contact);
  return m;
}

void BM_ContactTableBuild(benchmark::State& state) {
  const vehicle::WheelsetModel m = standard_wheelset();
  std::size_t shifts = 0;
  int solves = 0;
  for (auto _ : state) {
    const contactgeom::WheelsetContactTable table(m.track, m.contact);
    shifts = table.shifts().size();
    solves = table.contact_solves();
    benchmark::DoNotOptimize(shifts);
  }
  state.counters["shifts"] = static_cast<double>(shifts);
  state.counters["contact_solves"] = solves;
}
BENCHMARK(BM_ContactTableBuild)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WheelsetForcesFlange(benchmark::State& state) {
  const vehicle::WheelsetModel m =
      state.range(0) ? tabulated(standard_wheelset()) : standard_wheelset();
  vehicle::WheelsetMotionState s;
  s.dy = 6.16e-3;
  s.yaw = 4.6e-3;
  s.spin = 20.0 / 0.46;
  int solves = 0;
  for (auto _ : state) {
    const vehicle::WheelsetForces f =
        vehicle::wheelset_forces(m, s, 52e3, 57e3, {20.0, 500.0, 0.3});
    solves += f.load_iterations;
    benchmark::DoNotOptimize(f.lateral);
  }
  state.counters["contact_solves"] = benchmark::Counter(solves, benchmark::Counter::kAvgIterations);
}
// Argument: 0 direct evaluation, 1 with the contact table.
BENCHMARK(BM_WheelsetForcesFlange)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_QuasiStaticCurving(benchmark::State& state) {
  const vehicle::Vehicle v = vehicle::default_vehicle();
  const vehicle::WheelsetModel m =
      state.range(1) ? tabulated(standard_wheelset()) : standard_wheelset();
  vehicle::SteadyCurve curve;
  curve.running = {20.0, static_cast<double>(state.range(0)), 0.3};
  curve.cant = 0.1;
  int evaluations = 0, iterations = 0;
  for (auto _ : state) {
    const vehicle::VehicleCurving c = vehicle::solve_vehicle_curving(v, {m, m, m, m}, curve);
    if (!c.converged) state.SkipWithError(c.message.c_str());
    evaluations += c.wheelset_evaluations;
    iterations += c.iterations;
  }
  state.counters["wheelset_evaluations"] =
      benchmark::Counter(evaluations, benchmark::Counter::kAvgIterations);
  state.counters["newton_iterations"] =
      benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
}
// Arguments: the curve radius [m]; 0 direct evaluation, 1 with the contact table (its build
// not included: BM_ContactTableBuild).
BENCHMARK(BM_QuasiStaticCurving)
    ->ArgsProduct({{500, 1500, 3000}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
