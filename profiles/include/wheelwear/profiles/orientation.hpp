#pragma once
/// Bringing points read from a file into the profile frame (profile.hpp): z down, flange or gauge
/// face at -y, ordered from -y to +y.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "wheelwear/profiles/raw_profile.hpp"

namespace wheelwear::profiles {

/// Whether to mirror an axis.
enum class Mirror {
  automatic,  ///< decide from the shape (see orient())
  keep,       ///< never mirror
  flip,       ///< always mirror
};

/// How to orient a profile.
struct OrientationOptions {
  /// y -> -y about the file's origin. For a rail this says where the file has its gauge face,
  /// on the lateral axis as read (MiniProf X; Simpack y after the file's own mirror.y): keep =
  /// at the smaller values (the left of a plot of the file), flip = at the larger ones (the
  /// right). It is the override for rails the automatic rule gets wrong (switch rails measured
  /// deeper on the field side); `profile --gauge-side left|right`.
  Mirror mirror_y = Mirror::automatic;
  Mirror mirror_z = Mirror::automatic;  ///< z -> -z about the file's origin
};

/// "auto", "left" or "right" (a rail's gauge side on the file's lateral axis) to the mirror_y
/// that says it: automatic, keep or flip; nullopt for anything else.
std::optional<Mirror> gauge_side_mirror(std::string_view text);

/// What orient() did.
struct OrientationReport {
  bool mirrored_y = false;         ///< y was negated
  bool mirrored_z = false;         ///< z was negated
  bool reversed = false;           ///< the point order was reversed
  std::vector<std::string> notes;  ///< why
};

/// Orients `raw` in place. Automatic rules, from the shapes of real profiles (the z rules are
/// CONTACT's, read_profile.m):
/// - z, wheel: the lowest points (smallest z, z down) are the side faces at the ends (flange back
///   top, field-side chamfer) and the flange tip is the lowest-lying interior point; so z is kept
///   if the smallest z lies in the first or last 5% of the points, negated if the largest does.
/// - z, rail: the top of rail (smallest z) is interior; z is negated if it lies in the first or
///   last 10% of the points.
/// - y, wheel: the flange (largest z) must lie in the -y half of the lateral range.
/// - y, rail: the gauge face is the end that is measured deeper below the top (MiniProf measures
///   the gauge face down to about 25 mm, the field side far less; inclined heads also put the
///   gauge end deeper); y is negated if the +y end is deeper by more than 1 mm, kept otherwise.
/// - order: reversed if the first point lies at larger y than the last.
OrientationReport orient(RawProfile& raw, Body body, const OrientationOptions& options = {});

}  // namespace wheelwear::profiles
