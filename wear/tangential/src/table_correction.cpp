#include "wheelwear/tangential/table_correction.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/creep_table.hpp"

namespace wheelwear::tangential {

double rigid_slip_work(const CreepForces& forces, const Creepages& creepages) {
  if (!forces.Mz && creepages.phi != 0.0)
    throw InputError("rigid_slip_work: phi = " + std::to_string(creepages.phi) +
                     " 1/m needs the spin moment Mz, which these forces lack");
  const double spin = forces.Mz ? *forces.Mz * creepages.phi : 0.0;
  return -(forces.Fx * creepages.vx + forces.Fy * creepages.vy + spin);
}

bool correct_with_creep_table(const contactgeom::Sdec& sdec, const Creepages& creepages,
                              const ContactLoad& load, const Material& material,
                              TangentialSolution& solution) {
  const CreepTableLookup lookup = creep_table_lookup(sdec, creepages, load, material);
  return lookup.forces && correct_with_table_totals(*lookup.forces, creepages, solution);
}

bool correct_with_table_totals(const CreepForces& table, const Creepages& creepages,
                               TangentialSolution& solution) {
  creepages.validate();
  if (!table.Mz) return false;  // a table without Mz cannot give the spin's work
  // Interpolation can leave a tiny negative work near zero creepage; work is never negative.
  const double work = std::max(0.0, rigid_slip_work(table, creepages));
  solution.forces = table;
  if (solution.fields && solution.frictional_work > 0.0) {
    const double factor = work / solution.frictional_work;
    CellFields& f = *solution.fields;
    for (std::vector<double>* v : {&f.sx, &f.sy, &f.slip_norm, &f.work})
      for (double& x : *v) x *= factor;
    solution.frictional_work = work;
  }
  return true;
}

}  // namespace wheelwear::tangential
