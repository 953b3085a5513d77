#include "wheelwear/vehicle/quasi_static_curving.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "curving_problem.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::vehicle {

using detail::applied_force;
using detail::bogie_index;
using detail::CurvingProblem;
using detail::Evaluation;
using detail::initial_guess;
using detail::partial_curve;
using detail::placement;
using detail::Placement;
using detail::unknowns;
using detail::Vector;
using detail::wheelset_index;

std::array<double, 2> wheel_loads(const Vehicle& v, const SteadyCurve& curve, double lateral_arm,
                                  double car_body_y, double bogie_y, double wheelset_y) {
  struct Share {
    double mass, height, y;
  };
  const std::array<Share, 3> shares{
      Share{v.car_body.mass / kWheelsets, v.car_body.cg_height, car_body_y},
      Share{v.bogie.mass / 2.0, v.bogie.cg_height, bogie_y},
      Share{v.wheelset.body.mass, v.wheelset.body.cg_height, wheelset_y}};
  double weight = 0.0, moment = 0.0;  // e (Q_left - Q_right) = moment
  for (const Share& s : shares) {
    const double w = curve.normal_force(s.mass);
    weight += w;
    moment += w * s.y + s.height * applied_force(curve, s.mass);
  }
  const double difference = moment / lateral_arm;
  return {0.5 * (weight + difference), 0.5 * (weight - difference)};
}

void require_upright(const Vehicle& vehicle, const SteadyCurve& curve, double lateral_arm) {
  // The centred vehicle's wheel loads: where the curve's unbalanced lateral acceleration tips a
  // wheel off its rail, no balance exists (and a load below zero is no contact to solve).
  const auto loads = wheel_loads(vehicle, curve, lateral_arm, 0.0, 0.0, 0.0);
  const double least = std::min(loads[0], loads[1]);
  if (least > 0.0) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "the vehicle overturns in this curve: at R %g m, cant %g m and %g m/s (cant "
                "deficiency %.3f m) its %s wheels carry %.1f kN even with every body centred; "
                "lower the speed or raise the cant",
                curve.running.curve_radius, curve.cant, curve.running.speed,
                curve.cant_deficiency(), loads[0] < loads[1] ? "left" : "right", least * 1e-3);
  throw InputError(text);
}

void require_adhesion(const Vehicle& vehicle, const SteadyCurve& curve, double lateral_arm) {
  if (curve.traction == 0.0) return;
  // Every wheelset of the centred vehicle carries the same loads.
  const auto loads = wheel_loads(vehicle, curve, lateral_arm, 0.0, 0.0, 0.0);
  for (int k = 0; k < kWheelsets; ++k) {
    // A powered axle carries its traction or braking through the creep forces, at most
    // mu (Q_left + Q_right): beyond it the wheels slip or slide and no balance exists.
    if (!vehicle.powered[static_cast<std::size_t>(k)]) continue;
    const double adhesion = curve.running.friction * (loads[0] + loads[1]);
    if (std::abs(curve.traction) < adhesion) continue;
    char text[320];
    std::snprintf(text, sizeof text,
                  "%s of %.1f kN per powered axle is beyond the adhesion of wheelset %d, "
                  "friction %g times its %.1f kN of wheel load = %.1f kN: its wheels %s; "
                  "give at most that",
                  curve.traction > 0.0 ? "traction" : "braking", std::abs(curve.traction) * 1e-3,
                  k + 1, curve.running.friction, (loads[0] + loads[1]) * 1e-3, adhesion * 1e-3,
                  curve.traction > 0.0 ? "would slip" : "would slide");
    throw InputError(text);
  }
}

VehiclePlacement placement_of(const VehicleCurving& curving) {
  VehiclePlacement p;
  p.car_body = curving.car_body;
  p.bogies = curving.bogies;
  for (int k = 0; k < kWheelsets; ++k) p.wheelsets[k] = curving.wheelsets[k].state;
  return p;
}

VehicleCurving solve_vehicle_curving(const Vehicle& vehicle,
                                     const std::array<WheelsetModel, kWheelsets>& wheelsets,
                                     const SteadyCurve& curve, const CurvingOptions& options) {
  vehicle.validate();
  curve.validate();
  require(options.max_iterations > 0, "max iterations", options.max_iterations, "must be positive");
  require(std::isfinite(options.force_tolerance) && options.force_tolerance > 0.0,
          "force tolerance", options.force_tolerance, "must be positive");

  for (int k = 0; k < kWheelsets; ++k) {
    require_upright(vehicle, curve, wheelsets[k].lateral_arm);
    require_adhesion(vehicle, curve, wheelsets[k].lateral_arm);
  }
  VehicleCurving result;
  result.cant_deficiency = curve.cant_deficiency();
  Vector u = initial_guess(wheelsets, curve);
  Evaluation e;
  bool converged = false;
  std::string message;
  // The tabulated contact (WheelsetModel::table) is linear between its nodes, and Newton can
  // stall at their kinks short of the tolerance, or at a jump of a worn tread's geometry that
  // the direct contacts pass. The attempt at the whole curve that came nearest is remembered.
  std::optional<Vector> nearest;
  double nearest_residual = std::numeric_limits<double>::infinity();
  bool nearest_from_start = false;
  const auto remember = [&](const CurvingProblem& problem, bool from_start) {
    const double residual = problem.scaled(e).norm();
    if (residual < nearest_residual) {
      nearest_residual = residual;
      nearest = u;
      nearest_from_start = from_start;
    }
  };
  const bool tabulated = std::any_of(wheelsets.begin(), wheelsets.end(),
                                     [](const WheelsetModel& m) { return m.table != nullptr; });
  // The models without their tables, copied only where needed (they hold the profiles).
  std::optional<std::array<WheelsetModel, kWheelsets>> untabulated;
  const auto direct = [&]() -> const std::array<WheelsetModel, kWheelsets>& {
    if (!untabulated) {
      untabulated = wheelsets;
      for (WheelsetModel& m : *untabulated) m.table.reset();
    }
    return *untabulated;
  };
  // Newton from the nearest failed attempt, on the direct contacts, where it came near: the
  // stalls at a table's kink end at scaled residual norms of 1.4 to 2e4 (new S1002/60E1, the
  // built-in route's R 1500 m); attempts that went astray on a worn tread end at 1e5 to 1e8 and
  // are better restarted.
  constexpr double kNearEnough = 1e5;
  const auto finish_directly = [&] {
    if (!nearest || nearest_residual > kNearEnough) return false;
    Vector v = *nearest;
    Evaluation f;
    std::string why;
    const CurvingProblem problem(vehicle, direct(), curve, options, result.wheelset_evaluations);
    try {
      if (!problem.solve(v, f, result.iterations, why)) {
        message += "; finished with direct contacts: " + why;
        return false;
      }
    } catch (const InputError& error) {
      message += std::string("; finished with direct contacts: ") + error.what();
      return false;
    }
    u = v;
    e = std::move(f);
    return true;
  };
  // Straight to the curve first; where that fails (a flange contact Newton overshoots), in
  // steps of curvature and cant from tangent track, each from the last one's state.
  const auto continuation = [&](const std::array<WheelsetModel, kWheelsets>& models,
                                std::initializer_list<int> attempts) {
    for (int steps : attempts) {
      u = initial_guess(models, curve);
      bool reached = true;
      for (int s = 1; s <= steps && reached; ++s) {
        const CurvingProblem problem(vehicle, models, partial_curve(curve, double(s) / steps),
                                     options, result.wheelset_evaluations);
        std::string why;
        reached = problem.solve(u, e, result.iterations, why);
        if (!reached) message = why;
        if (!reached && s == steps) remember(problem, false);
      }
      result.continuation_steps = steps;
      if (reached) return true;
    }
    return false;
  };
  bool started = false;  // Newton ran from options.start
  if (options.start) {
    u = unknowns(*options.start);
    bool valid = u.allFinite();
    for (int k = 0; k < kWheelsets; ++k) valid = valid && u[wheelset_index(k) + 2] > 0.0;
    if (valid) {
      const CurvingProblem problem(vehicle, wheelsets, curve, options, result.wheelset_evaluations);
      try {
        converged = problem.solve(u, e, result.iterations, message);
        started = true;
        if (!converged) remember(problem, true);
      } catch (const InputError&) {
        converged = false;  // the start lies beyond the profiles now: start afresh
      }
      result.from_start = converged;
    }
  }
  // A start that could not be used (not finite, no spin, beyond the profiles) is no attempt:
  // the solve starts afresh whatever restart_on_failure says.
  const bool fresh = !options.start || options.restart_on_failure || !started;
  // On a table only the straight attempt: its continuation rarely reaches what the direct
  // contacts do not (measured on worn profiles it cost as much as their whole solve).
  if (!converged && fresh)
    converged = tabulated ? continuation(wheelsets, {1}) : continuation(wheelsets, {1, 4, 16});
  // On a table: from the nearest failed attempt with direct contacts, then (a fresh solve)
  // afresh with them, where the table's kinks led every attempt astray.
  if (!converged && tabulated) {
    converged = finish_directly();
    result.from_start = converged && nearest_from_start;
    if (!converged && fresh) {
      const std::string table_message = message;
      converged = continuation(direct(), {1, 4, 16});
      if (!converged) message = table_message + "; afresh with direct contacts: " + message;
    }
    result.finished_directly = converged;
  }
  result.converged = converged;
  if (!converged) result.message = message;
  const Placement p = placement(u);
  result.car_body = p.car_body;
  result.bogies = p.bogies;
  result.body_balances[0] = {e.residual[0], e.residual[1]};
  for (int i = 0; i < kBogies; ++i)
    result.body_balances[1 + i] = {e.residual[bogie_index(i)], e.residual[bogie_index(i) + 1]};
  result.wheelsets = std::move(e.wheelsets);
  return result;
}

}  // namespace wheelwear::vehicle
