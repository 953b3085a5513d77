#pragma once
// The surface z(y) of a profile, optionally rolled, evaluated at many nearby y in increasing
// order (the gap's samples) by Newton's method on the curve's own cubic pieces, continuing from
// the previous answer: one or two cubic evaluations per point instead of a lookup.

#include <cstddef>
#include <optional>
#include <vector>

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::contactgeom::detail {

// A point of the walked surface.
struct WalkPoint {
  double z_rolled = 0.0;  // height of the rolled surface [m]
  double y = 0.0;         // lateral coordinate of the unrolled curve point [m]
  double z = 0.0;         // height of the unrolled curve point [m]
  double s = 0.0;         // its arc length [m]
};

// Walks the curve (y(t), z(t)) of a profile rotated by `roll` about (0, z_pivot):
// Y = cos(roll) y - sin(roll) (z - z_pivot), Z = sin(roll) y + cos(roll) (z - z_pivot) + z_pivot.
// A walk starts at a point a lookup found (seed) and solves Y(t) = y for increasing y on the
// knot interval of the previous answer or the next ones, to 1e-15 m, as long as every interval
// it passes is strictly increasing in Y (Bernstein coefficients of Y' positive; Farin 2002,
// Curves and Surfaces for CAGD, Ch. 5). The walked stretch is then a graph over [y_seed, y_last].
//
// Why one lookup at each end vouches for the whole stretch: the lookup returns, of all points of
// the curve at a y, the one facing the mating body. If it returns the walked point at y_seed and
// at y_last, any other part of the curve facing the body better somewhere in between would have
// to cross the walked graph (the profile does not intersect itself), or pass the strip's ends,
// where it faces the body worse; or it lies inside the strip entirely, and then holds an end of
// the curve. So: the caller looks up y_last when the walk stops (close()), and the stretch
// stands if the lookup finds the walked point and no end of the curve lies strictly inside.
class SurfaceWalk {
 public:
  // Prepares walks on `profile` (no pass over the curve); reuses this object's storage.
  void reset(const profiles::Profile& profile, double roll, double z_pivot);
  // Starts a walk at the curve point of arc length s [m] whose rotated lateral coordinate is y.
  void seed(double y, double s);
  // The point whose rotated lateral coordinate is y [m], y above the last one, or nullopt when
  // no walk is on (not seeded) or it would leave the curve or a rising interval; the walk
  // stops then, still to be closed.
  std::optional<WalkPoint> at(double y);
  // Whether the stretch walked since the last seed still waits for its check.
  bool open() const { return open_; }
  // The last walked y [m] and arc length [m], for the closing lookup.
  double last_y() const { return last_y_; }
  double last_s() const { return last_s_; }
  // Closes the stretch: true when it stands, given the arc length the lookup found at last_y()
  // (nullopt: none), as explained above.
  bool close(std::optional<double> looked_up_s);

 private:
  bool rising(std::size_t k);

  const profiles::ArcLengthCurve* curve_ = nullptr;
  double cos_ = 1.0, sin_ = 0.0, z0_ = 0.0;
  std::size_t n_ = 0;                   // intervals
  std::vector<signed char> rising_;     // interval k: 1 rising, 0 not, -1 not yet known
  double y_start_ = 0.0, y_end_ = 0.0;  // rotated Y of the curve's two ends [m]
  bool seeded_ = false, open_ = false;
  std::size_t i_ = 0;  // interval of the last answer
  double u_ = 0.0;     // its local parameter [m]
  double seed_y_ = 0.0, last_y_ = 0.0, last_s_ = 0.0;
  bool have_rate_ = false;
  double rate_ = 0.0;  // d(arc length)/dy between the last two answers [-]
};

}  // namespace wheelwear::contactgeom::detail
