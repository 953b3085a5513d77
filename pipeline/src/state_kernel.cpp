#include "wheelwear/pipeline/state_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <utility>

#include "wheelwear/contactgeom/kinematics.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/profile_source.hpp"
#include "wheelwear/tangential/contact_model.hpp"
#include "wheelwear/wear/wear_distribution.hpp"

namespace wheelwear::pipeline {

namespace {

// The motion of wheel `side` in its own frame: the right wheel is the mirror image of a left
// one, so lateral quantities and the yaw change sign.
contactgeom::WheelsetMotion wheel_motion(const WheelsetStateSpec& s, int side, double lateral_arm,
                                         contactgeom::SlipPoint slip_point) {
  const double sign = side == 0 ? 1.0 : -1.0;
  contactgeom::WheelsetMotion motion;
  motion.speed = s.speed;
  motion.lateral_velocity = sign * s.lateral_velocity;
  // A right-hand curve (R > 0) turns the wheelset clockwise at V/R, which puts the left wheel
  // on the outer rail, ahead; its own yaw rate (+ counter-clockwise) takes from that.
  motion.yaw_rate = sign * ((s.curve_radius == 0.0 ? 0.0 : s.speed / s.curve_radius) - s.yaw_rate);
  motion.angular_velocity = s.angular_velocity.value_or(0.0);  // 0: on the nominal radius
  motion.lateral_arm = lateral_arm;
  motion.slip_point = slip_point;
  return motion;
}

// The bins of the wheel's wear grid a patch can reach: its width around O, both ways.
LocalWear wear_window(const contactgeom::WheelRailPatch& patch, double region_b,
                      double profile_length) {
  const std::size_t bins = static_cast<std::size_t>(std::ceil(profile_length / kWearBin)) + 1;
  const double reach = 2.0 * std::max(region_b, patch.sdec.b) + 2.0 * kWearBin;
  const double lo = std::max(0.0, patch.s_wheel - reach);
  const double hi = std::min(profile_length, patch.s_wheel + reach);
  LocalWear local;
  local.first = static_cast<std::size_t>(std::floor(lo / kWearBin));
  const std::size_t last = std::min(bins - 1, static_cast<std::size_t>(std::ceil(hi / kWearBin)));
  local.depth.assign(last - local.first + 1, 0.0);
  return local;
}

}  // namespace

double LocalWear::area() const {
  double area = 0.0;
  for (double d : depth) area += d * kWearBin;
  return area;
}

bool WheelOutcome::usable() const {
  return status == contactgeom::WheelRailStatus::ok;
}

DropReason WheelOutcome::drop_reason() const {
  using contactgeom::WheelRailStatus;
  switch (status) {
    case WheelRailStatus::ok:
      return nadal.exceeded ? DropReason::nadal : DropReason::none;
    case WheelRailStatus::flange_climb:
    case WheelRailStatus::past_flange:
      return DropReason::climbing;
    case WheelRailStatus::load_jump:
      return DropReason::load_jump;
    case WheelRailStatus::no_contact:
    case WheelRailStatus::not_converged:
    case WheelRailStatus::profile_end:
      return DropReason::failed;
  }
  return DropReason::failed;
}

bool StateOutcome::dropped() const {
  return wheels[0].drop_reason() != DropReason::none || wheels[1].drop_reason() != DropReason::none;
}

tangential::Method scene_method(tangential::ContactModel model, TangentialMethod tangential) {
  if (tangential == TangentialMethod::best) return tangential::Method::best;
  if (tangential == TangentialMethod::exact) return tangential::Method::exact;
  switch (model) {
    case tangential::ContactModel::sdec:
      return tangential::Method::fastsim_sdec;
    case tangential::ContactModel::eql:
      return tangential::Method::fastsim_eql;
    case tangential::ContactModel::eqe:
      return tangential::Method::fastsim_eqe;
    case tangential::ContactModel::eqe_shifted:
      return tangential::Method::fastsim_eqe_shifted;
    case tangential::ContactModel::hertz:
      return tangential::Method::fastsim_elliptic;
  }
  return tangential::Method::fastsim_sdec;
}

StateKernel::StateKernel(const Scene& scene)
    : scene_(scene),
      rail_(std::make_shared<const profiles::Profile>(
          profiles::rail_profile(scene.rail_profile, scene.rail_inclination, scene.rail_file))),
      law_(wear::TgammaLaw::usfd()),
      method_(scene_method(scene.model, scene.tangential)) {
  if (!scene.wear_law_table.empty()) {
    // The table as the scene read it (the stored copy on resume), not the file as it is now.
    std::istringstream table(scene.wear_law_text);
    if (scene.wear_law == "usfd") law_ = wear::TgammaLaw::read_csv(table, scene.wear_law_table);
    if (scene.wear_law == "archard") law_ = wear::ArchardLaw::read_csv(table, scene.wear_law_table);
  } else {
    const auto law = wear::default_wear_law(scene.wear_law);
    if (!law) throw InputError("scene: wear.law = " + scene.wear_law + ": unknown wear law");
    law_ = *law;
  }
  options_.strip_width = scene.strip_width;
  options_.kp.epsilon = scene.virtual_penetration;
  options_.kp.penetration = scene.normal_method;
  options_.contact_plane = scene.contact_plane;
  options_.max_contact_angle = scene.max_contact_angle;
  options_.validate();
  tangential::FastsimOptions& fastsim = solve_options_.fastsim;
  fastsim.nx = scene.grid_nx;
  fastsim.ny = scene.grid_ny;
  fastsim.scheme = scene.scheme;
  fastsim.cell_fields = true;  // the wear laws need every cell's work and slip
  solve_options_.exact_grid.nx = scene.grid_nx;
  solve_options_.exact_grid.ny = scene.grid_ny;
  solve_options_.validate();
}

contactgeom::RailFriction StateKernel::rail_friction(const WheelsetStateSpec& state) const {
  const double top = state.friction.value_or(scene_.friction);
  const double flange = state.friction_flange ? *state.friction_flange
                        : state.friction      ? *state.friction
                                              : scene_.friction_flange.value_or(top);
  return {top, flange};
}

tangential::Material StateKernel::material() const {
  return {scene_.youngs_modulus / (2.0 * (1.0 + scene_.poisson)), scene_.poisson};
}

contactgeom::WheelRailPair StateKernel::pair(const profiles::Profile& wheel) const {
  contactgeom::WheelRailPair p(wheel, *rail_);
  p.gauge = scene_.gauge;
  p.back_to_back = scene_.back_to_back;
  p.wheel_radius = wheel.info().nominal_radius;
  p.youngs_modulus = scene_.youngs_modulus;
  p.poisson = scene_.poisson;
  p.validate();
  return p;
}

contactgeom::WheelsetContact StateKernel::contact(const contactgeom::WheelsetOnTrack& track,
                                                  const WheelsetStateSpec& s,
                                                  const contactgeom::WheelsetContactTable* table,
                                                  bool* interpolated) const {
  contactgeom::WheelsetState state;
  state.dy = s.dy;
  state.yaw = s.yaw;
  state.vertical_force_left = s.load_left;
  state.vertical_force_right = s.load_right;
  state.lateral_force_left = s.lateral_force_left;
  state.lateral_force_right = s.lateral_force_right;
  if (interpolated) *interpolated = false;
  if (table && scene_.model != tangential::ContactModel::hertz) {
    if (std::optional<contactgeom::WheelsetContact> found = table->contact(state)) {
      if (interpolated) *interpolated = true;
      return std::move(*found);
    }
  }
  return contactgeom::solve_wheelset(track, state, options_);
}

WheelOutcome StateKernel::wheel(const contactgeom::WheelsetContact& both, int side,
                                const WheelsetStateSpec& s, const profiles::Profile& wheel_profile,
                                bool keep_fields) const {
  const contactgeom::WheelRailContact& contact = side == 0 ? both.left : both.right;
  contactgeom::WheelsetPose pose = side == 0 ? both.left_pose : both.right_pose;
  pose.yaw = side == 0 ? s.yaw : -s.yaw;  // this state's yaw: the geometry may be shared
  WheelOutcome out;
  out.status = contact.status;
  out.dy = pose.dy;
  out.vertical_force = contact.vertical_force;
  out.lateral_force = contact.lateral_force;
  out.lateral_fit = side == 0 ? both.left_fit : both.right_fit;
  out.contact_patches = contact.patches.size();
  if (!out.usable()) return out;

  const contactgeom::WheelsetMotion motion =
      wheel_motion(s, side, scene_.lateral_arm, scene_.slip_point);
  const std::optional<tangential::Creepages>& given =
      side == 0 ? s.creepages_left : s.creepages_right;
  const tangential::Material material = this->material();
  const contactgeom::RailFriction friction = rail_friction(s);
  tangential::SolveOptions options = solve_options_;
  // Only the fields the wear needs, unless the cells are kept for T gamma maps.
  options.fastsim.field_set =
      keep_fields ? tangential::CellFieldSet::all : tangential::CellFieldSet::wear;
  // The solution's cell storage is reused from patch to patch on this thread.
  thread_local tangential::TangentialSolution solution;
  for (const contactgeom::WheelRailPatch& patch : contact.patches) {
    PatchOutcome& p = out.patches.emplace_back();
    p.normal_force = patch.normal_force;
    p.sdec = patch.sdec;
    p.y_wheel = patch.y_wheel;
    p.contact_angle = patch.contact_angle;
    std::optional<contactgeom::Sdec> hertz;
    if (patch.hertz) hertz = contactgeom::Sdec{patch.hertz->a, patch.hertz->b, 0.0};
    if (scene_.model == tangential::ContactModel::hertz && !hertz) {
      p.solved = false;
      ++out.hertz_dropped;
      continue;
    }
    const contactgeom::Sdec region =
        tangential::model_patch(scene_.model, patch.sdec, hertz).region;
    p.creepages = given ? *given
                        : contactgeom::kinematic_creepages(patch, pose, motion,
                                                           wheel_profile.info().nominal_radius);
    // A patch of a blend: its description's problem, weighted by its share.
    const tangential::ContactLoad load{contactgeom::description_load(patch),
                                       friction.at(patch.contact_angle)};
    tangential::solve_patch(method_, region, p.creepages, load, material, options, solution);
    p.wear = wear_window(patch, region.b, wheel_profile.length());
    wear::WearDistribution part = wear::WearDistribution::zeros(
        static_cast<double>(p.wear.first) * kWearBin, kWearBin, p.wear.depth.size());
    wear::accumulate_wear(*solution.fields, motion.speed, law_,
                          {patch.s_wheel, patch.rolling_radius}, patch.share, part);
    p.wear.depth = std::move(part.depth);
    // The totals travel with the outcome; the cells only where they are kept.
    p.solution.forces = tangential::weighted(solution.forces, patch.share);
    p.solution.status = solution.status;
    p.solution.message = solution.message;
    p.solution.cells = solution.cells;
    p.solution.slip_cells = solution.slip_cells;
    p.solution.frictional_work = patch.share * solution.frictional_work;
    p.solution.from_table = solution.from_table;
    if (keep_fields) {
      // A T gamma map needs the work density and the cell positions, not every field.
      tangential::CellFields& kept = p.solution.fields.emplace();
      kept.nx = solution.fields->nx;
      kept.ny = solution.fields->ny;
      kept.work = solution.fields->work;
      if (patch.share != 1.0)
        for (double& w : kept.work) w *= patch.share;
      kept.x = solution.fields->x;
      kept.y = solution.fields->y;
    }
  }
  std::vector<double> creep_Fy;
  for (const PatchOutcome& p : out.patches)
    creep_Fy.push_back(p.solved ? p.solution.forces.Fy : 0.0);
  out.nadal = contactgeom::nadal_check(contact, friction.flange, creep_Fy);
  return out;
}

StateOutcome StateKernel::evaluate(const contactgeom::WheelsetOnTrack& track,
                                   const WheelsetStateSpec& state, bool keep_fields) const {
  const contactgeom::WheelsetContact both = contact(track, state);
  StateOutcome out;
  out.roll = both.roll;
  out.wheels[0] = wheel(both, 0, state, track.left.wheel, keep_fields);
  out.wheels[1] = wheel(both, 1, state, track.right.wheel, keep_fields);
  return out;
}

}  // namespace wheelwear::pipeline
