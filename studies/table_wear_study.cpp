// What evaluating a vehicle step's states on its contact tables costs in accuracy, and what it
// saves: the example scene (data/scenes/vehicle_route.toml: the built-in coach on the built-in
// 100 km line, with its time-domain pieces) solved on a new S1002 and on two worn S1002 wheels
// of a long run (tests/data/profiles/s1002_worn_*.csv), then its states evaluated twice on the
// same profiles: every contact solved directly (the reference) and interpolated in the tables the
// vehicle ran on ([vehicle] wear_from_table). Per wheel: the states, how many contacts the tables
// answered, the evaluation's time on one thread and on all, the worn area and frictional work of
// both, the largest difference of the wear rates over the reference's peak and their L1
// distance over its area, where the deepest wear lies, and the distance not worn. Writes
// bench/results/table_wear_study.csv (or the file given as the first argument).
//
//   build/studies/wheelwear_table_wear_study [CSV]

#include <tbb/global_control.h>

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
#include "wheelwear/profiles/profile_loader.hpp"
#include "wheelwear/profiles/profile_source.hpp"

namespace {

using namespace wheelwear;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Evaluated {
  pipeline::CollectiveWear wear;
  double seconds = 0.0;         // on all threads
  double seconds_serial = 0.0;  // on one thread
};

Evaluated evaluate(const pipeline::CollectiveEvaluator& evaluator, const profiles::Profile& wheel,
                   const pipeline::VehicleCollective& v, const pipeline::ContactTables* tables) {
  Evaluated e;
  auto t0 = Clock::now();
  e.wear = evaluator.evaluate({&wheel}, v.states, tables);
  e.seconds = seconds_since(t0);
  {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    t0 = Clock::now();
    evaluator.evaluate({&wheel}, v.states, tables);
    e.seconds_serial = seconds_since(t0);
  }
  return e;
}

double total_work(const pipeline::CollectiveWear& w, const std::vector<double>& shares) {
  double sum = 0.0;
  for (std::size_t i = 0; i < w.states.size(); ++i)
    for (const pipeline::WheelOutcome& wheel : w.states[i].wheels)
      for (const pipeline::PatchOutcome& p : wheel.patches)
        if (p.solved) sum += shares[i] * p.solution.frictional_work;
  return sum;
}

// Where the deepest wear rate lies on the profile's arc length [m].
double peak_position(const wear::WearDistribution& rate) {
  const auto it = std::max_element(rate.depth.begin(), rate.depth.end());
  return rate.s_first + static_cast<double>(it - rate.depth.begin()) * rate.ds;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string csv_path = argc > 1 ? argv[1] : WHEELWEAR_RESULTS "/table_wear_study.csv";
  pipeline::Scene scene = pipeline::load_scene(WHEELWEAR_EXAMPLE_SCENE);
  scene.state_summaries = true;  // the states' outcomes, for their frictional work
  scene.vehicle_run->critical_speed = false;
  const pipeline::CollectiveEvaluator evaluator(scene);
  struct Wheel {
    std::string name;
    profiles::Profile profile;
  };
  std::vector<Wheel> wheels;
  wheels.push_back(
      {"S1002 new", profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, {})});
  for (const char* km : {"33200", "64100"}) {
    profiles::LoadOptions options;
    options.read.body = profiles::Body::wheel;
    options.nominal_radius = scene.wheel_radius;  // the files carry no radius
    const std::string file =
        std::string(WHEELWEAR_TEST_DATA) + "/profiles/s1002_worn_" + km + "km.csv";
    wheels.push_back(
        {std::string("S1002 worn ") + km + " km", profiles::load_profile(file, options).profile});
  }
  std::ofstream csv(csv_path);
  csv << "wheel,states,table_contacts,vehicle_s,direct_s,table_s,direct_serial_s,table_serial_s,"
         "worn_area_direct_mm2_per_1e5km,worn_area_table_mm2_per_1e5km,work_direct_N,"
         "work_table_N,max_rate_difference,l1_rate_difference,peak_s_direct_mm,peak_s_table_mm,"
         "not_worn_direct,not_worn_table\n";
  for (const Wheel& w : wheels) {
    const auto t0 = Clock::now();
    const pipeline::VehicleCollective v =
        pipeline::solve_vehicle_collective(*scene.vehicle_run, evaluator.kernel(), {&w.profile});
    const double vehicle_s = seconds_since(t0);
    const Evaluated direct = evaluate(evaluator, w.profile, v, nullptr);
    const Evaluated table = evaluate(evaluator, w.profile, v, &v.contact_tables);
    const wear::WearDistribution& a = direct.wear.rate.at(0);
    const wear::WearDistribution& b = table.wear.rate.at(0);
    double peak = 0.0, largest = 0.0, l1 = 0.0;
    for (std::size_t k = 0; k < std::min(a.depth.size(), b.depth.size()); ++k) {
      peak = std::max(peak, a.depth[k]);
      largest = std::max(largest, std::abs(a.depth[k] - b.depth[k]));
      l1 += std::abs(a.depth[k] - b.depth[k]) * a.ds;
    }
    const std::vector<double> shares = pipeline::state_shares(v.states);
    char line[1024];
    std::snprintf(
        line, sizeof line,
        "%s,%zu,%zu,%.3f,%.3f,%.3f,%.3f,%.3f,%.6g,%.6g,%.6g,%.6g,%.5f,%.5f,%.2f,%.2f,"
        "%.5f,%.5f\n",
        w.name.c_str(), v.states.size(), table.wear.table_contacts, vehicle_s, direct.seconds,
        table.seconds, direct.seconds_serial, table.seconds_serial, a.area() * 1e14,
        b.area() * 1e14, total_work(direct.wear, shares), total_work(table.wear, shares),
        largest / peak, l1 / a.area(), peak_position(a) * 1e3, peak_position(b) * 1e3,
        direct.wear.dropped.dropped_patches_weight, table.wear.dropped.dropped_patches_weight);
    csv << line;
    std::printf("%s", line);
  }
  std::printf("wrote %s\n", csv_path.c_str());
  return 0;
}
