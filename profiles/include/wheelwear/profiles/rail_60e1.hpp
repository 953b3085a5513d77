#pragma once
/// The 60E1 (UIC60) rail head, generated from its circular arcs, upright or inclined.

#include <vector>

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles {

/// Standard rail inclinations (the rail tilted towards the track centre; not the track's cant).
enum class RailInclination { none, one_in_40, one_in_20 };

/// Inclination angle [rad]: atan(1/40), atan(1/20) or 0.
double inclination_angle(RailInclination inclination);

/// One circular arc of the upright 60E1 head, in the upright frame (origin on the crown top, on
/// the rail's axis; y towards the field side; z down).
struct HeadArc {
  Point centre;         ///< centre of curvature [m]
  double radius = 0.0;  ///< [m]
  double y_from = 0.0;  ///< lateral start of the arc [m]
  double y_to = 0.0;    ///< lateral end of the arc [m]
};

/// The five head arcs R13 - R80 - R300 - R80 - R13 of the upright 60E1, from the gauge side to the
/// field side. Geometry of the 60E1 (UIC60) head as EN 15302 Annex I uses it for its rail A: R300
/// crown centred on the axis over |y| <= 10.5 mm; R80 arcs tangent to it; R13 arcs tangent to the
/// R80 arcs and to head flanks inclined 1:20 that touch them at |y| = 36 mm (head width 72 mm).
/// These defining dimensions were reconstructed from rail A's arc centres, which they reproduce
/// to 2e-5 mm (rail_60e1.cpp).
std::vector<HeadArc> rail_60e1_arcs();

/// Parameters of a generated 60E1 rail head.
struct Rail60E1Options {
  /// Inclination towards the track centre [rad], in [0, 0.1]; see inclination_angle(). Default
  /// atan(1/40), the usual rail inclination of standard-gauge track.
  double inclination = 0.024994793618920156;
  /// Depth below the crown to which the head flanks are generated [m], in [0.0145, 0.0375]
  /// (0.0375: the extent of CONTACT's MBench UIC60 file).
  double flank_depth = 0.0375;
  /// Spacing of the generated definition points [m], 1e-5 ... 1e-3.
  double point_spacing = 0.1e-3;
  /// Side of the track.
  Side side = Side::right;

  /// Throws InputError naming the first parameter out of range.
  void validate() const;
};

/// The 60E1 head points [m] from the gauge-side flank (-y) to the field-side flank (+y), rotated
/// by the inclination about the rail's longitudinal axis so that the crown faces the gauge side,
/// with the origin moved to the top of rail (the highest point after the rotation).
PointList rail_60e1_points(const Rail60E1Options& options = {});

/// The 60E1 rail profile (name "60E1", body rail) built from rail_60e1_points().
Profile rail_60e1(const Rail60E1Options& options = {}, const CurveOptions& curve = {});

}  // namespace wheelwear::profiles
