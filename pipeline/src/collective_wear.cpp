#include "wheelwear/pipeline/collective_wear.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "wheelwear/contactgeom/kinematics.hpp"
#include "wheelwear/contactgeom/wheelset.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/tangential/contact_model.hpp"
#include "wheelwear/tangential/exact/exact_fields.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/table_correction.hpp"

namespace wheelwear::pipeline {

namespace {

constexpr double kBin = 0.1e-3;  // wear grid on the wheel's arc length [m]
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One wheel of one state, in that wheel's own frame: what its creepages and wear need beyond
// the wheelset's contact.
struct WheelCase {
  int profile = 0;   // index of the worn profile
  double yaw = 0.0;  // this wheel's yaw [rad]
  contactgeom::WheelsetMotion motion;
  std::optional<tangential::Creepages> creepages;
  double weight = 0.0;  // share of the running distance of this wheel's profile
};

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

// The per-state wear of one wheel: a run of bins starting at `first`.
struct LocalWear {
  std::size_t first = 0;
  std::vector<double> depth;
};

struct WheelResult {
  std::vector<LocalWear> wear;
  std::size_t table_patches = 0;  // patches whose totals came from the book of tables
  std::size_t unconverged = 0;    // exact solves that stopped at max_iterations
};

bool usable(contactgeom::WheelRailStatus status) {
  return status == contactgeom::WheelRailStatus::ok ||
         status == contactgeom::WheelRailStatus::load_jump;
}

}  // namespace

CollectiveEvaluator::CollectiveEvaluator(const Scene& scene, bool reuse_geometry)
    : scene_(scene),
      rail_(std::make_shared<const profiles::Profile>(
          profiles::rail_profile(scene.rail_profile, scene.rail_inclination))),
      law_(wear::TgammaLaw::usfd()),
      reuse_geometry_(reuse_geometry) {
  if (!scene.wear_law_table.empty()) {
    if (scene.wear_law == "usfd") law_ = wear::TgammaLaw::load_csv(scene.wear_law_table);
    if (scene.wear_law == "archard") law_ = wear::ArchardLaw::load_csv(scene.wear_law_table);
  } else {
    const auto law = wear::default_wear_law(scene.wear_law);
    if (!law) throw InputError("scene: wear.law = " + scene.wear_law + ": unknown wear law");
    law_ = *law;
  }
  options_.strip_width = scene.strip_width;
  options_.kp.epsilon = scene.virtual_penetration;
  options_.validate();
}

contactgeom::WheelRailPair CollectiveEvaluator::pair(const profiles::Profile& wheel) const {
  contactgeom::WheelRailPair p(wheel, *rail_);
  p.gauge = scene_.gauge;
  p.back_to_back = scene_.back_to_back;
  p.wheel_radius = scene_.wheel_radius;
  p.youngs_modulus = scene_.youngs_modulus;
  p.poisson = scene_.poisson;
  p.validate();
  return p;
}

CollectiveWear CollectiveEvaluator::evaluate(
    const std::vector<const profiles::Profile*>& wheels) const {
  const std::size_t profiles_worn = scene_.separate_wheels ? 2 : 1;
  require(wheels.size() == profiles_worn, "worn wheel profiles", static_cast<double>(wheels.size()),
          scene_.separate_wheels ? "separate wheels need two profiles (left, right)"
                                 : "shared wheels need one profile");
  std::vector<contactgeom::WheelRailPair> pairs;
  for (const profiles::Profile* wheel : wheels) pairs.push_back(pair(*wheel));

  // Each state stands for weight/total of the distance; in a shared profile each wheel for half.
  const std::size_t n_states = scene_.states.size();
  double total_weight = 0.0;
  for (const auto& s : scene_.states) total_weight += s.weight;
  std::vector<WheelCase> cases(2 * n_states);
  for (std::size_t i = 0; i < n_states; ++i) {
    const WheelsetStateSpec& s = scene_.states[i];
    for (int side = 0; side < 2; ++side) {
      const double sign = side == 0 ? 1.0 : -1.0;  // the right wheel is the mirror image
      WheelCase& c = cases[2 * i + static_cast<std::size_t>(side)];
      c.profile = scene_.separate_wheels ? side : 0;
      c.yaw = sign * s.yaw;
      c.motion.speed = s.speed;
      c.motion.lateral_velocity = sign * s.lateral_velocity;
      // A right-hand curve (R > 0) puts the left wheel on the outer rail, ahead.
      c.motion.yaw_rate = s.curve_radius == 0.0 ? 0.0 : sign * s.speed / s.curve_radius;
      c.motion.lateral_arm = scene_.lateral_arm;
      c.creepages = side == 0 ? s.creepages_left : s.creepages_right;
      c.weight = s.weight / total_weight * (scene_.separate_wheels ? 1.0 : 0.5);
    }
  }

  // Distinct wheelset geometries, numbered in the order of first use (deterministic).
  std::map<GeometryKey, std::size_t, KeyLess> index_of;
  std::vector<std::size_t> geometry_of(n_states);
  std::vector<std::size_t> first_state;
  for (std::size_t i = 0; i < n_states; ++i) {
    GeometryKey key = geometry_key(scene_.states[i]);
    if (!reuse_geometry_) std::get<0>(key) = static_cast<double>(i) + 1.0;  // unique per state
    const auto [it, inserted] = index_of.emplace(key, first_state.size());
    if (inserted) first_state.push_back(i);
    geometry_of[i] = it->second;
  }
  const contactgeom::WheelsetOnTrack track{pairs.front(), pairs.back()};
  std::vector<contactgeom::WheelsetContact> contacts(first_state.size());
  tbb::parallel_for(std::size_t{0}, first_state.size(), [&](std::size_t g) {
    const WheelsetStateSpec& s = scene_.states[first_state[g]];
    contactgeom::WheelsetState state;
    state.dy = s.dy;
    state.yaw = s.yaw;
    state.vertical_force_left = s.load_left;
    state.vertical_force_right = s.load_right;
    state.lateral_force_left = s.lateral_force_left;
    state.lateral_force_right = s.lateral_force_right;
    contacts[g] = contactgeom::solve_wheelset(track, state, options_);
  });
  // The contact of wheel case k (state k/2, side k%2) and the pose it was solved at, with this
  // state's yaw (a shared geometry may come from a state of another yaw).
  auto contact_of = [&](std::size_t k) -> const contactgeom::WheelRailContact& {
    const auto& c = contacts[geometry_of[k / 2]];
    return k % 2 == 0 ? c.left : c.right;
  };
  auto pose_of = [&](std::size_t k) {
    const auto& c = contacts[geometry_of[k / 2]];
    contactgeom::WheelsetPose pose = k % 2 == 0 ? c.left_pose : c.right_pose;
    pose.yaw = cases[k].yaw;
    return pose;
  };

  CollectiveWear out;
  out.geometry_solves = first_state.size();
  std::vector<std::size_t> bins(profiles_worn);
  for (std::size_t p = 0; p < profiles_worn; ++p) {
    bins[p] = static_cast<std::size_t>(std::ceil(wheels[p]->length() / kBin)) + 1;
    out.rate.push_back(wear::WearDistribution::zeros(0.0, kBin, bins[p]));
  }
  StateSummaries& sum = out.summaries;
  const bool summaries = scene_.state_summaries;
  if (summaries) {
    sum.states = n_states;
    sum.status.assign(2 * n_states, kNaN);
    sum.patches.assign(2 * n_states, 0.0);
    sum.dy.assign(2 * n_states, kNaN);
    sum.roll.assign(n_states, kNaN);
    sum.vertical_force.assign(2 * n_states, kNaN);
    sum.lateral_force.assign(2 * n_states, kNaN);
    sum.lateral_fit.assign(2 * n_states, kNaN);
    for (auto* v : {&sum.normal_force, &sum.a, &sum.b, &sum.psi, &sum.y_wheel, &sum.contact_angle,
                    &sum.vx, &sum.vy, &sum.phi, &sum.Fx, &sum.Fy, &sum.frictional_work,
                    &sum.worn_area, &sum.from_table})
      v->assign(2 * n_states * kPatchSlots, kNaN);
  }
  const int nx = scene_.grid_nx, ny = scene_.grid_ny;
  const std::size_t cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  if (scene_.tgamma_maps) {
    out.maps = TgammaMaps{nx, ny, {}, {}, {}};
    for (auto* v : {&out.maps->work, &out.maps->x, &out.maps->y})
      v->assign(2 * n_states * kPatchSlots * cells, kNaN);
  }

  const tangential::Material material{scene_.youngs_modulus / (2.0 * (1.0 + scene_.poisson)),
                                scene_.poisson};
  tangential::FastsimOptions fastsim_options;
  fastsim_options.nx = nx;
  fastsim_options.ny = ny;
  fastsim_options.scheme = scene_.scheme;
  fastsim_options.cell_fields = true;  // the wear laws need every cell's work and slip
  // Only the fields the wear needs, unless T gamma maps with their cell positions are written.
  fastsim_options.field_set =
      scene_.tgamma_maps ? tangential::CellFieldSet::all : tangential::CellFieldSet::wear;

  tangential::SdecGridOptions exact_options;
  exact_options.nx = nx;
  exact_options.ny = ny;

  std::vector<WheelResult> results(cases.size());
  tbb::parallel_for(std::size_t{0}, cases.size(), [&](std::size_t k) {
    const WheelCase& c = cases[k];
    const contactgeom::WheelRailContact& contact = contact_of(k);
    const contactgeom::WheelsetPose pose = pose_of(k);
    const std::size_t p = static_cast<std::size_t>(c.profile);
    if (summaries) {
      const auto& both = contacts[geometry_of[k / 2]];
      sum.status[k] = static_cast<double>(contact.status);
      sum.dy[k] = pose.dy;
      if (k % 2 == 0) sum.roll[k / 2] = both.roll;  // one writer per state
      sum.vertical_force[k] = contact.vertical_force;
      sum.lateral_force[k] = contact.lateral_force;
      sum.lateral_fit[k] = static_cast<double>(k % 2 == 0 ? both.left_fit : both.right_fit);
    }
    if (!usable(contact.status)) return;
    const std::size_t n_patches = std::min<std::size_t>(contact.patches.size(), kPatchSlots);
    if (summaries) sum.patches[k] = static_cast<double>(n_patches);
    tangential::TangentialSolution solution;
    for (std::size_t slot = 0; slot < n_patches; ++slot) {
      const contactgeom::WheelRailPatch& patch = contact.patches[slot];
      std::optional<contactgeom::Sdec> hertz;
      if (patch.hertz_valid) hertz = contactgeom::Sdec{patch.hertz.a, patch.hertz.b, 0.0};
      if (scene_.model == tangential::ContactModel::hertz && !hertz) continue;
      const tangential::ModelPatch region = tangential::model_patch(scene_.model, patch.sdec, hertz);
      const tangential::Creepages creep = c.creepages ? *c.creepages
                                                : contactgeom::kinematic_creepages(
                                                      patch, pose, c.motion, scene_.wheel_radius);
      const tangential::ContactLoad load{patch.normal_force, scene_.friction};
      if (scene_.tangential == TangentialMethod::exact) {
        const tangential::ExactSolution exact =
            tangential::exact_sdec(region.region, creep, load, material, exact_options);
        if (exact.status == tangential::ExactStatus::not_converged) ++results[k].unconverged;
        solution = tangential::exact_tangential_solution(exact, creep);
      } else {
        tangential::fastsim(region.method, region.region, creep, load, material, fastsim_options,
                      solution);
      }
      const bool from_table =
          scene_.tangential == TangentialMethod::best &&
          tangential::correct_with_creep_table(region.region, creep, load, material, solution);
      if (from_table) ++results[k].table_patches;
      // The bins the patch can reach on the wheel: its width around O, both ways.
      const double reach = 2.0 * std::max(region.region.b, patch.sdec.b) + 2.0 * kBin;
      const double lo = std::max(0.0, patch.s_wheel - reach);
      const double hi = std::min(wheels[p]->length(), patch.s_wheel + reach);
      LocalWear local;
      local.first = static_cast<std::size_t>(std::floor(lo / kBin));
      const std::size_t last =
          std::min(bins[p] - 1, static_cast<std::size_t>(std::ceil(hi / kBin)));
      wear::WearDistribution part = wear::WearDistribution::zeros(
          static_cast<double>(local.first) * kBin, kBin, last - local.first + 1);
      wear::accumulate_wear(*solution.fields, c.motion.speed, law_,
                            {patch.s_wheel, patch.rolling_radius}, 1.0, part);
      local.depth = std::move(part.depth);
      if (summaries) {
        const std::size_t at = k * kPatchSlots + slot;
        sum.normal_force[at] = patch.normal_force;
        sum.a[at] = patch.sdec.a;
        sum.b[at] = patch.sdec.b;
        sum.psi[at] = patch.sdec.psi;
        sum.y_wheel[at] = patch.y_wheel;
        sum.contact_angle[at] = patch.contact_angle;
        sum.vx[at] = creep.vx;
        sum.vy[at] = creep.vy;
        sum.phi[at] = creep.phi;
        sum.Fx[at] = solution.forces.Fx;
        sum.Fy[at] = solution.forces.Fy;
        sum.frictional_work[at] = solution.frictional_work;
        double area = 0.0;
        for (double d : local.depth) area += d * kBin;
        sum.worn_area[at] = area;
        sum.from_table[at] = from_table ? 1.0 : 0.0;
      }
      if (out.maps) {
        const std::size_t at = (k * kPatchSlots + slot) * cells;
        const tangential::CellFields& f = *solution.fields;
        std::copy(f.work.begin(), f.work.end(), out.maps->work.begin() + static_cast<long>(at));
        std::copy(f.x.begin(), f.x.end(), out.maps->x.begin() + static_cast<long>(at));
        std::copy(f.y.begin(), f.y.end(), out.maps->y.begin() + static_cast<long>(at));
      }
      results[k].wear.push_back(std::move(local));
    }
  });

  // The reduction runs in state order, whatever the threads did: bit-identical results.
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const WheelCase& c = cases[k];
    if (!usable(contact_of(k).status)) {
      ++out.failed_contacts;
      out.failed_weight += c.weight * (scene_.separate_wheels ? 0.5 : 1.0);
      continue;
    }
    out.patches += results[k].wear.size();
    out.table_patches += results[k].table_patches;
    out.unconverged_patches += results[k].unconverged;
    std::vector<double>& rate = out.rate[static_cast<std::size_t>(c.profile)].depth;
    for (const LocalWear& local : results[k].wear)
      for (std::size_t b = 0; b < local.depth.size(); ++b)
        rate[local.first + b] += c.weight * local.depth[b];
  }
  return out;
}

}  // namespace wheelwear::pipeline
