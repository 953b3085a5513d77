#pragma once
// The wheel/rail contact with the rail's gauge point computed beforehand and the input already
// validated: for callers that evaluate many poses of one pair (wheelset.cpp).

#include <limits>

#include "wheelwear/contactgeom/wheel_rail.hpp"

namespace wheelwear::contactgeom::detail {

// solve_wheel_rail with gauge_y = rail_gauge_y(pair) [m]; the input is not validated again.
WheelRailContact solve_wheel_rail_at(const WheelRailPair& pair, const WheelsetPose& pose,
                                     double vertical_force, const WheelRailOptions& options,
                                     double gauge_y);

// first_touch with gauge_y = rail_gauge_y(pair) [m]; the input is not validated again.
// `steepest`: the touch is the lowest local minimum of the gap whose contact angle is below
// this [rad] (the gap's lowest point where none is), and WheelRailTouch::resting_gap shares its
// load with the minima of a flank nearly that steep (resting_gap.hpp); +inf: the gap's lowest
// point, resting_gap = gap.
WheelRailTouch first_touch_at(const WheelRailPair& pair, const WheelsetPose& pose,
                              const WheelRailOptions& options, double gauge_y,
                              double steepest = std::numeric_limits<double>::infinity());

// Throws InputError unless dy, roll and yaw are finite and |roll| < 0.1 rad.
void validate_pose(const WheelsetPose& pose);

// Validates what a contact solve under a vertical force takes: the pair, the options, the pose
// and the force (finite, > 0).
void validate_loaded_contact(const WheelRailPair& pair, const WheelsetPose& pose,
                             double vertical_force, const WheelRailOptions& options);

}  // namespace wheelwear::contactgeom::detail
