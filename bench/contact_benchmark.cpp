// Wheel/rail contact: geometry + Kik-Piotrowski normal problem + SDEC regularisation for one
// position of an S1002 wheel on a 60E1 rail (1:40), 0.1 mm strips, Fz = 55 kN; a rolled wheel,
// as the rigid wheelset has on every call; the rigid wheelset itself, with and without a
// prescribed lateral force.

#include <benchmark/benchmark.h>

#include "wheelwear/contactgeom/kik_piotrowski.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"
#include "wheelwear/contactgeom/wheelset.hpp"
#include "wheelwear/profiles/rail_60e1.hpp"
#include "wheelwear/profiles/s1002.hpp"

namespace {

using namespace wheelwear;

const contactgeom::WheelRailPair& pair() {
  static const contactgeom::WheelRailPair p(profiles::s1002(), profiles::rail_60e1());
  return p;
}

// One wheel position at lateral shift range(0) (0.1 mm: tread at 0 and +-4 mm, flange root at
// 5.5 mm, flank at 7.2 mm) with the wheel rolled by `roll`; range(1) = 1: the Hertz-calibrated
// virtual penetration instead of Kik-Piotrowski's fixed 0.55.
void contact_geometry(benchmark::State& state, double roll) {
  contactgeom::WheelsetPose pose;
  pose.dy = static_cast<double>(state.range(0)) * 1e-4;
  pose.roll = roll;
  contactgeom::WheelRailOptions options;
  if (state.range(1) == 1) options.kp.penetration = contactgeom::KpPenetration::hertz_calibrated;
  std::size_t patches = 0;
  for (auto _ : state) {
    const auto contact = contactgeom::solve_wheel_rail(pair(), pose, 55e3, options);
    patches = contact.patches.size();
    benchmark::DoNotOptimize(contact.vertical_force);
  }
  state.counters["patches"] = static_cast<double>(patches);
}

void BM_ContactGeometry(benchmark::State& state) {
  contact_geometry(state, 0.0);
}
BENCHMARK(BM_ContactGeometry)
    ->ArgsProduct({{0, 40, -40, 55, 72}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

// The same with the wheel rolled by -0.5 mrad (what a wheelset 3 mm off centre has): the gap
// maps each rail point onto the unrolled wheel profile.
void BM_ContactGeometryRolled(benchmark::State& state) {
  contact_geometry(state, -0.5e-3);
}
BENCHMARK(BM_ContactGeometryRolled)->ArgsProduct({{0, 40, 55}, {0}})->Unit(benchmark::kMicrosecond);

// A rigid wheelset (both wheels, the roll from both touching) at a lateral shift (0.1 mm), 55 kN
// per wheel; range(1) = 1: the left wheel's lateral force prescribed at 20 kN.
void BM_Wheelset(benchmark::State& state) {
  const contactgeom::WheelsetOnTrack track{pair(), pair()};
  contactgeom::WheelsetState s;
  s.dy = static_cast<double>(state.range(0)) * 1e-4;
  s.vertical_force_left = s.vertical_force_right = 55e3;
  if (state.range(1) == 1) s.lateral_force_left = 20e3;
  contactgeom::WheelsetContact contact;
  for (auto _ : state) {
    contact = contactgeom::solve_wheelset(track, s);
    benchmark::DoNotOptimize(contact.left.vertical_force);
  }
  state.counters["roll_urad"] = contact.roll * 1e6;
  state.counters["touches"] = contact.touch_evaluations;
  state.counters["solves"] = contact.contact_solves;
}
BENCHMARK(BM_Wheelset)
    ->Args({0, 0})
    ->Args({30, 0})
    ->Args({60, 0})
    ->Args({60, 1})
    ->Unit(benchmark::kMicrosecond);

// The normal problem alone on a Hertzian gap of 121 strips of 0.1 mm (a 12 mm patch).
void BM_NormalKP(benchmark::State& state) {
  const int n = 121;
  std::vector<double> h(n), ax(n, 1.0 / (2 * 0.46));
  for (int j = 0; j < n; ++j) {
    const double s = (j - n / 2) * 1e-4;
    h[j] = s * s / (2 * 0.3);
  }
  contactgeom::GapStrips gap;
  gap.s_first = -(n / 2) * 1e-4;
  gap.ds = 1e-4;
  gap.h = h;
  gap.ax = ax;
  const double e_star = contactgeom::combined_modulus(200e9, 0.25);
  contactgeom::KpResult result;
  for (auto _ : state) {
    contactgeom::solve_kp_load(gap, e_star, 55e3, {}, result);
    benchmark::DoNotOptimize(result.approach);
  }
  state.counters["evaluations"] = result.evaluations;
}
BENCHMARK(BM_NormalKP)->Unit(benchmark::kMicrosecond);

}  // namespace
BENCHMARK_MAIN();
