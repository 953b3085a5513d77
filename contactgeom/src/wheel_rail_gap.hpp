#pragma once
// The undeformed vertical gap between a wheel and its rail at one wheelset pose, sampled where
// contact is possible (internal to the wheel/rail contact; wheel_rail.hpp documents the frames).

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "surface_walk.hpp"
#include "wheelwear/contactgeom/wheel_rail.hpp"

namespace wheelwear::contactgeom::detail {

// The gap sampled on uniform lateral windows of the rail frame where contact is possible.
struct GapSamples {
  double dy = 0.0;              // sample spacing [m]
  std::vector<double> y;        // rail-frame lateral coordinate [m]
  std::vector<double> h;        // vertical gap z_rail - z_wheel [m]
  std::vector<double> z_wheel;  // unrolled height of the wheel's material point (radius) [m]
  std::vector<double> s_rail;   // arc length of the rail's surface point [m]
  std::vector<int> window;      // index of the window a sample belongs to
  double h_min = std::numeric_limits<double>::infinity();
  std::vector<std::size_t> end_samples;  // samples that lie at the end of a profile
};

// The gap every scan_spacing from lo (+inf where either profile is missing).
struct CoarseScan {
  double lo = 0.0, hi = 0.0;  // lateral overlap of the profiles, rail frame [m]
  std::vector<double> h;      // gap at lo + i scan_spacing [m]
  // Per interval between points i and i + 1: where the gap's slopes at both ends point into a
  // dip between them, the height at which their tangents cross (+inf elsewhere) [m]. A steep
  // flank's dip can be narrower than the spacing and lie far below both points: a wheel flank
  // at 80 deg against the gauge face closes 6 mm of vertical gap per mm of shift.
  std::vector<double> dip;
  double h_min = std::numeric_limits<double>::infinity();  // of h
};

// The gap at one coarse point and its slope along rail-frame y.
struct CoarseGap {
  double h = 0.0;      // [m]
  double slope = 0.0;  // dh/dy [-]; +-inf on a vertical tangent
};

// The wheel's material point seen at one rail-frame lateral coordinate.
struct WheelPoint {
  double z_rolled = 0.0;  // height of the (rolled) surface in the rail frame [m]
  double z = 0.0;         // height of the material point in the unrolled wheel profile [m]
  double y = 0.0;         // lateral coordinate of the material point in the wheel profile [m]
  double s = 0.0;         // its arc length on the wheel profile [m]
};

// The gap at one rail-frame lateral coordinate with the surface points there.
struct GapPoint {
  double h = 0.0;  // vertical gap z_rail - z_wheel [m]
  WheelPoint wheel;
  double s_rail = 0.0;  // arc length of the rail's surface point [m]
};

// Where a rail profile sits in the track: the costly step of placing a wheel on its rail, kept
// for the last rails seen (compared by their curves) rather than computed for every pose.
struct RailDatum {
  double gauge_y = 0.0;  // the gauge point's y (profiles::gauge_point at the gauge depth) [m]
  double top_z = 0.0;    // the top of rail's z (profiles::top_of_rail) [m]
};
RailDatum rail_datum(const WheelRailPair& pair);
// rail_datum(pair).gauge_y [m].
double rail_gauge_y(const WheelRailPair& pair);

// Where a wheel's flange stops steepening: contact whose O lies beyond this towards the flange
// tip has passed the flank's steepest point (WheelRailStatus::past_flange). Slope angles are
// those of the unrolled profile, atan(-dz/dy) rising towards the tread; a roll adds the same
// angle everywhere and moves no material point's arc length, so one datum serves every pose.
struct FlangeDatum {
  bool found = false;           // false: no flank rises from a flange tip to the taping line
  double s_tip = 0.0;           // arc length of the flange tip, the lowest point (largest z) [m]
  double s_steepest = 0.0;      // arc length of the flank's steepest point [m]
  double steepest_angle = 0.0;  // its slope angle [rad]
  // Arc length of the flank point nearest the tip whose slope angle is still within
  // kFlangeSlopeTolerance of steepest_angle; O at a smaller arc length is past the flange [m].
  double s_limit = 0.0;
};

// The slope a contact may lose past the flank's steepest point and still count as flank
// contact [rad]. The steepest point of a straight flank (S1002: 1.3 mm at 1.2224 rad) is
// wherever the fitted curve's round-off or a measured profile's noise puts it; a smoothed
// measured flank carries slope noise of order 0.01 rad (10 um over 1 mm). 0.02 rad (1.1 deg)
// keeps contact anywhere on the steepest stretch ok, while the wheel that has passed it
// (0.15 to 0.6 rad lost beyond the tip, 0.5 rad on a worn flange that climbs) is caught; on
// S1002's R20 flange face it is 0.4 mm of arc.
constexpr double kFlangeSlopeTolerance = 0.02;

// The flange datum of a wheel profile, kept for the last wheels seen on this thread (compared
// by their curves, as rail_datum does): a scan of the flank every 0.05 mm on the first call.
FlangeDatum flange_datum(const profiles::Profile& wheel);

// The direction of a contact normal in the track's lateral-vertical plane: cos and sin of the
// contact angle.
struct ContactDirection {
  double cos = 1.0;
  double sin = 0.0;
};

// The wheel placed on its rail at one pose. The wheel profile is not rebuilt for a roll: the
// surface point seen at a rail-frame y is found on the unrolled profile by Newton's method on
// the rotation about the taping point (0, z_tape), y' = cos(roll) y - sin(roll) (z(y) - z_tape),
// z' = sin(roll) y + cos(roll) (z(y) - z_tape) + z_tape, to 1e-13 m.
class WheelRailGap {
 public:
  WheelRailGap(const WheelRailPair& pair, const WheelsetPose& pose, const WheelRailOptions& options,
               double gauge_y);

  double shift() const { return shift_; }    // rail-frame y of the wheel profile's y = 0 [m]
  double z_tape() const { return z_tape_; }  // wheel profile height at its taping line [m]
  const WheelRailPair& pair() const { return pair_; }

  // The wheel's material point whose rolled surface lies at rail-frame y; nullopt off the profile.
  std::optional<WheelPoint> wheel_at(double y) const;
  // Vertical gap at rail-frame y and the wheel point there; nullopt outside either profile.
  std::optional<GapPoint> gap(double y) const;
  // The coarse scan: the gap every options.scan_spacing over the lateral overlap (coarse_gap).
  void scan(CoarseScan& coarse) const;
  // Samples the gap every strip_width in the windows where the coarse scan lies within `margin`
  // of its minimum, or dips below that between two points that both lie above it (each window
  // reaches one coarse point beyond, where the gap is above it).
  // minima_only: only around the coarse scan's local minima within the margin, one coarse
  // point either side (enough to find the gap's minimum, not a contact's extent).
  void sample(const CoarseScan& coarse, double margin, GapSamples& g,
              bool minima_only = false) const;
  // The gap at increasing rail-frame y, walked along both curves (surface_walk.hpp), with the
  // lookups of gap() where a walk cannot go on. Same values as gap() to 1e-15 m once
  // close_walks() has checked the walked stretches.
  std::optional<GapPoint> walked_gap(double y) const;
  // Checks the open walked stretches by a lookup at their ends; false when one does not stand
  // (then the values walked since the last check are recomputed with gap()).
  bool close_walks() const;
  // Contact angle at rail-frame y: the rail surface's slope, + where it falls towards -y
  // (the gauge side), as on the gauge corner and flange contact [rad].
  double contact_angle(double y) const;
  // cos and sin of contact_angle(y), from the slope without the arctangent (one lookup).
  ContactDirection contact_direction(double y) const;
  // The same at the rail's surface point of arc length s [m] (GapSamples::s_rail): from the
  // curve's tangent there, without a lookup.
  ContactDirection rail_direction(double s) const;
  // Arc length of the wheel profile's taping line (y = 0) [m]: contact on the tread side of it
  // cannot have passed the flange.
  double s_tape() const { return s_tape_; }
  // Rolling radius of the wheel's material point with unrolled height z [m]: its distance from
  // the axle, which a roll about the taping point does not change.
  double rolling_radius(double z) const { return pair_.wheel_radius + z - z_tape_; }

 private:
  const WheelRailPair& pair_;
  const WheelRailOptions& options_;
  double shift_ = 0.0;
  double z_tape_ = 0.0;
  double s_tape_ = 0.0;
  double cos_roll_ = 1.0;
  double sin_roll_ = 0.0;
  // The gap for the coarse scan, which only chooses the sampled windows: with a roll, to
  // first order in the mapping onto the unrolled wheel (within 4e-7 m); its slope from the
  // surfaces' slopes there.
  std::optional<CoarseGap> coarse_gap(double y) const;
  void close_rail_walk() const;
  void close_wheel_walk() const;
  mutable SurfaceWalk rail_walk_, wheel_walk_;
  mutable bool walk_failed_ = false;
};

// The first sampling keeps only the windows where the gap lies within this of its minimum [m]:
// 0.3 mm, three times the approach of a 55 kN wheel on its flange root. The coarse scan misses
// nothing that deep: a dip of 0.1 mm between two coarse points 1 mm apart needs a gap curvature
// of 800 1/m (a 1.2 mm radius), far sharper than any wheel or rail. A loaded contact's answer
// stands when its approach stays 0.1 mm inside the margin; otherwise the gap is sampled to
// options.scan_margin.
constexpr double kFirstMargin = 0.3e-3;

// The gap minimum of samples [first, last], refined by a parabola through its neighbours.
struct GapMinimum {
  double y = 0.0;  // rail-frame lateral coordinate [m]
  double h = 0.0;  // gap [m]
};
GapMinimum refined_minimum(const GapSamples& g, std::size_t first, std::size_t last);

}  // namespace wheelwear::contactgeom::detail
