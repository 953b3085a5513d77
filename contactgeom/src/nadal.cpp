#include "wheelwear/contactgeom/nadal.hpp"

#include <algorithm>
#include <cmath>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {

TrackPlaneForces track_plane_forces(const WheelRailContact& contact,
                                    const PatchLateralCreep& creep_Fy) {
  TrackPlaneForces f{contact.lateral_force, contact.vertical_force};
  if (!creep_Fy) return f;
  require(creep_Fy->size() == contact.patches.size(), "lateral creep forces",
          static_cast<double>(creep_Fy->size()), "need one per patch");
  for (std::size_t k = 0; k < contact.patches.size(); ++k) {
    const double gamma = contact.patches[k].contact_angle;
    f.Y += (*creep_Fy)[k] * std::cos(gamma);
    f.Q -= (*creep_Fy)[k] * std::sin(gamma);
  }
  return f;
}

NadalCheck nadal_check(const WheelRailContact& contact, double mu, const TrackPlaneForces& f) {
  require(std::isfinite(mu) && mu >= 0.0, "flange friction", mu, "must be finite and >= 0");
  NadalCheck check;
  double total = 0.0;
  for (const WheelRailPatch& p : contact.patches) total += p.normal_force;
  if (contact.patches.empty() || !(total > 0.0) || !(f.Q > 0.0)) return check;
  for (const WheelRailPatch& p : contact.patches)
    if (p.normal_force >= kNadalLoadShare * total)
      check.delta = std::max(check.delta, std::abs(p.contact_angle));
  const double t = std::tan(check.delta);
  check.limit = (t - mu) / (1.0 + mu * t);
  check.Y_over_Q = f.Y / f.Q;
  check.applies = check.delta >= kNadalFlankAngle && t > mu;
  check.exceeded = check.applies && check.Y_over_Q > check.limit;
  return check;
}

NadalCheck nadal_check(const WheelRailContact& contact, double mu,
                       const PatchLateralCreep& creep_Fy) {
  return nadal_check(contact, mu, track_plane_forces(contact, creep_Fy));
}

}  // namespace wheelwear::contactgeom
