#pragma once
/// FASTSIM-SDEC's per-cell fields carried to the exact theory's totals with the book of tables:
/// the most accurate tangential solution available at FASTSIM's cost where the wear needs
/// every cell ("best" in scenes).

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/fastsim.hpp"

namespace wheelwear::tangential {

/// The frictional work per rolled distance [N] of steady rolling with total forces `forces`
/// (Kalker's convention, on the wheel) and spin moment about O at creepages `creepages` at O:
/// W = -(Fx vx + Fy vy + Mz phi). In the continuum theory the elastic part of the slip does no
/// net work (its operator is antisymmetric), so the work of the slip, the integral of |p| |s|,
/// equals the work of the rigid slip, which only the totals enter. Throws InputError when phi
/// is not 0 and the forces have no Mz.
double rigid_slip_work(const CreepForces& forces, const Creepages& creepages);

/// Where the built-in book of tables covers the patch (creep_table_covers) and tabulates Mz:
/// replaces `solution`'s forces and spin moment by the table's (Kalker's exact theory) and
/// scales its slip (sx, sy, slip_norm, where present) and frictional work density by one
/// factor so that the patch's frictional work is the exact theory's, rigid_slip_work of the
/// table's totals. Tractions, pressure and the slip area stay FASTSIM's: the distribution over
/// the patch is FASTSIM-SDEC's, the amount is the exact theory's. `solution` must come from
/// fastsim() on the same patch, creepages, load and material with cell fields; returns false
/// and leaves it untouched outside the table (FASTSIM-SDEC stands there). When FASTSIM finds
/// no frictional work (all cells adhere) the work stays zero and only the totals change.
bool correct_with_creep_table(const contactgeom::Sdec& sdec, const Creepages& creepages,
                              const ContactLoad& load, const Material& material,
                              TangentialSolution& solution);

/// The same with the table's totals `table` already looked up (creep_table_lookup): false,
/// leaving `solution` untouched, when they have no Mz. Throws InputError on invalid creepages.
bool correct_with_table_totals(const CreepForces& table, const Creepages& creepages,
                               TangentialSolution& solution);

}  // namespace wheelwear::tangential
