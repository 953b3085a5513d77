#pragma once
/// The profile cleaning pipeline: named steps with documented thresholds, a report of what each
/// dropped, and a limit on the fraction dropped.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
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
  /// Cleaning fails (InputError) when it discards more than this fraction of the points. Merged
  /// duplicates do not count: their points live on in the merged point (dense, noise-free
  /// sampling merges most of its points).
  double max_drop_fraction = 0.2;

  /// Throws InputError naming the first value out of range.
  void validate() const;
};

/// What one cleaning step did.
struct CleaningStep {
  std::string name;  ///< "bounding_box", "merge_duplicates", "fold_backs", "reversing_segments"
  std::string rule;  ///< the threshold, in words
  std::size_t dropped = 0;  ///< points removed (merged points count as removed)
  std::vector<int> lines;   ///< source lines of the removed points (the first 20 in file order)
};

/// What crop_rail() removed.
struct CropReport {
  double depth = 0.0;          ///< crop depth below the top of rail [m]; 0: not cropped
  double top = 0.0;            ///< z of the top of rail the depth is measured from [m]
  std::size_t gauge_side = 0;  ///< points removed at the -y (gauge face) end
  std::size_t field_side = 0;  ///< points removed at the +y (field side) end
  double deepest = 0.0;        ///< depth of the deepest removed point below the top [m]
  /// First and last source line of the points removed at the gauge end, in file order (0, 0
  /// when none or unknown); each end's removed points are consecutive rows of the file.
  std::pair<int, int> gauge_lines{0, 0};
  std::pair<int, int> field_lines{0, 0};  ///< the same at the field end
  std::string reason;  ///< why the rail was cropped: the whole profile's error, if that was why

  /// Points removed.
  std::size_t cropped() const { return gauge_side + field_side; }
  /// One line, e.g. "cropped 12 points deeper than 25 mm below the top of rail (gauge side 12,
  /// lines 188 ... 199; down to 36.2 mm)"; "" when nothing was cropped.
  std::string summary() const;
};

/// What shadow_lip() did to a rail whose gauge face recedes under a lip.
struct LipReport {
  std::size_t hidden = 0;           ///< points removed under the lip
  std::pair<int, int> lines{0, 0};  ///< their first and last source line, in file order
  double edge_depth = 0.0;          ///< depth of the lip's edge below the top of rail [m]
  double deepest = 0.0;             ///< depth of the deepest point removed [m]
  std::size_t added = 0;            ///< points of the vertical face put below the edge
  std::string reason;               ///< the error that made it necessary

  /// One line, e.g. "shadowed 38 points under the head's lips (lines 504 ... 541) from 13.1 mm
  /// below the top of rail, down to 31.4 mm: a face below its lip's edge is taken as vertical,
  /// as a wheel's flange meets it"; "" when nothing was shadowed.
  std::string summary() const;
};

/// A sharp turn of the polyline that was kept.
struct Kink {
  int line = 0;          ///< source line (0 if unknown)
  Point point;           ///< where [m]
  double angle_deg = 0;  ///< turning angle [deg]
};

/// What the cleaning did. clean() fills the counts, steps and kinks; the loader
/// (profile_loader.hpp) adds what the reader accepted, the crop and the warnings.
struct CleaningReport {
  std::size_t input_points = 0;       ///< points before cleaning (after the crop)
  std::size_t kept_points = 0;        ///< points after cleaning
  std::vector<CleaningStep> steps;    ///< every step, in the order run
  std::vector<Kink> kinks;            ///< sharp turns kept, in file order
  std::vector<ReadRepair> reading;    ///< departures from the strict format the reader accepted
  CropReport crop;                    ///< rails: what was cropped before the cleaning
  LipReport lip;                      ///< rails: the undercut of a lip shadowed, if needed
  std::vector<std::string> warnings;  ///< what the user should check (a point count off by one,
                                      ///< a rail without a gauge point or that looks mirrored),
                                      ///< each naming the file

  /// input_points - kept_points: points removed by the steps, merged duplicates included.
  std::size_t dropped() const { return input_points - kept_points; }
  /// Points merged into a neighbour by merge_duplicates (not lost: the merged point stands for
  /// them).
  std::size_t merged() const;
  /// dropped() - merged(): points discarded as bad data; the drop limit applies to these.
  std::size_t discarded() const { return dropped() - merged(); }
  /// One line, e.g. "kept 640 of 645 points (merge_duplicates 3, fold_backs 2); 1 kink", with
  /// "; cropped 12 below 25 mm" and "; read: trailing_comments 3" when those happened.
  std::string summary() const;
};

/// Shadows the underside of the head's lips (a rail whose gauge face recedes towards the field
/// side below a plastically flowed edge, as worn low rails do, and the same on the field side):
/// walking down each face from the top of rail (the points oriented, z down, the gauge side at
/// -y), every point that lies behind the outermost point above it is hidden from a wheel and
/// removed, and where a face does not come out again it is continued vertically below its edge
/// (points every 0.5 mm, line 0) to the depth of the deepest point removed there, at most
/// `max_depth` [m] below the top: a flange cannot reach into the undercut, and the gauge is
/// measured on the edge. Used by the loader only for a rail refused otherwise, with the crop
/// depth as max_depth (profile_loader.hpp).
LipReport shadow_lip(RawProfile& raw, double max_depth);

/// Runs the steps on `raw` in place (points already oriented, orientation.hpp). Throws
/// InputError naming the source when more than max_drop_fraction of the points was discarded
/// (merged duplicates do not count).
CleaningReport clean(RawProfile& raw, Body body, const CleaningOptions& options = {});

/// Throws InputError unless `depth` [m] is 0 or in [0.014, 0.2] (crop_rail).
void check_crop_depth(double depth);

/// A crop keeps the deep point next to the head only if it lies within this [m] below the crop
/// depth: the measurement runs on through the depth (a point much deeper lies across a gap in the
/// data, 12 mm in one measured rail, and would be refused as one).
inline constexpr double kCropNeighbourReach = 2e-3;

/// Crops a rail (points oriented, z down) to the part a wheel can touch: from each end, the run
/// of points deeper than `depth` below the top of rail is removed but for its point nearest the
/// head where that lies within kCropNeighbourReach below the depth, so that the profile still
/// reaches `depth` where the data allow. Points that dip below it inside the profile
/// are left to the cleaning. The top is the highest point within the cleaning's bounding box
/// around the median point, so a stray point cannot move it. depth 0 crops nothing. Throws
/// InputError unless depth is 0 or in [0.014, 0.2] m (the gauge point lies 14 mm deep).
CropReport crop_rail(RawProfile& raw, double depth, const CleaningOptions& options = {});

}  // namespace wheelwear::profiles
