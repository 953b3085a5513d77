#pragma once
/// Creep forces of SDEC patches interpolated in a book of tables of Kalker's exact theory, in
/// the spirit of Kalker's book of tables (Kalker 1996) and of KBTNH (Piotrowski, Liu & Bruni
/// 2017). The table (data/creep_table.h5, generators/creep_table_generator.cpp) is compiled into the
/// library.

#include <optional>
#include <string>
#include <vector>

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"

namespace wheelwear::tangential {

/// The parameter range the built-in table covers (for messages and for choosing a method).
struct CreepTableRange {
  double nu_min = 0.0, nu_max = 0.0;              ///< Poisson's ratio [-]
  double a_over_b_min = 0.0, a_over_b_max = 0.0;  ///< ellipticity a/b [-]
  double psi_max = 0.0;                           ///< |psi| <= psi_max [-]
  /// Largest magnitude of the normalised creepage (xi, eta, chi) [-] (see creep_table_forces).
  double r_max = 0.0;
  int grid = 0;  ///< elements per side of the exact solver's grid the table was made with
  double spin_scale = 1.0;  ///< s of the normalised spin (creep_table_magnitude) [-]
};

/// The range of the built-in table; all zero when the library was built without it.
CreepTableRange creep_table_range();

/// The normalised creepage of the table: xi = G c^2 C11 vx/(mu N), eta = G c^2 C22 vy/(mu N),
/// chi = s G c^3 C23 phi/(mu N), c = sqrt(ab) [m], C's Kalker's (Kalker 1990, Table E.3) for
/// the ellipse a/b at the table's nu, interpolated as the table does, s the table's spin scale
/// (CreepTableRange::spin_scale: spin saturates the patch at a fraction of the normalised
/// creepage translation needs); returns
/// sqrt(xi^2 + eta^2 + chi^2) [-] (the larger of the two tabulated nu around `material.nu`),
/// which the table covers up to creep_table_range().r_max. Throws InputError unless a/b, psi
/// and nu are inside the table's range.
double creep_table_magnitude(const contactgeom::Sdec& sdec, const Creepages& creepages,
                             const ContactLoad& load, const Material& material);

/// True when (sdec, creepages, load, material) lie inside the built-in table's range.
bool creep_table_covers(const contactgeom::Sdec& sdec, const Creepages& creepages,
                        const ContactLoad& load, const Material& material);

/// Why the built-in table does not cover (sdec, creepages, load, material): which parameter is
/// outside and the table's range; std::nullopt when it covers them.
std::optional<std::string> creep_table_outside(const contactgeom::Sdec& sdec,
                                               const Creepages& creepages, const ContactLoad& load,
                                               const Material& material);

/// Total creep forces Fx, Fy [N] and the spin moment Mz about O [N m] on the wheel (Kalker's
/// convention: they oppose the creepages) of the SDEC patch `sdec` with creepages at O, from the
/// built-in table of exact- theory solutions: local cubic (four-node Lagrange) interpolation in
/// log(a/b), psi, the direction (theta, beta) and the magnitude r of the normalised creepage, and
/// linear in nu between the tabulated ratios. psi < 0 uses the mirror image (vy, phi, Fy change
/// sign) and creepages with vx < 0 the reversed ones (forces change sign). Mz is tabulated as
/// Mz/(mu N c) (none for a table written without it). Throws InputError naming the
/// parameter when the input is invalid or outside the table's range (creep_table_range): use
/// FASTSIM-SDEC there.
CreepForces creep_table_forces(const contactgeom::Sdec& sdec, const Creepages& creepages,
                               const ContactLoad& load, const Material& material);

/// The built-in table's provenance (how it was generated), empty without a table.
std::string creep_table_provenance();

}  // namespace wheelwear::tangential
