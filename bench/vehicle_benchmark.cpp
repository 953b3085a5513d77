// The vehicle: one wheelset's forces (both wheels' contacts, their loads met, FASTSIM-SDEC on
// every patch) and the quasi-static curving of the whole vehicle (18 unknowns), by direct
// evaluation of the contact chain and with a contact look-up table (and the table's build), on
// S1002 / 60E1 1:40.

#include <benchmark/benchmark.h>

#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"
#include "wheelwear/vehicle/quasi_static_curving.hpp"
#include "wheelwear/vehicle/vehicle_file.hpp"
#include "wheelwear/vehicle/vehicle_motion.hpp"
#include "wheelwear/vehicle/vehicle_stability.hpp"

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
  std::size_t shifts = 0, nodes = 0;
  int solves = 0;
  for (auto _ : state) {
    const contactgeom::WheelsetContactTable table(m.track, m.contact);
    shifts = table.shifts().size();
    nodes = shifts * table.loads().size();
    solves = table.contact_solves();
    benchmark::DoNotOptimize(shifts);
  }
  state.counters["shifts"] = static_cast<double>(shifts);
  state.counters["nodes"] = static_cast<double>(nodes);
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

// The time-domain simulation of the whole vehicle (18 degrees of freedom: lateral shift and yaw
// of 7 bodies, the spin of 4 axles; classical Runge-Kutta 4 at the automatic step) over 200 m of
// tangent track with ERRI B176 low-level irregularities at 30 m/s, with the contact table.
// Counter real_time_factor: simulated time over the wall-clock time of one core.
void BM_VehicleMotion(benchmark::State& state) {
  const vehicle::Vehicle v = vehicle::default_vehicle();
  const vehicle::WheelsetModel m = tabulated(standard_wheelset());
  vehicle::Route route;
  route.name = "tangent";
  vehicle::RouteSection section;
  section.length_m = 1000.0;
  section.speed_m_s = 30.0;
  route.sections.push_back(section);
  vehicle::IrregularitySpec spec;
  spec.run_in = 50.0;
  const vehicle::TrackIrregularities track =
      vehicle::generate_irregularities(spec, 1000.0, 0.25, 2024);
  vehicle::SteadyCurve tangent;
  tangent.running = {30.0, 0.0, 0.3};
  const vehicle::VehiclePlacement start =
      vehicle::placement_of(vehicle::solve_vehicle_curving(v, {m, m, m, m}, tangent));
  vehicle::VehicleMotionOptions options;
  options.fastsim_grid = static_cast<int>(state.range(0));
  const double length = 200.0;
  vehicle::VehicleMotion motion;
  for (auto _ : state) {
    motion =
        vehicle::simulate_vehicle(v, {m, m, m, m}, route, 100.0, length, track, start, options);
    if (!motion.completed) state.SkipWithError(motion.message.c_str());
  }
  state.counters["time_step_ms"] = 1e3 * motion.time_step;
  state.counters["steps"] = static_cast<double>(motion.steps);
  state.counters["wheelset_evaluations"] = static_cast<double>(motion.wheelset_evaluations);
  state.counters["simulated_s"] = length / 30.0;
  state.counters["real_time_factor"] =
      benchmark::Counter(length / 30.0, benchmark::Counter::kIsIterationInvariantRate);
}
// Argument: the FASTSIM grid of the dynamics (cells per strip and strips; 0: the model's 50).
BENCHMARK(BM_VehicleMotion)->Arg(20)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

// The whole vehicle's linearised motion at one speed (the Jacobian of its 32 states by central
// differences and its eigenvalues), and the search for its linear critical speed from 5 m/s in
// steps of 5 m/s (argument 0) or from 2 m/s below it in steps of 2 m/s (argument 1, a run's
// later solves), with the contact table on new S1002/60E1.
void BM_VehicleModes(benchmark::State& state) {
  const vehicle::Vehicle v = vehicle::default_vehicle();
  const vehicle::WheelsetModel m = tabulated(standard_wheelset());
  for (auto _ : state) benchmark::DoNotOptimize(vehicle::vehicle_modes(v, {m, m, m, m}, 44.44));
}
BENCHMARK(BM_VehicleModes)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_VehicleCriticalSpeed(benchmark::State& state) {
  const vehicle::Vehicle v = vehicle::default_vehicle();
  const vehicle::WheelsetModel m = tabulated(standard_wheelset());
  vehicle::VehicleStabilityOptions options;
  options.speed_step = 5.0;
  options.tolerance = 1e-3;
  if (state.range(0) == 1) {
    options.start_speed = vehicle::vehicle_critical_speed(v, {m, m, m, m}, options).speed - 2.0;
    options.speed_step = 2.0;
  }
  vehicle::CriticalSpeed c;
  for (auto _ : state) c = vehicle::vehicle_critical_speed(v, {m, m, m, m}, options);
  if (!c.found) state.SkipWithError("no critical speed below 100 m/s");
  state.counters["critical_speed_m_s"] = c.speed;
}
BENCHMARK(BM_VehicleCriticalSpeed)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
BENCHMARK_MAIN();
