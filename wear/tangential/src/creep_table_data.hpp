#pragma once
// The creep-force table compiled into the library: the arrays of data/creep_table.h5, written
// at build time by wear/tools/creep_table_embed.cpp into creep_table_data.cpp.

namespace wheelwear::tangential::detail {

/// One Poisson's ratio of the table. Nodes are indexed [g][psi][theta][beta][r] (r fastest).
struct CreepTableBlock {
  double nu;          ///< Poisson's ratio [-]
  int grid;           ///< elements per side of the exact solver's grid
  double spin_scale;  ///< s of the normalised spin chi = s G c^3 C23 phi / (mu N) [-]
  int n_g, n_psi, n_theta, n_beta, n_r;
  const double* a_over_b;  ///< n_g ellipticities a/b [-], increasing
  const double* psi;       ///< n_psi shape numbers [-], increasing from 0
  const double* theta;     ///< n_theta polar angles of the normalised creepage from chi [rad]
  const double* beta;      ///< n_beta azimuths in the (xi, eta) plane [rad], -pi/2 ... pi/2
  const double* r;         ///< n_r magnitudes of the normalised creepage [-], from 0
  const double* c11;       ///< n_g normalisation coefficients (Kalker's C11 at a/b, nu) [-]
  const double* c22;       ///< n_g (Kalker's C22) [-]
  const double* c23;       ///< n_g (Kalker's C23) [-]
  /// Per node (r fastest) three values: Fx/(mu N), Fy/(mu N), Mz/(mu N c) (c = sqrt(ab), Mz
  /// about O) [-], in single precision (6e-8 relative, far below the interpolation's error).
  const float* values;
  bool has_mz;                 ///< false for a table written without Mz (its values are 0)
  const double* log_a_over_b;  ///< n_g values log(a/b) (the interpolation's axis)
};

extern const CreepTableBlock* const kCreepTableBlocks;  ///< the blocks, increasing nu
extern const int kCreepTableBlockCount;                 ///< 0 when no table was built in
extern const char* const kCreepTableProvenance;         ///< the file's description

}  // namespace wheelwear::tangential::detail
