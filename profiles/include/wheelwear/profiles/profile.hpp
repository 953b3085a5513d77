#pragma once
/// The wheel or rail profile value type: a smooth parametric curve with its body, side and frame.

#include <optional>
#include <string>

#include "wheelwear/profiles/curve.hpp"
#include "wheelwear/profiles/surface_lookup.hpp"
#include "wheelwear/profiles/types.hpp"

namespace wheelwear::profiles {

/// What a profile is, besides its shape.
struct ProfileInfo {
  std::string name;             ///< e.g. "S1002", "60E1 1:40" or a file name
  Body body = Body::wheel;      ///< wheel or rail
  Side side = Side::right;      ///< side of the track (placement into the track frame mirrors left)
  double nominal_radius = 0.0;  ///< wheels: rolling radius at the taping line [m]; 0 if unknown
  /// Wheels: the taping line's distance from the internal face [m] by the profile's origin
  /// convention (EN 13715: 70 mm), used where the profile does not show its back face
  /// (internal_face.hpp).
  double taping_line_distance = 0.070;
};

/// A wheel or rail cross-section profile in its own frame, SI metres.
///
/// Frame (the convention of the standards' definitions, EN 13715 / EN 15302, and of CONTACT):
/// - y lateral, positive towards the field side; the wheel flange and the rail's gauge face lie on
///   the negative-y side, for left and right profiles alike (Side only matters in the track).
/// - z vertical, positive downwards (towards the rail for a wheel, into the rail for a rail).
/// - Generated profiles put the origin at the taping line (wheel: y = 0 is 70 mm from the flange
///   back, z = 0 its height) or at the top of rail (rail: the highest point). Profiles read from
///   files keep the file's origin (columns_format.hpp, simpack_format.hpp and miniprof_format.hpp
///   say what each format gives).
/// - The arc length s runs from the flange/gauge side (-y end) to the field side (+y end).
/// The curve is C2 and may be vertical or overhang; z(y) queries return the branch that faces the
/// mating body (SurfaceLookup).
class Profile {
 public:
  /// Profile through (or near, with smoothing) `points`, ordered from the -y end to the +y end
  /// (at least 4 points, no consecutive duplicates). Throws InputError otherwise.
  Profile(const PointList& points, ProfileInfo info, const CurveOptions& options = {});

  /// Name, body, side and nominal radius.
  const ProfileInfo& info() const { return info_; }
  /// Wheel or rail.
  Body body() const { return info_.body; }
  /// Left or right.
  Side side() const { return info_.side; }
  /// The options the curve was built with.
  const CurveOptions& curve_options() const { return options_; }
  /// The underlying arc-length curve.
  const ArcLengthCurve& curve() const { return curve_; }

  /// Total arc length [m].
  double length() const { return curve_.length(); }
  /// Position (y, z) at arc length s [m]; s is clamped to [0, length()].
  Point position(double s) const { return curve_.position(s); }
  /// Unit tangent at s, pointing towards increasing s (towards +y on the tread).
  Point tangent(double s) const;
  /// Unit outward normal at s: out of the material, towards the mating body (wheel tread: +z,
  /// rail top: -z; the tangent turned by +90 deg for a wheel, by -90 deg for a rail).
  Point normal(double s) const;
  /// Curvature at s [1/m], positive where the surface is convex (bulges towards the mating body):
  /// +1/R on the 60E1 crown and on the S1002 flange tip, negative in the flange root.
  double curvature(double s) const;

  /// Height z [m] of the surface at lateral position y [m], nullopt outside [y_min(), y_max()].
  std::optional<double> z_at(double y) const;
  /// Height, slope and arc length of the surface point at y (SurfaceLookup): O(1).
  std::optional<SurfaceSample> surface_at(double y) const { return lookup_.at(y); }
  /// Smallest lateral coordinate of the profile [m].
  double y_min() const { return lookup_.y_min(); }
  /// Largest lateral coordinate of the profile [m].
  double y_max() const { return lookup_.y_max(); }

  /// Points at equal arc-length steps no longer than `spacing` [m], both ends included.
  PointList resample(double spacing) const { return curve_.sample(spacing); }
  /// The curve at its knots [m] (equal arc-length steps of curve_options().knot_spacing).
  PointList knot_points() const { return curve_.knot_points(); }

  /// This profile moved by (dy, dz) [m]; same parametrisation.
  Profile translated(double dy, double dz) const;

 private:
  ProfileInfo info_;
  CurveOptions options_;
  ArcLengthCurve curve_;
  SurfaceLookup lookup_;
};

}  // namespace wheelwear::profiles
