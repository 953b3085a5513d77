#pragma once
/// The S1002 wheel profile of EN 13715, generated from its piecewise definition.

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles {

/// Parameters of a generated S1002 wheel profile (EN 13715, designation S1002/h/e). The defaults
/// give the standard's nominal profile point for point. Other flange heights and thicknesses are
/// wheelwear's construction after EN 13715's rule of moving the flange towards the internal face
/// by the thickness reduction: the flange moves rigidly, a quintic blend across the connection
/// zone (y = -35 ... -26 mm) joins it to the unchanged tread, and a 3 mm fillet rounds the corner
/// where the internal face cuts the back arc. They meet Sh and Sd exactly but are not the
/// standard's tabulated variants.
struct S1002Options {
  /// Flange height Sh [m], 0.028 ... 0.032 (EN 13715 h28 ... h32). The flange is lowered rigidly
  /// by flange_height - 0.028; the connection zone blends into the unchanged tread.
  double flange_height = 0.028;
  /// Flange thickness Sd [m] as EN 15313 measures it (10 mm from the running circle), 0.028 ...
  /// 0.0325 (EN 13715 e28 ... e32.5). The flange is moved towards the internal face until Sd
  /// matches; the internal face (y = -70 mm) then cuts the back arc, the corner rounded with a
  /// 3 mm radius.
  double flange_thickness = 0.0325;
  /// Rolling radius at the taping line [m], > 0; only recorded in the profile (EN 13715's
  /// profiles do not depend on it). Default: the 920 mm wheel of the Manchester benchmark.
  double nominal_radius = 0.46;
  /// Height z [m] where the vertical flange back ends at the top, at most the height where the back
  /// arc begins (9.519 mm for h28). Default: level with the running circle.
  double back_face_top = 0.0;
  /// Spacing of the generated definition points [m], 1e-5 ... 1e-3.
  double point_spacing = 0.1e-3;
  /// Side of the track.
  Side side = Side::right;

  /// Throws InputError naming the first parameter out of range.
  void validate() const;
};

/// Height z [m] of the nominal S1002 (h28, e32.5) at y [m], y in [-0.070, 0.060]: the eight
/// sections A-H of H. Netter's (DLR) implementation of EN 13715 (two lines, degree-8 and degree-7
/// polynomials, four circular arcs; coefficients in s1002.cpp with what they were checked against).
/// Frame of Profile: taping line at y = 0, flange on the -y side, z down. Throws InputError
/// outside the range.
double s1002_nominal_z(double y);

/// The S1002 definition points [m], from the top of the flange back (-y) to the field side (+y),
/// about `point_spacing` apart along the curve (arcs sampled by angle, so the vertical flange back
/// is resolved).
PointList s1002_points(const S1002Options& options = {});

/// The S1002 wheel profile (name "S1002", body wheel) built from s1002_points().
Profile s1002(const S1002Options& options = {}, const CurveOptions& curve = {});

}  // namespace wheelwear::profiles
