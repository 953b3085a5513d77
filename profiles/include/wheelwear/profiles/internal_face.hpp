#pragma once
/// The internal face (flange back) of a wheel profile: the reference of EN 15313's Sd and of the
/// wheel's place on its axle (back-to-back distance).

#include <string>

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles {

/// Steep back-face points lie within this angle of the vertical [rad] (about 3 degrees: a
/// measured back face after the loader's smoothing, and no rounding of radius below 40 mm over
/// kMinBackFaceHeight).
inline constexpr double kBackFaceSteepness = 0.05;
/// The steep points must span this much height [m] to be taken as the back face: the rounding
/// between back face and flange tip (S1002: R20.5, 1 mm within kBackFaceSteepness) never does.
inline constexpr double kMinBackFaceHeight = 2e-3;

/// Where the internal face lies, and how it was found.
struct InternalFace {
  double y = 0.0;         ///< lateral position of the face in the profile's frame [m]
  bool measured = false;  ///< from the profile's steep back-face points, else by convention
  std::string how;        ///< one line for reports
};

/// The internal face of `wheel`: the median y of its steep back-face points (sampled every
/// 0.1 mm between the flange-side end and the flange tip, tangent within kBackFaceSteepness of
/// the vertical, spanning kMinBackFaceHeight or more); where the profile has none (it starts on
/// the rounding, or short of the back face), the convention of its origin: the taping line at
/// y = 0 lies ProfileInfo::taping_line_distance from the face. The extreme -y point is never
/// used: on a file that starts on the rounding it puts the face, and Sd, millimetres off.
InternalFace internal_face(const Profile& wheel);

}  // namespace wheelwear::profiles
