#pragma once
/// Kalker's linear theory generalised to the SDEC region, and its Shen-Hedrick-Elkins saturation.

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"

namespace wheelwear::tangential {

/// Linear (no-slip) creep forces of an SDEC patch with creepages at O (Liu, Fu & Bruni 2022,
/// Eq. 11-12): Fx = -G c^2 C11s vx - G c^3 C13s phi, Fy = -G c^2 C22s vy - G c^3 C23s phi,
/// c = sqrt(ab). Mz is not defined by the paper's theory (Mz is empty).
CreepForces linear_sdec_forces(const contactgeom::Sdec& sdec, const Creepages& creepages,
                               const Material& material);

/// Shen-Hedrick-Elkins (1983) saturation of the SDEC linear forces (paper, Section 4): with
/// f = |F_lin|/(mu N), both components are scaled by f_s/f where
/// f_s = f - f^2/3 + f^3/27 for f < 3 and f_s = 1 otherwise.
CreepForces she_sdec_forces(const contactgeom::Sdec& sdec, const Creepages& creepages,
                            const Material& material, const ContactLoad& load);

}  // namespace wheelwear::tangential
