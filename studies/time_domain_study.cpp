// Convergence of a vehicle run's time-domain pieces in their numerical choices: the wear rate
// of the example scene (data/scenes/vehicle_route.toml: the built-in coach on the built-in
// 100 km line, new S1002 on 60E1) on new profiles, with the tangents' stretch length, the
// sample distance, the run-in and the irregularities' seed varied one at a time around the
// defaults, against a fine reference (800 m of each tangent, a sample every 0.25 m, 100 m of
// run-in). Writes bench/results/time_domain_study.csv (or the file given as the first argument):
// per variant the states, the time of the vehicle's solve and of the wear, the worn area per
// 10^5 km, the share of it from the time-domain pieces, and the wear rate's distance from the
// reference's.
//
//   build/studies/wheelwear_time_domain_study [CSV]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"

namespace {

using namespace wheelwear;
using Clock = std::chrono::steady_clock;

struct Variant {
  std::string name;  // which choice it varies
  pipeline::TimeDomainKeys keys;
};

pipeline::TimeDomainKeys keys(double tangent, double sample, double run_in, int seed) {
  pipeline::TimeDomainKeys k;
  k.tangent_length = tangent;
  k.sample_distance = sample;
  k.run_in = run_in;
  k.seed = static_cast<std::uint64_t>(seed);
  return k;
}

std::vector<Variant> variants() {
  std::vector<Variant> out{{"reference", keys(800.0, 0.25, 100.0, 1)}};
  for (double sample : {2.0, 1.0, 0.5, 0.25})
    out.push_back({"sample", keys(200.0, sample, 50.0, 1)});
  for (double tangent : {50.0, 100.0, 200.0, 400.0, 800.0})
    out.push_back({"tangent", keys(tangent, 0.5, 50.0, 1)});
  for (double run_in : {25.0, 50.0, 100.0}) out.push_back({"run_in", keys(200.0, 0.5, run_in, 1)});
  for (int seed = 1; seed <= 5; ++seed) out.push_back({"seed", keys(200.0, 0.5, 50.0, seed)});
  pipeline::TimeDomainKeys off;
  off.enabled = false;
  out.push_back({"quasi_static", off});
  return out;
}

struct Measured {
  std::size_t states = 0;
  double vehicle_s = 0.0, wear_s = 0.0;
  wear::WearDistribution rate;
  double piece_area = 0.0;  // worn area per metre from the pieces' states [m^2/m]
};

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Measured measure(const pipeline::Scene& scene, const pipeline::CollectiveEvaluator& evaluator,
                 const profiles::Profile& wheel, const pipeline::TimeDomainKeys& keys) {
  pipeline::VehicleRun run = *scene.vehicle_run;
  run.time_domain = keys;
  run.critical_speed = false;  // the time-domain choices alone
  Measured m;
  auto t0 = Clock::now();
  const pipeline::VehicleCollective v =
      pipeline::solve_vehicle_collective(run, evaluator.kernel(), {&wheel});
  m.vehicle_s = seconds_since(t0);
  m.states = v.states.size();
  t0 = Clock::now();
  m.rate = evaluator.evaluate({&wheel}, v.states).rate.at(0);
  m.wear_s = seconds_since(t0);
  // The pieces' part: their states alone (after the curves' in the collective), scaled back by
  // their share of the distance.
  std::size_t curve_states = 0;
  for (const pipeline::RouteCase& c : v.cases)
    if (c.share > 0.0) curve_states += run.worn_wheelsets().size();
  const std::vector<pipeline::WheelsetStateSpec> pieces(
      v.states.begin() + static_cast<std::ptrdiff_t>(curve_states), v.states.end());
  double piece_weight = 0.0, total_weight = 0.0;
  for (const pipeline::WheelsetStateSpec& s : v.states) total_weight += s.weight;
  for (const pipeline::WheelsetStateSpec& s : pieces) piece_weight += s.weight;
  if (!pieces.empty())
    m.piece_area =
        evaluator.evaluate({&wheel}, pieces).rate.at(0).area() * piece_weight / total_weight;
  return m;
}

// Largest |a - b| over the reference's peak, and the sum of |a - b| ds over its area.
std::pair<double, double> distance(const wear::WearDistribution& a,
                                   const wear::WearDistribution& ref) {
  double peak = 0.0, largest = 0.0, sum = 0.0;
  const std::size_t n = std::min(a.depth.size(), ref.depth.size());
  for (std::size_t k = 0; k < n; ++k) {
    peak = std::max(peak, ref.depth[k]);
    largest = std::max(largest, std::abs(a.depth[k] - ref.depth[k]));
    sum += std::abs(a.depth[k] - ref.depth[k]) * ref.ds;
  }
  return {largest / peak, sum / ref.area()};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string csv_path = argc > 1 ? argv[1] : WHEELWEAR_RESULTS "/time_domain_study.csv";
  const pipeline::Scene scene = pipeline::load_scene(WHEELWEAR_EXAMPLE_SCENE);
  const pipeline::CollectiveEvaluator evaluator(scene);
  const profiles::Profile wheel =
      profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
  const std::vector<Variant> list = variants();
  std::vector<Measured> results;
  for (const Variant& v : list) {
    results.push_back(measure(scene, evaluator, wheel, v.keys));
    const Measured& m = results.back();
    std::printf(
        "%-12s tangent %5.0f m  sample %4.2f m  run-in %3.0f m  seed %d: %6zu states, "
        "vehicle %5.2f s, wear %5.2f s, area %.4g m^2/m\n",
        v.name.c_str(), v.keys.tangent_length, v.keys.sample_distance, v.keys.run_in,
        static_cast<int>(v.keys.seed), m.states, m.vehicle_s, m.wear_s, m.rate.area());
  }
  std::ofstream csv(csv_path);
  csv << "variant,enabled,tangent_length_m,sample_distance_m,run_in_m,seed,states,vehicle_s,"
         "wear_s,worn_area_mm2_per_1e5km,piece_share,max_rate_difference,l1_rate_difference\n";
  const wear::WearDistribution& reference = results.front().rate;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const pipeline::TimeDomainKeys& k = list[i].keys;
    const Measured& m = results[i];
    const auto [largest, l1] = distance(m.rate, reference);
    char line[512];
    std::snprintf(line, sizeof line, "%s,%d,%g,%g,%g,%d,%zu,%.3f,%.3f,%.6g,%.4f,%.4f,%.4f\n",
                  list[i].name.c_str(), k.enabled ? 1 : 0, k.tangent_length, k.sample_distance,
                  k.run_in, static_cast<int>(k.seed), m.states, m.vehicle_s, m.wear_s,
                  m.rate.area() * 1e6 * 1e8, m.piece_area / m.rate.area(), largest, l1);
    csv << line;
  }
  std::printf("wrote %s\n", csv_path.c_str());
  return 0;
}
