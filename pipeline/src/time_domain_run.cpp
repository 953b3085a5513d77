// The time-domain pieces of a vehicle run: the irregularities each one runs over and the states
// its simulation gives the collective.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/pipeline/vehicle_run.hpp"

namespace wheelwear::pipeline {

namespace {

// Spacing of a generated record [m]: a twelfth of the shortest wavelength (3 m), far below
// the dynamics' slope stencil of +-0.25 m, so the record's linear interpolation adds nothing.
constexpr double kRecordSpacing_m = 0.25;

// Whether a wheelset at `distance` runs through the piece's stretch; the ends' tolerance takes
// the rounding of the samples' distances.
bool in_stretch(const DynamicPiece& piece, double distance) {
  const double tolerance = 1e-9 * (1.0 + std::abs(piece.start_m + piece.length_m));
  return distance >= piece.start_m - tolerance &&
         distance <= piece.start_m + piece.length_m + tolerance;
}

std::string sample_label(const DynamicPiece& piece, int k, double distance) {
  char text[64];
  std::snprintf(text, sizeof text, ", wheelset %d, s = %.1f m", k + 1, distance);
  return piece.label + text;
}

// Where the wheelsets of `piece` run, from the trailing one's start to the leading one's end.
std::pair<double, double> wheelsets_range(const DynamicPiece& piece, double run_in,
                                          const vehicle::Vehicle& vehicle) {
  return {piece.sim_start_m - run_in + vehicle.wheelset_x(vehicle::kWheelsets - 1),
          piece.sim_start_m + piece.sim_length_m + vehicle.wheelset_x(0)};
}

// A measured record must cover the piece: outside it the track would be ideal, and a wheelset
// crossing its end would see a step.
void check_coverage(const DynamicPiece& piece, const TimeDomainKeys& keys,
                    const vehicle::Vehicle& vehicle) {
  const auto [from, to] = wheelsets_range(piece, keys.run_in, vehicle);
  const std::vector<double>& s = keys.measured.distance;
  if (!s.empty() && s.front() <= from && s.back() >= to) return;
  char text[256];
  std::snprintf(text, sizeof text,
                "covers %.1f ... %.1f m of the route, but the wheelsets of the piece of %s run "
                "from %.1f to %.1f m",
                s.empty() ? 0.0 : s.front(), s.empty() ? 0.0 : s.back(), piece.label.c_str(), from,
                to);
  throw InputError(
      "[time_domain] irregularities = \"" + keys.irregularity_file + "\": " + text +
      "; give a record of the whole route (distance along it, from before its start by "
      "the run-in and half the vehicle's length), or generate one (erri-low)");
}

}  // namespace

vehicle::TrackIrregularities piece_irregularities(const DynamicPiece& piece,
                                                  const TimeDomainKeys& time_domain,
                                                  const vehicle::Vehicle& vehicle) {
  switch (time_domain.irregularities) {
    case IrregularitySource::none:
      return {};
    case IrregularitySource::file:
      check_coverage(piece, time_domain, vehicle);
      return time_domain.measured;
    case IrregularitySource::erri_low:
    case IrregularitySource::erri_high:
      break;
  }
  vehicle::IrregularitySpec spec;
  spec.spectrum = time_domain.irregularities == IrregularitySource::erri_high
                      ? vehicle::ErriSpectrum::high()
                      : vehicle::ErriSpectrum::low();
  spec.run_in = time_domain.run_in;
  // From where the leading wheelset starts to past where it ends, with room for the slope's
  // stencil; the trailing wheelsets enter the record after the leading one.
  const double lead = vehicle.wheelset_x(0);
  const double from = piece.sim_start_m - time_domain.run_in + lead;
  const double to = piece.sim_start_m + piece.sim_length_m + lead + 1.0;
  vehicle::TrackIrregularities record =
      vehicle::generate_irregularities(spec, to - from, kRecordSpacing_m, piece.seed);
  for (double& s : record.distance) s += from;
  return record;
}

namespace {

// The samples wheelset k would have had in the stretch had the simulation completed: the car
// body's samples fall sample_spacing apart from the first, so the wheelset's do from its first.
// At least 1, so that a wheelset that was never sampled gets the whole of its part.
long planned_in_stretch(const DynamicPiece& piece, const vehicle::VehicleMotion& motion,
                        std::size_t k) {
  if (motion.samples.empty()) return 1;
  const double first = motion.samples.front().wheelsets[k].distance;
  long count = 0;
  for (long i = 0; i < motion.planned_samples; ++i)
    if (in_stretch(piece, first + static_cast<double>(i) * motion.sample_spacing)) ++count;
  return std::max(count, 1L);
}

}  // namespace

StartStates start_states(const RouteCase& route_case, const vehicle::VehicleCurving& curving) {
  StartStates states;
  for (int k = 0; k < vehicle::kWheelsets; ++k)
    states[static_cast<std::size_t>(k)] = wheelset_state(route_case, curving, k, 1.0);
  return states;
}

std::vector<WheelsetStateSpec> piece_states(const DynamicPiece& piece,
                                            const vehicle::VehicleMotion& motion,
                                            const RouteCase& start_case,
                                            const vehicle::VehicleCurving& start,
                                            const std::vector<int>& worn, PieceRun& summary) {
  return piece_states(piece, motion, start_states(start_case, start), worn, summary);
}

std::vector<WheelsetStateSpec> piece_states(const DynamicPiece& piece,
                                            const vehicle::VehicleMotion& motion,
                                            const StartStates& start, const std::vector<int>& worn,
                                            PieceRun& summary) {
  summary = {};
  summary.completed = motion.completed;
  summary.message = motion.message;
  summary.time_step = motion.time_step;
  summary.steps = motion.steps;
  for (int k = 0; k < vehicle::kWheelsets; ++k) {
    const auto K = static_cast<std::size_t>(k);
    double dy2 = 0.0, yaw2 = 0.0;
    for (const vehicle::VehicleSample& sample : motion.samples) {
      const vehicle::WheelsetMotionSample& w = sample.wheelsets[K];
      if (!in_stretch(piece, w.distance)) continue;
      ++summary.samples[K];
      if (w.forces.load_jump) ++summary.load_jumps[K];
      dy2 += w.state.dy * w.state.dy;
      yaw2 += w.state.yaw * w.state.yaw;
      summary.dy_max[K] = std::max(summary.dy_max[K], std::abs(w.state.dy));
      for (const vehicle::WheelForces& wheel : w.forces.wheels)
        if (wheel.Q > 0.0) summary.y_over_q[K] = std::max(summary.y_over_q[K], wheel.Y / wheel.Q);
    }
    const double n = summary.samples[K];
    if (n == 0.0) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      summary.dy_rms[K] = summary.dy_max[K] = summary.yaw_rms[K] = summary.y_over_q[K] = nan;
      continue;
    }
    summary.dy_rms[K] = std::sqrt(dy2 / n);
    summary.yaw_rms[K] = std::sqrt(yaw2 / n);
  }

  std::vector<WheelsetStateSpec> states;
  const double per_wheelset = piece.share / static_cast<double>(worn.size());
  for (int k : worn) {
    const auto K = static_cast<std::size_t>(k);
    const int n = summary.samples[K];
    const long planned =
        std::max<long>({1L, n, motion.completed ? 0L : planned_in_stretch(piece, motion, K)});
    const double weight = per_wheelset / static_cast<double>(planned);
    for (const vehicle::VehicleSample& sample : motion.samples) {
      const vehicle::WheelsetMotionSample& w = sample.wheelsets[K];
      if (!in_stretch(piece, w.distance)) continue;
      states.push_back(
          motion_state(w.state, w.forces, w.running, sample_label(piece, k, w.distance), weight));
      mark_wheelset(states.back(), k, piece.reversed);
    }
    if (planned > n) {
      // The part of the stretch the stopped simulation did not reach: the wheelset's state where
      // the car body started stands in, rather than the last states before the stop (which
      // lead up to it) carrying more than their own share.
      const double rest =
          per_wheelset * static_cast<double>(planned - n) / static_cast<double>(planned);
      WheelsetStateSpec s = start[K];
      s.weight = rest;
      s.label = piece.label + ", wheelset " + std::to_string(k + 1) +
                (n == 0 ? " (start state)" : " (start state, for the part not simulated)");
      states.push_back(std::move(s));
    }
  }
  return states;
}

}  // namespace wheelwear::pipeline
