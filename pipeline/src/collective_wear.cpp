#include "wheelwear/pipeline/collective_wear.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::pipeline {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr auto kPhysicalWheelsets = static_cast<std::size_t>(vehicle::kWheelsets);

// Geometry is shared by states with the same position and loads (the yaw enters only the
// creepages): NaN stands for a lateral force not given.
// The first element is the state's pair of profiles (its wheelset on the track).
using GeometryKey = std::tuple<double, double, double, double, double, double>;

GeometryKey geometry_key(const WheelsetStateSpec& s, std::size_t track) {
  return {static_cast<double>(track),
          s.dy,
          s.load_left,
          s.load_right,
          s.lateral_force_left.value_or(kNaN),
          s.lateral_force_right.value_or(kNaN)};
}

// Orders keys with NaN (no lateral force) before any number, so std::map can hold them.
struct KeyLess {
  bool operator()(const GeometryKey& a, const GeometryKey& b) const {
    auto as_pair = [](double v) { return std::pair{!std::isnan(v), std::isnan(v) ? 0.0 : v}; };
    const auto comparable = [&](const GeometryKey& k) {
      return std::tuple{std::get<0>(k), std::get<1>(k),          std::get<2>(k),
                        std::get<3>(k), as_pair(std::get<4>(k)), as_pair(std::get<5>(k))};
    };
    return comparable(a) < comparable(b);
  }
};

// Distinct wheelset geometries, numbered in the order of first use (deterministic).
struct GeometryIndex {
  std::vector<std::size_t> geometry_of;  // per state
  std::vector<std::size_t> first_state;  // per geometry
};

GeometryIndex index_geometries(const std::vector<WheelsetStateSpec>& states,
                               const std::vector<std::size_t>& track_of, bool reuse) {
  GeometryIndex index;
  std::map<GeometryKey, std::size_t, KeyLess> index_of;
  index.geometry_of.resize(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    GeometryKey key = geometry_key(states[i], track_of[i]);
    if (!reuse) std::get<1>(key) = static_cast<double>(i) + 1.0;  // unique per state
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

ProfileLayout profile_layout(const Scene& scene) {
  if (!scene.separate_wheels) return ProfileLayout::shared;
  return scene.vehicle_run ? ProfileLayout::per_wheelset : ProfileLayout::left_right;
}

std::size_t profile_count(ProfileLayout layout) {
  switch (layout) {
    case ProfileLayout::shared:
      return 1;
    case ProfileLayout::left_right:
      return 2;
    case ProfileLayout::per_wheelset:
      return 2 * kPhysicalWheelsets;
  }
  return 1;
}

std::vector<std::string> profile_names(ProfileLayout layout) {
  switch (layout) {
    case ProfileLayout::shared:
      return {"wheel"};
    case ProfileLayout::left_right:
      return {"wheel_left", "wheel_right"};
    case ProfileLayout::per_wheelset: {
      std::vector<std::string> names;
      for (std::size_t k = 1; k <= kPhysicalWheelsets; ++k)
        for (const char* side : {"wheel_left", "wheel_right"})
          names.push_back("wheelsets/" + std::to_string(k) + "/" + side);
      return names;
    }
  }
  return {};
}

ProfileLayout layout_of(std::size_t count) {
  for (ProfileLayout layout :
       {ProfileLayout::shared, ProfileLayout::left_right, ProfileLayout::per_wheelset})
    if (profile_count(layout) == count) return layout;
  throw InputError("worn wheel profiles: " + std::to_string(count) +
                   " given; a run wears 1 (shared), 2 (left, right) or 8 (per wheelset)");
}

std::array<std::size_t, 2> worn_profiles(const WheelsetStateSpec& state, ProfileLayout layout) {
  const std::size_t near = state.reversed ? 1 : 0;  // the physical side on the left in travel
  switch (layout) {
    case ProfileLayout::shared:
      return {0, 0};
    case ProfileLayout::left_right:
      return {near, 1 - near};
    case ProfileLayout::per_wheelset: {
      if (state.wheelset < 0 || state.wheelset >= static_cast<int>(kPhysicalWheelsets))
        throw InputError("state '" + state.label + "' (line " + std::to_string(state.line) +
                         "): each wheelset wears its own profiles, and the state names none; "
                         "give its wheelset (1 to 4)");
      const auto first = 2 * static_cast<std::size_t>(state.wheelset);
      return {first + near, first + 1 - near};
    }
  }
  return {0, 0};
}

std::vector<double> wheel_weights(const std::vector<WheelsetStateSpec>& states,
                                  ProfileLayout layout) {
  const std::vector<double> shares = state_shares(states);
  std::vector<double> on_profile(profile_count(layout), 0.0);
  for (std::size_t i = 0; i < states.size(); ++i)
    for (std::size_t p : worn_profiles(states[i], layout)) on_profile[p] += shares[i];
  std::vector<double> weights(2 * shares.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    const std::array<std::size_t, 2> p = worn_profiles(states[i], layout);
    for (std::size_t side = 0; side < 2; ++side)
      weights[2 * i + side] = shares[i] == 0.0 ? 0.0 : shares[i] / on_profile[p[side]];
  }
  return weights;
}

std::vector<double> wheel_weights(const Scene& scene) {
  return wheel_weights(scene.states, profile_layout(scene));
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
  const ProfileLayout layout = profile_layout(scene);
  const std::vector<double> weights = wheel_weights(specs, layout);
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (states[i].dropped()) {
      count_dropped(states[i], shares[i], out.dropped);
      continue;
    }
    const std::array<std::size_t, 2> profile = worn_profiles(specs[i], layout);
    for (std::size_t side = 0; side < 2; ++side) {
      const WheelOutcome& wheel = states[i].wheels[side];
      const double weight = weights[2 * i + side];
      out.hertz_dropped += static_cast<std::size_t>(wheel.hertz_dropped);
      std::vector<double>& rate = out.rate[profile[side]].depth;
      for (const PatchOutcome& p : wheel.patches) {
        if (!p.solved) continue;
        ++out.patches;
        out.frictional_work += shares[i] * p.solution.frictional_work;
        if (p.solution.from_table) {
          ++out.table_patches;
          out.table_work += shares[i] * p.solution.frictional_work;
        }
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

namespace {

// Which profile pair (track) each state runs on, numbered in the order of first use.
struct TrackIndex {
  std::vector<std::array<std::size_t, 2>> profiles;  // per track: left, right profile index
  std::vector<std::size_t> track_of;                 // per state
};

TrackIndex index_tracks(const std::vector<WheelsetStateSpec>& specs, ProfileLayout layout) {
  TrackIndex index;
  std::map<std::array<std::size_t, 2>, std::size_t> number;
  index.track_of.resize(specs.size());
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const std::array<std::size_t, 2> worn = worn_profiles(specs[i], layout);
    const auto [it, inserted] = number.emplace(worn, index.profiles.size());
    if (inserted) index.profiles.push_back(worn);
    index.track_of[i] = it->second;
  }
  return index;
}

}  // namespace

void CollectiveEvaluator::check_wheels(const std::vector<const profiles::Profile*>& wheels) const {
  const ProfileLayout layout = profile_layout(kernel_.scene());
  require(wheels.size() == profile_count(layout), "worn wheel profiles",
          static_cast<double>(wheels.size()),
          layout == ProfileLayout::shared ? "shared wheels need one profile"
          : layout == ProfileLayout::left_right
              ? "separate wheels need two profiles (left, right)"
              : "separate wheels of a vehicle need eight profiles "
                "(left and right of each wheelset)");
}

std::vector<int> CollectiveEvaluator::owners(const std::vector<WheelsetStateSpec>& specs,
                                             int ranks) const {
  require(ranks >= 1, "processes", ranks, "at least one");
  const TrackIndex tracks = index_tracks(specs, profile_layout(kernel_.scene()));
  const GeometryIndex index = index_geometries(specs, tracks.track_of, reuse_geometry_);
  std::vector<int> owner(specs.size());
  for (std::size_t i = 0; i < specs.size(); ++i)
    owner[i] = static_cast<int>(index.geometry_of[i] % static_cast<std::size_t>(ranks));
  return owner;
}

StateOutcomes CollectiveEvaluator::outcomes(const std::vector<const profiles::Profile*>& wheels,
                                            const std::vector<WheelsetStateSpec>& specs,
                                            const std::vector<std::size_t>& which,
                                            const ContactTables* tables) const {
  check_wheels(wheels);
  const Scene& scene = kernel_.scene();
  const TrackIndex track_index = index_tracks(specs, profile_layout(scene));
  std::vector<contactgeom::WheelRailPair> pairs;
  for (const profiles::Profile* wheel : wheels) pairs.push_back(kernel_.pair(*wheel));
  std::vector<contactgeom::WheelsetOnTrack> tracks;
  for (const std::array<std::size_t, 2>& worn : track_index.profiles)
    tracks.push_back({pairs[worn[0]], pairs[worn[1]]});
  const std::vector<std::size_t>& track_of = track_index.track_of;

  // The distinct geometries of the states asked for, each solved once.
  const GeometryIndex index = index_geometries(specs, track_of, reuse_geometry_);
  std::vector<std::size_t> needed;  // geometry numbers, in order of first use
  std::map<std::size_t, std::size_t> slot_of;
  for (std::size_t i : which)
    if (slot_of.emplace(index.geometry_of[i], needed.size()).second)
      needed.push_back(index.geometry_of[i]);
  std::vector<const contactgeom::WheelsetContactTable*> table_of(tracks.size(), nullptr);
  if (tables)
    for (std::size_t t = 0; t < tracks.size(); ++t)
      if (const auto it = tables->find(track_index.profiles[t]); it != tables->end())
        table_of[t] = it->second.get();
  std::vector<contactgeom::WheelsetContact> contacts(needed.size());
  std::vector<char> from_table(needed.size(), 0);
  tbb::parallel_for(std::size_t{0}, contacts.size(), [&](std::size_t g) {
    const std::size_t first = index.first_state[needed[g]];
    const std::size_t track = track_of[first];
    bool interpolated = false;
    contacts[g] = kernel_.contact(tracks[track], specs[first], table_of[track], &interpolated);
    from_table[g] = interpolated ? 1 : 0;
  });

  StateOutcomes out;
  out.geometry_solves = contacts.size();
  out.table_contacts =
      static_cast<std::size_t>(std::count(from_table.begin(), from_table.end(), 1));
  out.states.resize(which.size());
  // Wheel by wheel: a state's two wheels are independent work.
  tbb::parallel_for(std::size_t{0}, 2 * which.size(), [&](std::size_t k) {
    const std::size_t i = which[k / 2];
    const int side = static_cast<int>(k % 2);
    const contactgeom::WheelsetContact& both = contacts[slot_of.at(index.geometry_of[i])];
    const contactgeom::WheelsetOnTrack& track = tracks[track_of[i]];
    StateOutcome& state = out.states[k / 2];
    if (side == 0) state.roll = both.roll;  // one writer per state
    state.wheels[static_cast<std::size_t>(side)] = kernel_.wheel(
        both, side, specs[i], side == 0 ? track.left.wheel : track.right.wheel, scene.tgamma_maps);
  });
  return out;
}

CollectiveWear CollectiveEvaluator::reduce(const std::vector<const profiles::Profile*>& wheels,
                                           const std::vector<WheelsetStateSpec>& specs,
                                           StateOutcomes all) const {
  const Scene& scene = kernel_.scene();
  require(all.states.size() == specs.size(), "state outcomes",
          static_cast<double>(all.states.size()), "one per state of the collective");
  CollectiveWear out;
  out.geometry_solves = all.geometry_solves;
  out.table_contacts = all.table_contacts;
  for (const profiles::Profile* wheel : wheels) {
    const auto bins = static_cast<std::size_t>(std::ceil(wheel->length() / kWearBin)) + 1;
    out.rate.push_back(wear::WearDistribution::zeros(0.0, kWearBin, bins));
  }
  reduce_states(scene, specs, all.states, out);
  if (scene.state_summaries || scene.tgamma_maps) out.states = std::move(all.states);
  return out;
}

CollectiveWear CollectiveEvaluator::evaluate(const std::vector<const profiles::Profile*>& wheels,
                                             const std::vector<WheelsetStateSpec>& specs,
                                             const ContactTables* tables) const {
  std::vector<std::size_t> every(specs.size());
  for (std::size_t i = 0; i < every.size(); ++i) every[i] = i;
  return reduce(wheels, specs, outcomes(wheels, specs, every, tables));
}

}  // namespace wheelwear::pipeline
