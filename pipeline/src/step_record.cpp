#include "step_record.hpp"

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <ctime>
#include <limits>

#include "vehicle_record.hpp"
#include "wheelwear/contactgeom/equivalent_conicity.hpp"
#include "wheelwear/profiles/wear_measures.hpp"

namespace wheelwear::pipeline::detail {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kConicityAmplitude = 3e-3;  // EN 15302's reference amplitude [m]
constexpr double kDeltaRRange = 6e-3;        // Delta r is sampled over +-6 mm ...
constexpr int kDeltaRSamples = 61;           // ... every 0.2 mm

std::size_t largest_patch_count(const std::vector<StateOutcome>& states) {
  std::size_t count = 1;  // a dimension of extent zero would make every per-patch array empty
  for (const StateOutcome& s : states)
    for (const WheelOutcome& w : s.wheels) count = std::max(count, w.patches.size());
  return count;
}

// One per-patch quantity over [state, wheel, patch], NaN where there is no (solved) patch.
template <class Value>
std::vector<double> per_patch(const std::vector<StateOutcome>& states, std::size_t slots,
                              bool solved_only, Value value) {
  std::vector<double> out(states.size() * 2 * slots, kNaN);
  for (std::size_t i = 0; i < states.size(); ++i)
    for (std::size_t w = 0; w < 2; ++w) {
      const WheelOutcome& wheel = states[i].wheels[w];
      if (!wheel.usable()) continue;
      for (std::size_t k = 0; k < wheel.patches.size(); ++k) {
        const PatchOutcome& p = wheel.patches[k];
        if (solved_only && !p.solved) continue;
        out[(i * 2 + w) * slots + k] = value(p);
      }
    }
  return out;
}

template <class Value>
std::vector<double> per_wheel(const std::vector<StateOutcome>& states, Value value) {
  std::vector<double> out(states.size() * 2);
  for (std::size_t i = 0; i < states.size(); ++i)
    for (std::size_t w = 0; w < 2; ++w) out[i * 2 + w] = value(states[i].wheels[w]);
  return out;
}

std::string now_iso8601() {
  const std::time_t t = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return text;
}

}  // namespace

ArrayRecord scalar(std::string name, double value, std::string units, std::string description) {
  return {std::move(name), {value}, {}, std::move(units), std::move(description)};
}

ArrayRecord vector(std::string name, std::vector<double> values, std::string units,
                   std::string description) {
  const std::size_t n = values.size();
  return {std::move(name), std::move(values), {n}, std::move(units), std::move(description)};
}

void add_state_summaries(GroupRecord& g, const std::vector<StateOutcome>& states) {
  const std::size_t n = states.size();
  const std::size_t slots = largest_patch_count(states);
  auto wheel_array = [&](const char* name, std::vector<double> v, const char* units,
                         const char* what, bool integer = false) {
    g.arrays.push_back({std::string("states/") + name, std::move(v), {n, 2}, units, what, integer});
  };
  auto patch_array = [&](const char* name, std::vector<double> v, const char* units,
                         const char* what, bool integer = false) {
    g.arrays.push_back(
        {std::string("states/") + name, std::move(v), {n, 2, slots}, units, what, integer});
  };
  using P = const PatchOutcome&;
  using W = const WheelOutcome&;
  wheel_array("status", per_wheel(states, [](W w) { return static_cast<double>(w.status); }), "1",
              "[state, wheel (left, right)] contact status: 0 ok, 1 no contact, 2 flange climb, "
              "3 not converged, 4 load jump, 5 profile end, 6 past the flange",
              true);
  wheel_array("drop_reason",
              per_wheel(states, [](W w) { return static_cast<double>(w.drop_reason()); }), "1",
              "[state, wheel] why the wheel keeps its state from being worn: 0 none, 1 failed, "
              "2 climbing, 3 load jump, 4 beyond Nadal's limit (a state with any reason is not "
              "worn)",
              true);
  wheel_array("nadal_delta", per_wheel(states, [](W w) { return w.nadal.delta; }), "rad",
              "[state, wheel] Nadal's delta: the largest contact angle of the patches carrying "
              "10 % of the wheel's normal load (status ok only, else 0)");
  wheel_array("Y_over_Q", per_wheel(states, [](W w) { return w.nadal.Y_over_Q; }), "1",
              "[state, wheel] lateral over vertical force of the wheel in the track plane, creep "
              "forces included");
  wheel_array("nadal_limit", per_wheel(states, [](W w) { return w.nadal.limit; }), "1",
              "[state, wheel] Nadal's limit (tan delta - mu)/(1 + mu tan delta)");
  wheel_array(
      "patches",
      per_wheel(states, [](W w) { return w.usable() ? static_cast<double>(w.patches.size()) : 0; }),
      "1", "[state, wheel] number of contact patches (the per-patch arrays' entries)", true);
  wheel_array("dy", per_wheel(states, [](W w) { return w.dy; }), "m",
              "[state, wheel] lateral shift of the wheel, + towards its flange");
  std::vector<double> roll(n);
  for (std::size_t i = 0; i < n; ++i) roll[i] = states[i].roll;
  g.arrays.push_back(
      {"states/roll", roll, {n}, "rad", "[state] wheelset roll, + when the left wheel goes down"});
  wheel_array("vertical_force", per_wheel(states, [](W w) { return w.vertical_force; }), "N",
              "[state, wheel] vertical force of the contact");
  wheel_array("lateral_force", per_wheel(states, [](W w) { return w.lateral_force; }), "N",
              "[state, wheel] lateral force of the contact, + pushing the wheel to the track "
              "centre");
  wheel_array("lateral_fit",
              per_wheel(states, [](W w) { return static_cast<double>(w.lateral_fit); }), "1",
              "[state, wheel] prescribed lateral force: 0 not given, 1 matched, 2 position kept, "
              "3 flange just unloaded, 4 not matched",
              true);
  patch_array("normal_force", per_patch(states, slots, false, [](P p) { return p.normal_force; }),
              "N", "[state, wheel, patch] normal force");
  patch_array("a", per_patch(states, slots, false, [](P p) { return p.sdec.a; }), "m",
              "[state, wheel, patch] SDEC semi-axis along x (Eq. 13)");
  patch_array("b", per_patch(states, slots, false, [](P p) { return p.sdec.b; }), "m",
              "[state, wheel, patch] SDEC semi-axis along y (Eq. 13)");
  patch_array("psi", per_patch(states, slots, false, [](P p) { return p.sdec.psi; }), "1",
              "[state, wheel, patch] SDEC asymmetry psi (Eq. 14)");
  patch_array("y_wheel", per_patch(states, slots, false, [](P p) { return -p.y_wheel; }), "m",
              "[state, wheel, patch] O on the wheel: lateral position in the profile frame (+ "
              "towards the field side, 0 at the taping line), as wheel/y");
  patch_array("contact_angle", per_patch(states, slots, false, [](P p) { return p.contact_angle; }),
              "rad", "[state, wheel, patch] contact angle");
  patch_array("vx", per_patch(states, slots, true, [](P p) { return p.creepages.vx; }), "1",
              "[state, wheel, patch] longitudinal creepage at O");
  patch_array("vy", per_patch(states, slots, true, [](P p) { return p.creepages.vy; }), "1",
              "[state, wheel, patch] lateral creepage at O, + to the gauge side");
  patch_array("phi", per_patch(states, slots, true, [](P p) { return p.creepages.phi; }), "1/m",
              "[state, wheel, patch] spin creepage at O");
  patch_array("Fx", per_patch(states, slots, true, [](P p) { return p.solution.forces.Fx; }), "N",
              "[state, wheel, patch] longitudinal creep force on the wheel");
  patch_array("Fy", per_patch(states, slots, true, [](P p) { return p.solution.forces.Fy; }), "N",
              "[state, wheel, patch] lateral creep force on the wheel");
  patch_array("frictional_work",
              per_patch(states, slots, true, [](P p) { return p.solution.frictional_work; }), "J/m",
              "[state, wheel, patch] frictional work per metre rolled");
  patch_array("worn_area", per_patch(states, slots, true, [](P p) { return p.wear.area(); }),
              "m^2/m",
              "[state, wheel, patch] worn cross-section per metre running of this contact");
  patch_array("from_table",
              per_patch(states, slots, true, [](P p) { return p.solution.from_table ? 1.0 : 0.0; }),
              "1",
              "[state, wheel, patch] 1: Fx, Fy and the frictional work from the book of tables "
              "of Kalker's exact theory (tangential_method = best), 0: not from the table, -1: "
              "no solved patch",
              true);
}

void add_wear_measures(GroupRecord& g, const std::string& name, const profiles::Profile& original,
                       const profiles::Profile& current) {
  const profiles::NormalWear worn = profiles::normal_wear(original, current);
  g.arrays.push_back(vector(name + "/cumulative_wear/s", worn.s, "m",
                            "arc length on the step-0 profile, every 0.1 mm from its flange end"));
  g.arrays.push_back(vector(name + "/cumulative_wear/depth", worn.depth, "m",
                            "depth worn since step 0, along the step-0 profile's inward normal "
                            "(> 0 worn; NaN where the normal does not meet this profile)"));
  const profiles::RadiusChange radius = profiles::radius_change(original, current);
  g.arrays.push_back(vector(name + "/radius_change/y", radius.y, "m",
                            "lateral position, profile frame (+ towards the field side, 0 at the "
                            "taping line), every 0.1 mm: the same grid at every step"));
  g.arrays.push_back(vector(name + "/radius_change/value", radius.delta, "m",
                            "rolling radius change since step 0, r(y) - r0(y) (< 0 worn; NaN "
                            "where either profile has no surface at y)"));
}

void add_tgamma_maps(GroupRecord& g, const std::vector<StateOutcome>& states, int nx, int ny) {
  const std::size_t slots = largest_patch_count(states);
  const auto cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  std::vector<double> work(states.size() * 2 * slots * cells, kNaN), x = work, y = work;
  for (std::size_t i = 0; i < states.size(); ++i)
    for (std::size_t w = 0; w < 2; ++w) {
      const WheelOutcome& wheel = states[i].wheels[w];
      for (std::size_t k = 0; k < wheel.patches.size(); ++k) {
        const auto& fields = wheel.patches[k].solution.fields;
        if (!fields || fields->work.size() != cells) continue;
        const auto at = static_cast<long>(((i * 2 + w) * slots + k) * cells);
        std::copy(fields->work.begin(), fields->work.end(), work.begin() + at);
        std::copy(fields->x.begin(), fields->x.end(), x.begin() + at);
        std::copy(fields->y.begin(), fields->y.end(), y.begin() + at);
      }
    }
  const std::vector<std::size_t> shape = {states.size(), 2, slots, static_cast<std::size_t>(ny),
                                          static_cast<std::size_t>(nx)};
  g.arrays.push_back({"tgamma/work", std::move(work), shape, "J/m^2/m",
                      "[state, wheel, patch, strip, cell] frictional work density T gamma per "
                      "metre rolled"});
  g.arrays.push_back(
      {"tgamma/x", std::move(x), shape, "m", "cell centre along x (rolling) relative to O"});
  g.arrays.push_back({"tgamma/y", std::move(y), shape, "m",
                      "cell centre along y relative to O, + towards the flange"});
}

GroupRecord collective_record(const Scene& scene) {
  GroupRecord g;
  add_collective(g, "", scene.states);
  return g;
}

GroupRecord run_info(const fs::path& scene_directory, bool builtin, double elapsed,
                     std::size_t evaluations, int resumed_from, const std::string& program) {
  char host[256] = "unknown";
  ::gethostname(host, sizeof host - 1);
  GroupRecord info;
  info.texts.push_back({"scene_directory", scene_directory.string(),
                        "directory the scene's relative file names are resolved in"});
  info.texts.push_back({"host", host, "machine the run (or its last part) ran on"});
  info.texts.push_back(
      {"program", program, "program and version that wrote the run (or its last part)"});
  info.texts.push_back({"written", now_iso8601(), "time of writing (UTC)"});
  info.arrays.push_back(as_integer(scalar("builtin_scene", builtin ? 1.0 : 0.0, "1",
                                          "1 when the run uses the built-in default scene")));
  info.arrays.push_back(as_integer(scalar("threads", tbb::this_task_arena::max_concurrency(), "1",
                                          "worker threads available to this process")));
  info.arrays.push_back(scalar("elapsed", elapsed, "s", "wall time of this process"));
  info.arrays.push_back(as_integer(scalar("evaluations", static_cast<double>(evaluations), "1",
                                          "wheelset states evaluated by this process")));
  info.arrays.push_back(
      as_integer(scalar("resumed_from_step", resumed_from, "1",
                        "step this process resumed after; -1 for a run from the start")));
  return info;
}

// The equivalent conicity and rolling radius difference of the wheelset(s) the profiles make:
// at the top of the step the first wheelset's (the only one unless each wheelset wears its own
// profiles), then each wheelset's below wheelsets/K/.
void add_conicity(GroupRecord& g, const CollectiveEvaluator& evaluator,
                  const std::vector<profiles::Profile>& wheels) {
  const bool per_wheelset = wheels.size() > 2;
  const std::size_t wheelsets = per_wheelset ? wheels.size() / 2 : 1;
  for (std::size_t k = 0; k < wheelsets; ++k) {
    const profiles::Profile& left = per_wheelset ? wheels[2 * k] : wheels.front();
    const profiles::Profile& right = per_wheelset ? wheels[2 * k + 1] : wheels.back();
    const contactgeom::RollingRadiusDifference dr = contactgeom::rolling_radius_difference(
        evaluator.pair(left), evaluator.pair(right), kDeltaRRange, kDeltaRSamples);
    const double conicity = contactgeom::equivalent_conicity(dr, kConicityAmplitude);
    const std::string prefixes[2] = {"", "wheelsets/" + std::to_string(k + 1) + "/"};
    for (const std::string& prefix : prefixes) {
      if (!prefix.empty() && !per_wheelset) continue;
      if (prefix.empty() && k > 0) continue;
      g.arrays.push_back(scalar(prefix + "equivalent_conicity", conicity, "1",
                                "tan(gamma_e) at 3 mm amplitude (EN 15302, Annex C)"));
      g.arrays.push_back(
          vector(prefix + "delta_r/dy", dr.dy, "m", "wheelset shift, + to the left"));
      g.arrays.push_back(vector(prefix + "delta_r/value", dr.delta_r, "m", "r_left - r_right"));
    }
  }
}

}  // namespace wheelwear::pipeline::detail
