#pragma once
/// Placing rail profiles in a track: top of rail, gauge point, and the track frame.

#include <optional>

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles {

/// Track layout used to place rails.
struct TrackGeometry {
  double gauge = 1.435;                  ///< track gauge [m] (standard gauge 1435 mm)
  double gauge_measuring_depth = 0.014;  ///< depth below the top of rail where gauge is measured
                                         ///< [m] (EN 13848-1: 14 mm)
  /// Throws InputError unless gauge > 0 and 0 < depth < 0.05 m.
  void validate() const;
};

/// A point of a profile with its arc length.
struct ProfilePoint {
  Point point;     ///< (y, z) [m]
  double s = 0.0;  ///< arc length [m]
};

/// The highest point of a rail profile (smallest z) [m].
ProfilePoint top_of_rail(const Profile& rail);

/// The gauge point of a rail profile: of the points on the gauge side between the top of rail and
/// `measuring_depth` below it, the one nearest the track centre (smallest y) (EN 13848-1). Throws
/// InputError if the profile does not reach that depth on its gauge side.
ProfilePoint gauge_point(const Profile& rail, double measuring_depth = 0.014);

/// A rail's inclination estimated from its head: the slope of the chord across the crown between
/// the points `half_width` either side of the head's axis, positive when the gauge side lies
/// lower (canted towards the track centre, as rails are laid). The axis is taken `axis_offset`
/// to the field side of the gauge point, less 14 mm times the slope (the gauge point lies 14 mm
/// below the top, so canting moves it across by that much; one correction step). The default
/// offset is the upright 60E1's, 35.98 mm (72 mm head); the 70 mm head of 54E1 or the 67 mm
/// one of 49E1 put the axis 1 to 2.5 mm nearer, which tilts the estimate by about 1/300 per mm
/// on their R300 crowns. Meant to tell a rail that carries its inclination from a level one.
struct InclinationEstimate {
  double angle = 0.0;  ///< [rad], positive: gauge side lower
  Point gauge_end;     ///< chord end on the gauge side [m]
  Point field_end;     ///< chord end on the field side [m]
};

/// The estimate above (axis_offset and half_width in m); nullopt when the rail has no gauge point
/// or does not reach the chord's field end.
std::optional<InclinationEstimate> estimate_inclination(const Profile& rail,
                                                        double axis_offset = 0.03598,
                                                        double half_width = 0.010);

/// Where a rail sits in the track frame: x along the track (running direction), y to the right,
/// z down (right-handed); origin on the track centre line at top-of-rail height. The gauge point
/// of the right rail is at y = +gauge/2, of the left rail at y = -gauge/2; the left rail is the
/// mirror image of its profile (both profiles have their gauge side at -y).
struct RailPlacement {
  Side side = Side::right;  ///< which rail
  Point gauge_point;        ///< gauge point in the profile frame [m]
  Point top;                ///< top of rail in the profile frame [m]
  double gauge = 1.435;     ///< track gauge [m]

  /// Profile-frame point [m] in the track frame [m].
  Point to_track(const Point& p) const;
  /// Track-frame point [m] in the profile frame [m].
  Point to_profile(const Point& q) const;
};

/// Places a rail profile in the track (side from the profile).
RailPlacement place_rail(const Profile& rail, const TrackGeometry& track = {});

}  // namespace wheelwear::profiles
