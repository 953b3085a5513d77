#include "wheelwear/tangential/linear_theory.hpp"

#include <cmath>

#include "wheelwear/tangential/sdec_coefficients.hpp"

namespace wheelwear::tangential {

CreepForces linear_sdec_forces(const contactgeom::Sdec& sdec, const Creepages& creepages,
                               const Material& material) {
  creepages.validate();
  material.validate();
  const SdecCoefficients k = sdec_coefficients(sdec, material.nu);
  const double c = sdec.c();
  const double gc2 = material.G * c * c;
  CreepForces forces;
  forces.Fx = -gc2 * (k.c11s * creepages.vx + c * k.c13s * creepages.phi);
  forces.Fy = -gc2 * (k.c22s * creepages.vy + c * k.c23s * creepages.phi);
  forces.flags = k.flags;
  return forces;
}

CreepForces she_sdec_forces(const contactgeom::Sdec& sdec, const Creepages& creepages,
                            const Material& material, const ContactLoad& load) {
  load.validate();
  CreepForces forces = linear_sdec_forces(sdec, creepages, material);
  const double limit = load.mu * load.N;
  const double f = std::hypot(forces.Fx, forces.Fy) / limit;
  if (f > 0.0) {
    const double saturated = f < 3.0 ? f - f * f / 3.0 + f * f * f / 27.0 : 1.0;
    forces.Fx *= saturated / f;
    forces.Fy *= saturated / f;
  }
  return forces;
}

}  // namespace wheelwear::tangential
