#pragma once
/// Basic value types of wheel and rail profiles: points, bodies and sides.

#include <Eigen/Core>
#include <string_view>
#include <vector>

namespace wheelwear::profiles {

/// A point of a profile, (y, z) [m]: p[0] = y lateral, p[1] = z vertical, in the profile's frame
/// (profile.hpp).
using Point = Eigen::Vector2d;

/// An ordered list of profile points [m].
using PointList = std::vector<Point>;

/// Which body a profile belongs to; it fixes the side the outward normal points to.
enum class Body { wheel, rail };

/// Which side of the track a wheel or rail is on, looking in the running direction.
enum class Side { left, right };

/// "wheel" or "rail".
std::string_view to_string(Body body);

/// "left" or "right".
std::string_view to_string(Side side);

}  // namespace wheelwear::profiles
