#pragma once
// A wear step's increment: the collective's wear rate smoothed along the profile and placed on
// the profile's lateral coordinate, as the profile update takes it.

#include "wheelwear/profiles/profile.hpp"
#include "wheelwear/profiles/wear_update.hpp"
#include "wheelwear/wear/wear_distribution.hpp"

namespace wheelwear::pipeline::detail {

// The rate smoothed along the arc length by a Gaussian of standard deviation `length`: each
// bin's wear is spread over its neighbours with weights that sum to one within the profile, so
// the worn area is conserved exactly and no negative lobes appear (a smoothing spline's would
// be clipped at zero and add area).
wear::WearDistribution smoothed(const wear::WearDistribution& rate, double length);

// The step's depth as a function of the profile's lateral coordinate (what apply_wear takes):
// bins where y does not increase (a vertical flange back) carry no wear and are left out.
profiles::WearDepth depth_on_y(const profiles::Profile& profile, const wear::WearDistribution& rate,
                               double distance);

}  // namespace wheelwear::pipeline::detail
