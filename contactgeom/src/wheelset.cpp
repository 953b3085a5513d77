#include "wheelwear/contactgeom/wheelset.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "bracketed_root.hpp"
#include "wheel_rail_gap.hpp"
#include "wheel_rail_solve.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

namespace {

// The lateral search for a prescribed lateral force reaches this far from the given position [m].
constexpr double kLateralReach = 20e-3;
// First step of that search [m]; later steps grow by half.
constexpr double kLateralStep = 0.5e-3;
// First step of that search from a guess [m].
constexpr double kWarmStep = 0.05e-3;
// Where the flange just unloads is located to this [m].
constexpr double kUnloadResolution = 10e-6;
// The roll iteration stops when the height residual is below this [m].
constexpr double kRollResidual = 1e-11;
// The roll is sought within this [rad] (WheelsetPose requires |roll| < 0.1).
constexpr double kMaxRoll = 0.09;
// The alternation of roll and lateral positions stops when the roll changes less than this [rad].
constexpr double kRollChange = 1e-9;

// The flange statuses carry the load too: the lateral search may pass through them.
bool flange_loaded(const WheelRailContact& c, double flange_angle) {
  return std::any_of(c.patches.begin(), c.patches.end(), [&](const WheelRailPatch& p) {
    return p.contact_angle > flange_angle && p.normal_force > 0.0;
  });
}

// The lateral-force solve of one wheel, the rail's gauge point given.
// `guess`: a shift near the answer (the previous one of the wheelset's alternation), or 0.
WheelRailLateral lateral_at(const WheelRailPair& pair, const WheelsetPose& pose, double Fz,
                            double Fy, const WheelRailOptions& options, double gauge_y,
                            double guess) {
  WheelRailLateral out;
  out.pose = pose;
  const double tol = options.lateral_tolerance * Fz;
  auto contact_at = [&](double e) {
    WheelsetPose p = pose;
    p.dy = pose.dy + e;
    ++out.evaluations;
    return detail::solve_wheel_rail_at(pair, p, Fz, options, gauge_y);
  };
  auto finish = [&](double e, WheelRailContact c, LateralFit fit) {
    out.shift = e;
    out.pose.dy = pose.dy + e;
    out.contact = std::move(c);
    out.fit = fit;
    return out;
  };

  // Later rounds of the wheelset's alternation start from the previous shift, the roll having
  // changed by micro-radians: where the flange carries load there, the search starts from it
  // with small steps (and the given position's own contact, which decides only whether the
  // position is kept, was looked at in the first round).
  double e_in = 0.0, f_in = 0.0;  // last point on the starting side
  WheelRailContact c_in;
  double first_step = kLateralStep;
  bool warm = false;
  if (guess != 0.0 && std::abs(guess) < kLateralReach) {
    WheelRailContact cg = contact_at(guess);
    if (carries_load(cg.status) && flange_loaded(cg, options.flange_angle)) {
      const double fg = cg.lateral_force - Fy;
      if (std::abs(fg) <= tol) return finish(guess, std::move(cg), LateralFit::matched);
      e_in = guess;
      f_in = fg;
      c_in = std::move(cg);
      first_step = kWarmStep;
      warm = true;
    }
  }
  if (!warm) {
    WheelRailContact c0 = contact_at(0.0);
    if (!carries_load(c0.status)) {
      out.message = "no contact to adjust at the given position: " + c0.message;
      return finish(0.0, std::move(c0), LateralFit::not_matched);
    }
    const double f0 = c0.lateral_force - Fy;
    if (std::abs(f0) <= tol) return finish(0.0, std::move(c0), LateralFit::matched);
    if (f0 > 0.0 && !flange_loaded(c0, options.flange_angle))
      return finish(0.0, std::move(c0), LateralFit::kept_position);
    f_in = f0;
    c_in = std::move(c0);
  }

  // Bracket: towards the flange when more force is wanted, away from it when less.
  const double direction = f_in < 0.0 ? 1.0 : -1.0;
  const double f_start = f_in;
  double e_out = 0.0, f_out = f_in;
  bool bracketed = false;
  for (double step = first_step; std::abs(e_in) < kLateralReach; step *= 1.5) {
    const double e = e_in + direction * std::min(step, kLateralReach - std::abs(e_in) + 1e-12);
    WheelRailContact c = contact_at(e);
    if (!carries_load(c.status)) {
      out.message = "the lateral force " + std::to_string(Fy) + " N is not reached before " +
                    std::string(status_name(c.status)) + " at a shift of " + std::to_string(e) +
                    " m";
      return finish(e_in, std::move(c_in), LateralFit::not_matched);
    }
    const double f = c.lateral_force - Fy;
    if (direction < 0.0 && f > 0.0 && !flange_loaded(c, options.flange_angle)) {
      // The flange unloads before the force drops to the target: the tread alone gives more.
      // Locate where the flange unloads, between e_in (loaded) and e (not).
      double loaded = e_in, unloaded = e;
      WheelRailContact c_unloaded = std::move(c);
      while (std::abs(loaded - unloaded) > kUnloadResolution) {
        const double mid = 0.5 * (loaded + unloaded);
        WheelRailContact cm = contact_at(mid);
        if (carries_load(cm.status) && !flange_loaded(cm, options.flange_angle)) {
          unloaded = mid;
          c_unloaded = std::move(cm);
        } else {
          loaded = mid;
        }
      }
      return finish(unloaded, std::move(c_unloaded), LateralFit::flange_unloaded);
    }
    if (std::abs(f) <= tol) return finish(e, std::move(c), LateralFit::matched);
    if ((f > 0.0) != (f_start > 0.0)) {
      e_out = e;
      f_out = f;
      bracketed = true;
      break;
    }
    e_in = e;
    f_in = f;
    c_in = std::move(c);
  }
  if (!bracketed) {
    out.message = "the lateral force " + std::to_string(Fy) + " N is not reached within " +
                  std::to_string(kLateralReach) + " m of the given position";
    return finish(e_in, std::move(c_in), LateralFit::not_matched);
  }

  // The contact at the best shift seen is kept: the root finder answers with it.
  double best_e = 0.0, best_f = std::numeric_limits<double>::infinity();
  WheelRailContact best;
  auto residual = [&](double e) {
    WheelRailContact c = contact_at(e);
    const double f = c.lateral_force - Fy;
    if (std::abs(f) < std::abs(best_f)) {
      best_e = e;
      best_f = f;
      best = std::move(c);
    }
    return f;
  };
  const detail::RootResult root =
      detail::find_root_bracketed(residual, e_in, f_in, e_out, f_out, tol, 1e-9, 60);
  WheelRailContact c = root.x == best_e ? std::move(best) : contact_at(root.x);
  if (!root.converged) {
    out.message = "the lateral force jumps across " + std::to_string(Fy) + " N at a shift of " +
                  std::to_string(root.x) + " m (the load moves between contact regions); it is " +
                  std::to_string(c.lateral_force) + " N there";
    return finish(root.x, std::move(c), LateralFit::not_matched);
  }
  return finish(root.x, std::move(c), LateralFit::matched);
}

// The wheelset's fixed geometry: the rigid-body placement of wheelset.hpp.
struct Placement {
  double y_left = 0.0, y_right = 0.0;          // taping points' distances from the centre [m]
  double r_left = 0.0, r_right = 0.0;          // wheel radii at the taping points [m]
  double base_left = 0.0, base_right = 0.0;    // z_tape - z_top per side [m]
  double gauge_left = 0.0, gauge_right = 0.0;  // rails' gauge points [m]

  WheelsetPose left(const WheelsetState& s, double roll, double shift) const {
    WheelsetPose p;
    p.dy = s.dy + (std::cos(roll) - 1.0) * y_left - std::sin(roll) * r_left + shift;
    p.roll = roll;
    p.yaw = s.yaw;
    return p;
  }
  WheelsetPose right(const WheelsetState& s, double roll, double shift) const {
    WheelsetPose p;
    p.dy = -s.dy + (std::cos(roll) - 1.0) * y_right + std::sin(roll) * r_right + shift;
    p.roll = -roll;
    p.yaw = -s.yaw;
    return p;
  }
};

double top_depth(const WheelRailPair& pair) {
  const auto tape = pair.wheel.surface_at(0.0);
  return (tape ? tape->z : 0.0) - detail::rail_datum(pair).top_z;
}

void validate_state(const WheelsetOnTrack& track, const WheelsetState& s) {
  require_finite("dy", s.dy);
  require(std::abs(s.dy) < 0.1, "dy", s.dy, "the wheelset's lateral shift must be below 0.1 m");
  require_finite("yaw", s.yaw);
  require(std::abs(s.yaw) < 0.1, "yaw", s.yaw, "the yaw angle must be small (< 0.1 rad)");
  require_finite("vertical_force_left", s.vertical_force_left);
  require(s.vertical_force_left > 0.0, "vertical_force_left", s.vertical_force_left,
          "the vertical wheel load must be positive (newtons)");
  require_finite("vertical_force_right", s.vertical_force_right);
  require(s.vertical_force_right > 0.0, "vertical_force_right", s.vertical_force_right,
          "the vertical wheel load must be positive (newtons)");
  if (s.known_roll) {
    require_finite("known_roll.roll", s.known_roll->roll);
    require(std::abs(s.known_roll->roll) <= kMaxRoll, "known_roll.roll", s.known_roll->roll,
            "a wheelset's roll lies within 0.09 rad");
    require_finite("known_roll.centre_height", s.known_roll->centre_height);
  }
  if (s.lateral_force_left) require_finite("lateral_force_left", *s.lateral_force_left);
  if (s.lateral_force_right) require_finite("lateral_force_right", *s.lateral_force_right);
  track.left.validate();
  track.right.validate();
  require(std::abs(track.left.gauge - track.right.gauge) < 1e-9, "right.gauge", track.right.gauge,
          "both pairs of a wheelset must have the same track gauge (m)");
  require(std::abs(track.left.back_to_back - track.right.back_to_back) < 1e-9, "right.back_to_back",
          track.right.back_to_back,
          "both pairs of a wheelset must have the same back-to-back distance (m)");
}

}  // namespace

namespace {
constexpr core::NameTable<LateralFit, 5> kFitNames = {{
    {LateralFit::not_prescribed, "not prescribed"},
    {LateralFit::matched, "matched"},
    {LateralFit::kept_position, "kept position"},
    {LateralFit::flange_unloaded, "flange unloaded"},
    {LateralFit::not_matched, "not matched"},
}};
}  // namespace

// The table's names are string literals: data() is null-terminated.
const char* lateral_fit_name(LateralFit fit) {
  return core::name_of(kFitNames, fit).data();
}

WheelRailLateral solve_wheel_rail_lateral(const WheelRailPair& pair, const WheelsetPose& pose,
                                          double vertical_force, double lateral_force,
                                          const WheelRailOptions& options) {
  detail::validate_loaded_contact(pair, pose, vertical_force, options);
  require_finite("lateral_force", lateral_force);
  return lateral_at(pair, pose, vertical_force, lateral_force, options, detail::rail_gauge_y(pair),
                    0.0);
}

WheelsetContact solve_wheelset(const WheelsetOnTrack& track, const WheelsetState& state,
                               const WheelRailOptions& options) {
  validate_state(track, state);
  options.validate();
  Placement at;
  at.y_left = 0.5 * track.left.back_to_back - track.left.flange_back_y;
  at.y_right = 0.5 * track.right.back_to_back - track.right.flange_back_y;
  at.r_left = track.left.wheel_radius;
  at.r_right = track.right.wheel_radius;
  at.base_left = top_depth(track.left);
  at.base_right = top_depth(track.right);
  at.gauge_left = detail::rail_gauge_y(track.left);
  at.gauge_right = detail::rail_gauge_y(track.right);
  const double D = at.y_left + at.y_right;

  WheelsetContact out;
  double shift_left = 0.0, shift_right = 0.0;
  // Height residual of the rigid wheelset at a roll: what the roll lifts the left taping point
  // above the right one, minus what the rails ask for. Sets `touch` false without contact.
  bool touch = true;
  double centre = 0.0, centre_roll = std::numeric_limits<double>::quiet_NaN();
  // A wheel rests on the lowest of its gap's minima whose contact is less steep than
  // atan(D / r): on a steeper flank (a worn one; a new S1002's is 1.22 rad) lifting the wheel by
  // the roll pushes the flank into its rail faster than it rises, so a rigid wheelset has no
  // roll that touches there and the next one lies millimetres up the flank. Such a flank is
  // met by the contact's approach instead, its load rising continuously with the shift.
  const double steepest_left = std::atan(D / at.r_left);
  const double steepest_right = std::atan(D / at.r_right);
  auto residual = [&](double roll) {
    const WheelRailTouch l = detail::first_touch_at(track.left, at.left(state, roll, shift_left),
                                                    options, at.gauge_left, steepest_left);
    const WheelRailTouch r = detail::first_touch_at(track.right, at.right(state, roll, shift_right),
                                                    options, at.gauge_right, steepest_right);
    ++out.touch_evaluations;
    touch = l.found && r.found;
    if (!touch) return 0.0;
    const double z_left = at.base_left + l.resting_gap, z_right = at.base_right + r.resting_gap;
    centre = -(z_left - std::sin(roll) * at.y_left - std::cos(roll) * at.r_left);
    centre_roll = roll;
    return std::sin(roll) * D + std::cos(roll) * (at.r_left - at.r_right) - (z_left - z_right);
  };
  // The residual rises with the roll (the lever D) less the rails' answer, which moves a wheel
  // on its flange up by r tan(angle) per radian of roll: it stays increasing until the flange
  // angle reaches atan(D/r) (1.27 rad for a 0.46 m wheel on standard gauge), where the flange
  // climbs. A Newton step with the slope D brackets the root, then Anderson-Bjorck regula falsi
  // (bracketed_root.hpp) finds it.
  auto solve_roll = [&](double start) {
    out.roll_converged = false;
    double lo = start, f_lo = residual(lo);
    if (!touch) return start;
    if (std::abs(f_lo) <= kRollResidual) {
      out.roll_converged = true;
      return start;
    }
    double step = -f_lo / D;
    double hi = lo, f_hi = f_lo;
    for (int i = 0; i < 40 && (f_hi > 0.0) == (f_lo > 0.0); ++i) {
      lo = hi;
      f_lo = f_hi;
      hi = std::clamp(lo + step, -kMaxRoll, kMaxRoll);
      f_hi = residual(hi);
      if (!touch) return start;
      if (std::abs(f_hi) <= kRollResidual) {
        out.roll_converged = true;
        return hi;
      }
      if (hi == lo) break;  // at the limit of the roll
      // Past the first step, the measured slope may be shallower than D (flange contact).
      const double measured = (f_hi - f_lo) / (hi - lo);
      step = std::isfinite(measured) && measured > 0.01 * D ? -f_hi / measured : 2.0 * step;
      step = std::copysign(std::max(std::abs(step), 1e-9), step);
    }
    if ((f_hi > 0.0) == (f_lo > 0.0)) return hi;
    const detail::RootResult root =
        detail::find_root_bracketed(residual, lo, f_lo, hi, f_hi, kRollResidual, 1e-14, 60);
    out.roll_converged = root.converged && touch;
    if (centre_roll != root.x) residual(root.x);  // the centre's height at the answer
    return root.x;
  };

  const bool prescribed = state.lateral_force_left || state.lateral_force_right;
  double roll = 0.0;
  const bool reuse = state.known_roll && !prescribed && state.known_roll->dy == state.dy &&
                     state.known_roll->yaw == state.yaw;
  if (reuse) {
    roll = state.known_roll->roll;
    centre = state.known_roll->centre_height;
    out.roll_converged = state.known_roll->converged;
  } else {
    roll = solve_roll(0.0);
  }
  WheelRailLateral lateral_left, lateral_right;
  bool alternation_converged = !prescribed;
  double previous_roll = 0.0, previous_r = 0.0;
  for (int round = 0; touch && prescribed && round < 12; ++round) {
    if (state.lateral_force_left) {
      lateral_left = lateral_at(track.left, at.left(state, roll, 0.0), state.vertical_force_left,
                                *state.lateral_force_left, options, at.gauge_left, shift_left);
      shift_left = lateral_left.shift;
      out.contact_solves += lateral_left.evaluations;
    }
    if (state.lateral_force_right) {
      lateral_right =
          lateral_at(track.right, at.right(state, roll, 0.0), state.vertical_force_right,
                     *state.lateral_force_right, options, at.gauge_right, shift_right);
      shift_right = lateral_right.shift;
      out.contact_solves += lateral_right.evaluations;
    }
    // A force that falls in a jump of Fy(dy) is not met; the side the search stops on may
    // flip with the roll, so the alternation ends with that wheel at its last position.
    const bool unmatched =
        lateral_left.fit == LateralFit::not_matched || lateral_right.fit == LateralFit::not_matched;
    const double next = solve_roll(roll);
    if (std::abs(next - roll) <= kRollChange || !touch || unmatched) {
      alternation_converged = true;
      break;
    }
    // The alternation is a fixed-point iteration roll -> next; secant steps on next - roll = 0
    // (Steffensen-like) cut its linear convergence short.
    const double r = next - roll;
    double step_to = next;
    if (round > 0 && r != previous_r) {
      const double secant = roll - r * (roll - previous_roll) / (r - previous_r);
      if (std::isfinite(secant) && std::abs(secant) < kMaxRoll) step_to = secant;
    }
    previous_roll = roll;
    previous_r = r;
    roll = step_to;
  }
  out.roll = roll;
  out.left_pose = at.left(state, roll, shift_left);
  out.right_pose = at.right(state, roll, shift_right);
  if (!touch) {
    out.message = "a wheel does not reach its rail: the profiles do not overlap laterally";
    out.left = detail::solve_wheel_rail_at(track.left, out.left_pose, state.vertical_force_left,
                                           options, at.gauge_left);
    out.right = detail::solve_wheel_rail_at(track.right, out.right_pose, state.vertical_force_right,
                                            options, at.gauge_right);
    return out;
  }
  out.centre_height = centre;
  if (!prescribed)
    out.known_roll = KnownRoll{state.dy, state.yaw, roll, centre, out.roll_converged};
  // Each wheel: the contact its lateral-force solve found, or the one at its rigid position.
  auto finish = [&](bool given, WheelRailLateral& lateral, const WheelRailPair& pair,
                    double vertical_force, double gauge_y, const char* side, WheelsetPose& pose,
                    double& shift, WheelRailContact& contact, LateralFit& fit) {
    if (given) {
      pose = lateral.pose;
      shift = lateral.shift;
      contact = std::move(lateral.contact);
      fit = lateral.fit;
      if (!lateral.message.empty()) out.message += side + (": " + lateral.message) + "; ";
    } else {
      contact = detail::solve_wheel_rail_at(pair, pose, vertical_force, options, gauge_y);
      ++out.contact_solves;
    }
  };
  finish(state.lateral_force_left.has_value(), lateral_left, track.left, state.vertical_force_left,
         at.gauge_left, "left", out.left_pose, out.left_shift, out.left, out.left_fit);
  finish(state.lateral_force_right.has_value(), lateral_right, track.right,
         state.vertical_force_right, at.gauge_right, "right", out.right_pose, out.right_shift,
         out.right, out.right_fit);
  if (!alternation_converged) {
    out.roll_converged = false;
    out.message += "roll and lateral positions did not settle in 12 rounds; ";
  }
  if (!out.roll_converged) out.message += "the roll iteration did not converge";
  return out;
}

}  // namespace wheelwear::contactgeom
