// Which patches of real runs the book of creep-force tables covers (tangential_method = "best"),
// and the shapes it would have to cover to answer for nearly all of a run's frictional work:
// every state of three collectives evaluated once on new profiles with "best", each patch's SDEC
// shape (a/b, psi) and its frictional work recorded.
//   - "frozen": the frozen-collective scene's states (data/scenes/frozen_collective.csv);
//   - "vehicle": the example scene's vehicle on its route (data/scenes/vehicle_route.toml, new
//     S1002/60E1 1:40, time-domain pieces included);
//   - "flange sweep": one wheelset at shifts 6 ... 8 mm in 0.05 mm (flange root to flank),
//     55 kN per wheel, 30 m/s, 5 mrad of yaw (an angle of attack of a leading wheelset in a
//     tight curve).
// Per collective: the patches, their frictional work per metre, the share of it the table
// answered, the shares outside its a/b range, outside its |psi| range and inside both but outside
// what it answers of the creepages (beyond its largest normalised creepage and short of full
// sliding there, or nu), the work-weighted 1st, 50th and 99th percentiles of a/b and the 99th of
// |psi|, and the share of the work on patches with 0.05 <= a/b <= 25 and |psi| <= 0.9. Writes
// bench/results/table_coverage.csv (or the file given as the first argument).
//
//   build/studies/wheelwear_table_coverage_study [CSV]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "wheelwear/pipeline/collective_wear.hpp"
#include "wheelwear/pipeline/scene.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/tangential/creep_table.hpp"

namespace {

using namespace wheelwear;

struct PatchRecord {
  double ab = 0.0, psi = 0.0, work = 0.0;  // work: share-weighted [N]
  bool from_table = false;
};

// Every solved patch of an evaluation of `specs`, its work weighted by its state's share.
std::vector<PatchRecord> patches_of(const pipeline::CollectiveEvaluator& evaluator,
                                    const profiles::Profile& wheel,
                                    const std::vector<pipeline::WheelsetStateSpec>& specs) {
  const pipeline::CollectiveWear w = evaluator.evaluate({&wheel}, specs);
  const std::vector<double> shares = pipeline::state_shares(specs);
  std::vector<PatchRecord> out;
  for (std::size_t i = 0; i < w.states.size(); ++i)
    for (const pipeline::WheelOutcome& side : w.states[i].wheels)
      for (const pipeline::PatchOutcome& p : side.patches)
        if (p.solved)
          out.push_back({p.sdec.a / p.sdec.b, p.sdec.psi, shares[i] * p.solution.frictional_work,
                         p.solution.from_table});
  return out;
}

// The work-weighted quantile q of value(p) over `patches`.
template <class Value>
double quantile(std::vector<PatchRecord> patches, double q, Value value) {
  std::sort(patches.begin(), patches.end(),
            [&](const PatchRecord& a, const PatchRecord& b) { return value(a) < value(b); });
  double total = 0.0;
  for (const PatchRecord& p : patches) total += p.work;
  double sum = 0.0;
  for (const PatchRecord& p : patches) {
    sum += p.work;
    if (sum >= q * total) return value(p);
  }
  return patches.empty() ? NAN : value(patches.back());
}

// The collective's line of the CSV; `nu` its scene's Poisson's ratio (the table's groups may
// differ in the a/b they reach).
std::string row(const std::string& name, const std::vector<PatchRecord>& patches, double nu) {
  const tangential::CreepTableRange range = tangential::creep_table_range(nu);
  double total = 0.0, table = 0.0, ab_out = 0.0, psi_out = 0.0, creep_out = 0.0, target = 0.0;
  for (const PatchRecord& p : patches) {
    total += p.work;
    const bool ab_in = p.ab >= range.a_over_b_min && p.ab <= range.a_over_b_max,
               psi_in = std::abs(p.psi) <= range.psi_max;
    if (p.from_table) table += p.work;
    if (!ab_in) ab_out += p.work;
    if (ab_in && !psi_in) psi_out += p.work;
    if (ab_in && psi_in && !p.from_table) creep_out += p.work;
    if (p.ab >= 0.05 && p.ab <= 25.0 && std::abs(p.psi) <= 0.9) target += p.work;
  }
  const auto ab = [](const PatchRecord& p) { return p.ab; };
  const auto psi = [](const PatchRecord& p) { return std::abs(p.psi); };
  char line[512];
  std::snprintf(line, sizeof line, "%s,%zu,%.6g,%.5f,%.5f,%.5f,%.5f,%.4g,%.4g,%.4g,%.4g,%.5f\n",
                name.c_str(), patches.size(), total, table / total, ab_out / total, psi_out / total,
                creep_out / total, quantile(patches, 0.01, ab), quantile(patches, 0.5, ab),
                quantile(patches, 0.99, ab), quantile(patches, 0.99, psi), target / total);
  return line;
}

pipeline::Scene with_best(pipeline::Scene scene) {
  scene.tangential = pipeline::TangentialMethod::best;
  scene.state_summaries = true;  // the states' outcomes, for their patches
  return scene;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string csv_path = argc > 1 ? argv[1] : WHEELWEAR_RESULTS "/table_coverage.csv";
  std::ofstream csv(csv_path);
  csv << "collective,patches,work_N,share_from_table,share_outside_ab,share_outside_psi,"
         "share_outside_creepage,ab_p01,ab_p50,ab_p99,abs_psi_p99,share_ab_0.05_25_psi_0.9\n";
  const auto emit = [&](const std::string& name, const std::vector<PatchRecord>& patches,
                        double nu) {
    const std::string line = row(name, patches, nu);
    csv << line;
    std::printf("%s", line.c_str());
  };
  {
    const pipeline::Scene scene = with_best(pipeline::load_scene(WHEELWEAR_FROZEN_SCENE));
    const pipeline::CollectiveEvaluator evaluator(scene);
    const profiles::Profile wheel =
        profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
    emit("frozen", patches_of(evaluator, wheel, scene.states), scene.poisson);
  }
  {
    pipeline::Scene scene = with_best(pipeline::load_scene(WHEELWEAR_EXAMPLE_SCENE));
    scene.vehicle_run->critical_speed = false;
    const pipeline::CollectiveEvaluator evaluator(scene);
    const profiles::Profile wheel =
        profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
    const pipeline::VehicleCollective v =
        pipeline::solve_vehicle_collective(*scene.vehicle_run, evaluator.kernel(), {&wheel});
    emit("vehicle", patches_of(evaluator, wheel, v.states), scene.poisson);
  }
  {
    std::string text = "[load_collective]\n";
    for (int k = 0; k <= 40; ++k)
      text += "[[load_collective.state]]\ndy_m = " + std::to_string(6e-3 + k * 0.05e-3) +
              "\naxle_load_N = 110e3\nspeed_m_s = 30\nyaw_rad = 5e-3\n";
    const pipeline::Scene scene = with_best(pipeline::parse_scene(text, {}));
    const pipeline::CollectiveEvaluator evaluator(scene);
    const profiles::Profile wheel =
        profiles::wheel_profile(scene.wheel_profile, scene.wheel_radius, scene.wheel_file);
    emit("flange sweep", patches_of(evaluator, wheel, scene.states), scene.poisson);
  }
  std::printf("wrote %s\n", csv_path.c_str());
  return 0;
}
