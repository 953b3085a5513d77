#pragma once
/// A conical wheel profile: the textbook wheel of linear wheelset dynamics (Klingel's kinematic
/// oscillation, the pure-rolling line in curves): its rolling radius changes by its conicity
/// lambda per metre along the wheel. (Per metre of wheelset shift the change is a little larger
/// on a real rail head: the wheelset's roll moves the contacts along the wheels.)

#include "wheelwear/profiles/profile.hpp"

namespace wheelwear::profiles {

struct ConicalWheelOptions {
  double conicity = 0.05;         ///< lambda = -dr/dy [-], 0 ... 0.5 (radius grows towards -y)
  double nominal_radius = 0.46;   ///< rolling radius at the taping line y = 0 [m], > 0
  double flange_side = -0.070;    ///< start of the cone towards the flange side [m], < -0.02
  double field_side = 0.060;      ///< end of the cone on the field side [m], > 0.02
  double point_spacing = 0.5e-3;  ///< spacing of the definition points [m], 1e-5 ... 1e-3
  Side side = Side::right;

  void validate() const;  ///< throws InputError naming the first bad field
};

/// The cone z = -conicity * y (z down: the radius grows towards the flange side), without a
/// flange; its flange-side end is at the convention's internal face (70 mm from the taping line
/// by default), so WheelRailPair places it as an S1002. Fitted without smoothing: a straight
/// line is reproduced by the spline exactly.
Profile conical_wheel(const ConicalWheelOptions& options = {});

}  // namespace wheelwear::profiles
