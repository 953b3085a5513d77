#pragma once
/// Creep forces of SDEC patches interpolated in a book of tables of Kalker's exact theory, in
/// the spirit of Kalker's book of tables (Kalker 1996) and of KBTNH (Piotrowski, Liu & Bruni
/// 2017). The table (data/creep_table.h5, generators/creep_table_generator.cpp) is read at run
/// time, once, on first use (creep_table), from the first of:
///   1. $WHEELWEAR_DATA_DIR/creep_table.h5 when WHEELWEAR_DATA_DIR is set (then only there: a
///      folder set on purpose must not be replaced silently by another table);
///   2. <prefix>/share/wheelwear/creep_table.h5 of an installation, <prefix> the parent of the
///      folder of the running program (or of the shared object holding this library);
///   3. data/creep_table.h5 of the source tree the library was built from (programs run from
///      the build tree).
/// Every function below that needs the table throws InputError, naming each path tried, when
/// none is found or the file is not a readable table.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"

namespace wheelwear::tangential {

namespace detail {
struct CreepTableData;
struct CreepTableAccess;
}  // namespace detail

/// The parameter range a table covers (for messages and for choosing a method).
struct CreepTableRange {
  double nu_min = 0.0, nu_max = 0.0;              ///< Poisson's ratio [-]
  double a_over_b_min = 0.0, a_over_b_max = 0.0;  ///< ellipticity a/b [-]
  double psi_max = 0.0;                           ///< |psi| <= psi_max [-]
  /// Largest tabulated magnitude of the normalised creepage (xi, eta, chi) [-] (beyond it the
  /// table answers near full sliding only: creep_table_forces).
  double r_max = 0.0;
  int grid = 0;  ///< elements across the patch of the exact solver's grid the table was made with
  double spin_scale = 1.0;  ///< s of the normalised spin (creep_table_magnitude) [-]
  /// Its elements at most this many times as long as wide (0: grid x grid at every a/b);
  /// creep_table_grid gives the grid of a patch.
  double max_element_aspect = 0.0;
  /// Beyond r_max the table answers where the patch is nearly sliding fully: where its forces
  /// at r_max (same direction) lie within this fraction of mu N (and of mu N c for Mz) of the
  /// full-sliding limit, it extrapolates towards that limit (creep_table_forces) [-].
  double full_sliding_margin = 0.0;
};

/// A book of creep-force tables read from its file (load_creep_table): immutable; copies share
/// the data.
class CreepTable {
 public:
  /// What the table covers at every nu it tabulates (its groups, one per nu, may differ in
  /// their a/b, direction and r nodes: then the a/b range and r_max all of them cover).
  CreepTableRange range() const;
  /// What it covers at `nu` (clamped to nu_min ... nu_max): the a/b range and r_max of the
  /// groups that weigh in there (the group of nu alone when nu is one of the table's). Throws
  /// InputError when nu is not finite.
  CreepTableRange range(double nu) const;
  const std::filesystem::path& path() const;  ///< the file read (absolute)
  /// Lower-case hex SHA-256 of the file's bytes, the very bytes the table was read from.
  const std::string& sha256() const;
  const std::string& provenance() const;  ///< how the table was generated (the file's description)

 private:
  CreepTable() = default;  // only load_creep_table makes one: a table is never empty
  friend struct detail::CreepTableAccess;
  std::shared_ptr<const detail::CreepTableData> data_;
};

/// Reads the book of tables from `file` (the layout generators/creep_table_generator.cpp
/// writes). Throws InputError naming the file and what is wrong when it cannot be read, is not
/// HDF5 (e.g. truncated) or does not hold a consistent table.
CreepTable load_creep_table(const std::filesystem::path& file);

/// Searches creep_table.h5 now, in the order above; throws InputError naming every path tried
/// when none exists.
std::filesystem::path locate_creep_table();

/// The table of the functions below: load_creep_table(locate_creep_table()) on the first call
/// (thread-safe). A failure is kept: every later call throws the same InputError, so that one
/// run never mixes results with and without the table.
const CreepTable& creep_table();

/// The file of creep_table() (for results files: which table a run used).
std::filesystem::path creep_table_path();

/// creep_table().sha256(): lower-case hex SHA-256 of the file of creep_table().
std::string creep_table_sha256();

/// Lower-case hex SHA-256 of `bytes` (OpenSSL).
std::string sha256_hex(std::string_view bytes);

/// Lower-case hex SHA-256 of the file `file`, read but not loaded as a table: what a caller
/// that does not use the table records of it (tens of milliseconds, against the tenths of a
/// second creep_table() takes). Throws InputError when the file cannot be read.
std::string file_sha256(const std::filesystem::path& file);

/// The range of the table at every nu (creep_table().range()).
CreepTableRange creep_table_range();

/// The range of the table at `nu` (creep_table().range(nu)).
CreepTableRange creep_table_range(double nu);

/// The grid the table's nodes were solved on, for the patch `sdec` (a fresh exact solve on it
/// differs from the table by its interpolation alone): creep_table_range().grid elements
/// across, n x n up to a/b = max_element_aspect and as many more along a longer patch as keep
/// the elements no longer than there (aspect_sdec_grid).
SdecGridOptions creep_table_grid(const contactgeom::Sdec& sdec);

/// The normalised creepage of the table: xi = G c^2 C11 vx/(mu N), eta = G c^2 C22 vy/(mu N),
/// chi = s G c^3 C23 phi/(mu N), c = sqrt(ab) [m], C's Kalker's (Kalker 1990, Table E.3) for
/// the ellipse a/b at the table's nu, interpolated as the table does, s the table's spin scale
/// (CreepTableRange::spin_scale: spin saturates the patch at a fraction of the normalised
/// creepage translation needs); returns
/// sqrt(xi^2 + eta^2 + chi^2) [-] (the larger of the two tabulated nu around `material.nu`;
/// of the one when it is a tabulated nu),
/// which the table tabulates up to creep_table_range().r_max. Throws InputError on invalid
/// input and unless a/b, psi and nu are inside the table's range.
double creep_table_magnitude(const contactgeom::Sdec& sdec, const Creepages& creepages,
                             const ContactLoad& load, const Material& material);

/// The table's answer for one patch in one evaluation: its forces where it answers
/// (creep_table_forces), else why not (creep_table_outside).
struct CreepTableLookup {
  std::optional<CreepForces> forces;
  std::optional<std::string> outside;
};

/// Looks (sdec, creepages, load, material) up in the table: forces or the reason, never both.
/// Throws InputError on invalid input and when there is no table.
CreepTableLookup creep_table_lookup(const contactgeom::Sdec& sdec, const Creepages& creepages,
                                    const ContactLoad& load, const Material& material);

/// True when the table answers for (sdec, creepages, load, material): inside its range, or
/// beyond r_max near full sliding (creep_table_forces). Throws InputError on invalid input and
/// when there is no table (an installation without it is broken, not "outside").
bool creep_table_covers(const contactgeom::Sdec& sdec, const Creepages& creepages,
                        const ContactLoad& load, const Material& material);

/// Why the table does not answer for (sdec, creepages, load, material): which parameter is
/// outside and the table's range (beyond r_max: how far the patch is from full sliding);
/// std::nullopt when it answers. Throws InputError on invalid input and when there is no
/// table.
std::optional<std::string> creep_table_outside(const contactgeom::Sdec& sdec,
                                               const Creepages& creepages, const ContactLoad& load,
                                               const Material& material);

/// Total creep forces Fx, Fy [N] and the spin moment Mz about O [N m] on the wheel (Kalker's
/// convention: they oppose the creepages) of the SDEC patch `sdec` with creepages at O, from the
/// table of exact- theory solutions: local cubic (four-node Lagrange) interpolation in
/// log(a/b), psi, the direction (theta, beta) and the magnitude r of the normalised creepage, and
/// linear in nu between the tabulated ratios. psi < 0 uses the mirror image (vy, phi, Fy change
/// sign) and creepages with vx < 0 the reversed ones (forces change sign). Mz is tabulated as
/// Mz/(mu N c) (none for a table written without it). Near full sliding (|F| from 0.5 to 0.9
/// of the full-sliding limit S's, Fx/(mu N), Fy/(mu N), Mz/(mu N c) together, faded in), where
/// the forces turn with the
/// creepages' direction faster than the direction nodes resolve, the interpolation's error of S
/// is taken out: F + rho (S - S_interp), S (full_sliding_sdec on the table's grid) exact at the
/// creepages and S_interp interpolated from the limits the table holds per direction node (a
/// table written without them interpolates F alone). Beyond r_max, where the patch at r_max
/// (same direction) is within full_sliding_margin of its full-sliding limit S
/// (full_sliding_sdec on the table's grid), the exact theory's approach to that limit as 1/r
/// carries the table on: F(r) = S + (F(r_max) - S) r_max / r (S depends on the creepages'
/// direction alone). Throws InputError naming the parameter when the input is invalid or
/// outside what the table answers (creep_table_range, creep_table_outside): use FASTSIM-SDEC
/// there.
CreepForces creep_table_forces(const contactgeom::Sdec& sdec, const Creepages& creepages,
                               const ContactLoad& load, const Material& material);

/// The same with the table `table` (e.g. one read by load_creep_table from another file).
CreepForces creep_table_forces(const CreepTable& table, const contactgeom::Sdec& sdec,
                               const Creepages& creepages, const ContactLoad& load,
                               const Material& material);

/// The table's provenance (how it was generated).
std::string creep_table_provenance();

}  // namespace wheelwear::tangential
