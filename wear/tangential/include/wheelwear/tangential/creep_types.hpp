#pragma once
/// Value types shared by the tangential contact solvers: creepages, material, load, forces.

#include <optional>
#include <string>

#include "wheelwear/contactgeom/creepages.hpp"

namespace wheelwear::tangential {

/// Creepages at O; defined with the contact geometry, which computes them from kinematics.
using contactgeom::Creepages;

/// Elastic constants of the (elastically similar) wheel and rail.
struct Material {
  double G = 80e9;   ///< combined shear modulus [Pa], > 0
  double nu = 0.25;  ///< Poisson's ratio [-], 0 <= nu <= 0.5

  void validate() const;
};

/// Normal load and friction of one contact.
struct ContactLoad {
  double N = 0.0;   ///< normal force [N], > 0
  double mu = 0.3;  ///< Coulomb friction coefficient [-], > 0

  void validate() const;
};

/// Flags that say a coefficient came from outside the range of its table.
struct CoefficientFlags {
  bool kalker_extrapolated = false;  ///< a/b outside 0.1 ... 10: Kalker's asymptotes were used
  bool sdec_held = false;            ///< a/b outside 0.1 ... 10: Table 1's end row was held

  bool any() const { return kalker_extrapolated || sdec_held; }
  /// Human-readable list of the raised flags, empty when none is.
  std::string describe() const;
};

/// Total tangential forces on body 1 (the wheel) in Kalker's convention: they oppose the
/// creepages, so positive vx gives negative Fx (Liu, Fu & Bruni 2022, Eq. 11).
struct CreepForces {
  double Fx = 0.0;  ///< longitudinal force [N]
  double Fy = 0.0;  ///< lateral force [N]
  /// Spin moment about O [N m]; none from the linear theory, which does not define it for
  /// the SDEC.
  std::optional<double> Mz;
  CoefficientFlags flags;  ///< where the coefficients came from
};

/// The forces times `weight` (a patch's share of a blend of descriptions).
inline CreepForces weighted(CreepForces f, double weight) {
  f.Fx *= weight;
  f.Fy *= weight;
  if (f.Mz) *f.Mz *= weight;
  return f;
}

}  // namespace wheelwear::tangential
