#pragma once
/// The profile cleaning pipeline: named steps with documented thresholds, a report of what each
/// dropped, and a limit on the fraction dropped.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "wheelwear/profiles/raw_profile.hpp"

namespace wheelwear::profiles {

/// Thresholds of the cleaning steps (run in this order on oriented points).
struct CleaningOptions {
  /// bounding_box: drop points farther than this from the median point laterally [m]. Real
  /// profiles span at most 0.14 m across, so only stray points (sentinel values, a misplaced
  /// decimal point) fall outside.
  double box_half_width = 0.15;
  /// bounding_box: the same vertically [m]; real profiles span at most 0.06 m in height.
  double box_half_height = 0.06;
  /// merge_duplicates: runs of consecutive points within this distance of the run's first point
  /// become one point at their mean [m]. 1e-5 m is below MiniProf's resolution yet keeps the
  /// chord-length spline away from zero-length intervals.
  double merge_distance = 1e-5;
  /// fold_backs: drop a point where the polyline turns by more than this [deg] (a spike or a
  /// reversal of direction); local maxima first, repeated until none is left. Real profiles turn
  /// less than 60 deg between measured points, even at chamfer corners.
  double max_turn_deg = 120.0;
  /// reversing_segments: drop points whose y steps back by more than `reversal_tolerance` from
  /// the previous kept point. Unset: on for rails, off for wheels (whose flange back is vertical
  /// or overhangs). Vertical stretches are kept either way: the curve representation handles
  /// them.
  std::optional<bool> remove_reversals{};
  /// reversing_segments: the step back in y that counts as a reversal [m] (1 um: round-off of
  /// files printed to 1e-4 mm and more).
  double reversal_tolerance = 1e-6;
  /// reversing_segments, when on: also drop points reached by a segment steeper than this angle
  /// from the y axis [deg], for callers that need z(y) from the raw points. 90 keeps vertical
  /// stretches (60E1 inclined 1:20 has an exactly vertical gauge flank).
  double max_segment_angle_deg = 90.0;
  /// kinks: turns above this [deg] are reported (kept: a chamfer corner is real).
  double kink_deg = 20.0;
  /// Cleaning fails (InputError) when it drops more than this fraction of the points.
  double max_drop_fraction = 0.2;

  /// Throws InputError naming the first value out of range.
  void validate() const;
};

/// What one cleaning step did.
struct CleaningStep {
  std::string name;  ///< "bounding_box", "merge_duplicates", "fold_backs", "reversing_segments"
  std::string rule;  ///< the threshold, in words
  std::size_t dropped = 0;  ///< points removed (merged points count as removed)
  std::vector<int> lines;   ///< source lines of the removed points (at most 20)
};

/// A sharp turn of the polyline that was kept.
struct Kink {
  int line = 0;          ///< source line (0 if unknown)
  Point point;           ///< where [m]
  double angle_deg = 0;  ///< turning angle [deg]
};

/// What the cleaning did.
struct CleaningReport {
  std::size_t input_points = 0;     ///< points before cleaning
  std::size_t kept_points = 0;      ///< points after cleaning
  std::vector<CleaningStep> steps;  ///< every step, in the order run
  std::vector<Kink> kinks;          ///< sharp turns kept

  /// input_points - kept_points.
  std::size_t dropped() const { return input_points - kept_points; }
  /// One line, e.g. "kept 640 of 645 points (merge_duplicates 3, fold_backs 2); 1 kink".
  std::string summary() const;
};

/// Runs the steps on `raw` in place (points already oriented, orientation.hpp). Throws
/// InputError naming the source when more than max_drop_fraction of the points was dropped.
CleaningReport clean(RawProfile& raw, Body body, const CleaningOptions& options = {});

}  // namespace wheelwear::profiles
