#include "wheelwear/pipeline/collective_wear.hpp"

#include <tbb/parallel_for.h>

#include <cmath>
#include <map>
#include <tuple>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::pipeline {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Geometry is shared by states with the same position and loads (the yaw enters only the
// creepages): NaN stands for a lateral force not given.
using GeometryKey = std::tuple<double, double, double, double, double>;

GeometryKey geometry_key(const WheelsetStateSpec& s) {
  return {s.dy, s.load_left, s.load_right, s.lateral_force_left.value_or(kNaN),
          s.lateral_force_right.value_or(kNaN)};
}

// Orders keys with NaN (no lateral force) before any number, so std::map can hold them.
struct KeyLess {
  bool operator()(const GeometryKey& a, const GeometryKey& b) const {
    auto as_pair = [](double v) { return std::pair{!std::isnan(v), std::isnan(v) ? 0.0 : v}; };
    return std::tuple{std::get<0>(a), std::get<1>(a), std::get<2>(a), as_pair(std::get<3>(a)),
                      as_pair(std::get<4>(a))} < std::tuple{std::get<0>(b), std::get<1>(b),
                                                            std::get<2>(b), as_pair(std::get<3>(b)),
                                                            as_pair(std::get<4>(b))};
  }
};

// Distinct wheelset geometries, numbered in the order of first use (deterministic).
struct GeometryIndex {
  std::vector<std::size_t> geometry_of;  // per state
  std::vector<std::size_t> first_state;  // per geometry
};

GeometryIndex index_geometries(const std::vector<WheelsetStateSpec>& states, bool reuse) {
  GeometryIndex index;
  std::map<GeometryKey, std::size_t, KeyLess> index_of;
  index.geometry_of.resize(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    GeometryKey key = geometry_key(states[i]);
    if (!reuse) std::get<0>(key) = static_cast<double>(i) + 1.0;  // unique per state
    const auto [it, inserted] = index_of.emplace(key, index.first_state.size());
    if (inserted) index.first_state.push_back(i);
    index.geometry_of[i] = it->second;
  }
  return index;
}

}  // namespace

std::vector<double> state_shares(const std::vector<WheelsetStateSpec>& states) {
  double total = 0.0;
  for (const auto& s : states) total += s.weight;
  std::vector<double> shares;
  for (const auto& s : states) shares.push_back(s.weight / total);
  return shares;
}

std::vector<double> state_shares(const Scene& scene) {
  return state_shares(scene.states);
}

std::vector<double> wheel_weights(const std::vector<WheelsetStateSpec>& states,
                                  bool separate_wheels) {
  const std::vector<double> shares = state_shares(states);
  std::vector<double> weights(2 * shares.size());
  for (std::size_t i = 0; i < shares.size(); ++i)
    weights[2 * i] = weights[2 * i + 1] = shares[i] * (separate_wheels ? 1.0 : 0.5);
  return weights;
}

std::vector<double> wheel_weights(const Scene& scene) {
  return wheel_weights(scene.states, scene.separate_wheels);
}

std::vector<std::pair<std::string, double>> DroppedStates::named() const {
  return {{"failed_contacts", failed_contacts},
          {"failed_contacts_weight", failed_contacts_weight},
          {"climbing_contacts", climbing_contacts},
          {"climbing_contacts_weight", climbing_contacts_weight},
          {"nadal_contacts", nadal_contacts},
          {"nadal_contacts_weight", nadal_contacts_weight},
          {"load_jump_contacts", load_jump_contacts},
          {"load_jump_contacts_weight", load_jump_contacts_weight},
          {"dropped_patches", dropped_patches},
          {"dropped_patches_weight", dropped_patches_weight}};
}

namespace {

// Counts a dropped state's wheels by reason; its share once per reason and once as dropped.
void count_dropped(const StateOutcome& state, double share, DroppedStates& d) {
  bool seen[5] = {false, false, false, false, false};
  for (const WheelOutcome& wheel : state.wheels) {
    d.dropped_patches += static_cast<int>(wheel.contact_patches);
    const DropReason reason = wheel.drop_reason();
    const auto r = static_cast<std::size_t>(reason);
    if (reason == DropReason::none) continue;
    const bool first = !seen[r];
    seen[r] = true;
    const auto count = [&](int& contacts, double& weight) {
      ++contacts;
      if (first) weight += share;
    };
    switch (reason) {
      case DropReason::failed:
        count(d.failed_contacts, d.failed_contacts_weight);
        break;
      case DropReason::climbing:
        count(d.climbing_contacts, d.climbing_contacts_weight);
        break;
      case DropReason::load_jump:
        count(d.load_jump_contacts, d.load_jump_contacts_weight);
        break;
      case DropReason::nadal:
        count(d.nadal_contacts, d.nadal_contacts_weight);
        break;
      case DropReason::none:
        break;
    }
  }
  d.dropped_patches_weight += share;
}

}  // namespace

void reduce_states(const Scene& scene, const std::vector<StateOutcome>& states,
                   CollectiveWear& out) {
  reduce_states(scene, scene.states, states, out);
}

void reduce_states(const Scene& scene, const std::vector<WheelsetStateSpec>& specs,
                   const std::vector<StateOutcome>& states, CollectiveWear& out) {
  const std::vector<double> shares = state_shares(specs);
  const std::vector<double> weights = wheel_weights(specs, scene.separate_wheels);
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (states[i].dropped()) {
      count_dropped(states[i], shares[i], out.dropped);
      continue;
    }
    for (int side = 0; side < 2; ++side) {
      const WheelOutcome& wheel = states[i].wheels[static_cast<std::size_t>(side)];
      const double weight = weights[2 * i + static_cast<std::size_t>(side)];
      out.hertz_dropped += static_cast<std::size_t>(wheel.hertz_dropped);
      std::vector<double>& rate =
          out.rate[scene.separate_wheels ? static_cast<std::size_t>(side) : 0].depth;
      for (const PatchOutcome& p : wheel.patches) {
        if (!p.solved) continue;
        ++out.patches;
        if (p.solution.from_table) ++out.table_patches;
        if (p.solution.status == tangential::SolveStatus::not_converged) ++out.unconverged_patches;
        for (std::size_t b = 0; b < p.wear.depth.size(); ++b)
          rate[p.wear.first + b] += weight * p.wear.depth[b];
      }
    }
  }
}

CollectiveEvaluator::CollectiveEvaluator(const Scene& scene, bool reuse_geometry)
    : kernel_(scene), reuse_geometry_(reuse_geometry) {}

CollectiveWear CollectiveEvaluator::evaluate(
    const std::vector<const profiles::Profile*>& wheels) const {
  return evaluate(wheels, kernel_.scene().states);
}

CollectiveWear CollectiveEvaluator::evaluate(const std::vector<const profiles::Profile*>& wheels,
                                             const std::vector<WheelsetStateSpec>& specs) const {
  const Scene& scene = kernel_.scene();
  const std::size_t profiles_worn = scene.separate_wheels ? 2 : 1;
  require(wheels.size() == profiles_worn, "worn wheel profiles", static_cast<double>(wheels.size()),
          scene.separate_wheels ? "separate wheels need two profiles (left, right)"
                                : "shared wheels need one profile");
  const contactgeom::WheelsetOnTrack track{kernel_.pair(*wheels.front()),
                                           kernel_.pair(*wheels.back())};

  const GeometryIndex index = index_geometries(specs, reuse_geometry_);
  std::vector<contactgeom::WheelsetContact> contacts(index.first_state.size());
  tbb::parallel_for(std::size_t{0}, contacts.size(), [&](std::size_t g) {
    contacts[g] = kernel_.contact(track, specs[index.first_state[g]]);
  });

  const std::size_t n_states = specs.size();
  std::vector<StateOutcome> states(n_states);
  // Wheel by wheel: a state's two wheels are independent work.
  tbb::parallel_for(std::size_t{0}, 2 * n_states, [&](std::size_t k) {
    const std::size_t i = k / 2;
    const int side = static_cast<int>(k % 2);
    const contactgeom::WheelsetContact& both = contacts[index.geometry_of[i]];
    if (side == 0) states[i].roll = both.roll;  // one writer per state
    states[i].wheels[static_cast<std::size_t>(side)] = kernel_.wheel(
        both, side, specs[i], side == 0 ? track.left.wheel : track.right.wheel, scene.tgamma_maps);
  });

  CollectiveWear out;
  out.geometry_solves = contacts.size();
  for (const profiles::Profile* wheel : wheels) {
    const auto bins = static_cast<std::size_t>(std::ceil(wheel->length() / kWearBin)) + 1;
    out.rate.push_back(wear::WearDistribution::zeros(0.0, kWearBin, bins));
  }
  reduce_states(scene, specs, states, out);
  if (scene.state_summaries || scene.tgamma_maps) out.states = std::move(states);
  return out;
}

}  // namespace wheelwear::pipeline
