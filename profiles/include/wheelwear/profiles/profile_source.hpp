#pragma once
/// Resolves the wheel and rail profiles a user names: a standard profile or a file.

#include <optional>
#include <string>

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles {

/// "S1002" (generated, EN 13715 defaults, nominal radius `radius`) or a profile file.
profiles::Profile wheel_profile(const std::string& spec, double radius);

/// "60E1" (generated, EN 15302 arcs) or a profile file, inclined by `inclination` [rad] towards
/// the track centre. Without an inclination the built-in rail is inclined 1:40 and a file is
/// taken as it is (rail files usually carry their inclination).
profiles::Profile rail_profile(const std::string& spec, std::optional<double> inclination);

/// Default inclination applied to a rail spec: atan(1/40) for the built-in 60E1, 0 for files.
double default_inclination(const std::string& spec);

}  // namespace wheelwear::profiles
