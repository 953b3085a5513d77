#pragma once
// The book of creep-force tables in memory: the arrays of data/creep_table.h5 (written by
// generators/creep_table_generator.cpp), read at run time by creep_table_data.cpp.

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "wheelwear/tangential/creep_table.hpp"

namespace wheelwear::tangential::detail {

/// One Poisson's ratio of the table. Nodes are indexed [g][psi][theta][beta][r] (r fastest).
struct CreepTableBlock {
  double nu = 0.0;  ///< Poisson's ratio [-]
  int grid = 0;     ///< elements across the patch of the exact solver's grid
  /// Elements at most this many times as long as wide (aspect_sdec_grid); 0: grid x grid at
  /// every a/b (tables made before the attribute).
  double max_element_aspect = 0.0;
  double spin_scale = 1.0;  ///< s of the normalised spin chi = s G c^3 C23 phi / (mu N) [-]
  int n_g = 0, n_psi = 0, n_theta = 0, n_beta = 0, n_r = 0;
  std::vector<double> a_over_b;  ///< n_g ellipticities a/b [-], increasing
  std::vector<double> psi;       ///< n_psi shape numbers [-], increasing from 0
  std::vector<double> theta;     ///< n_theta polar angles of the normalised creepage from chi [rad]
  std::vector<double> beta;      ///< n_beta azimuths in the (xi, eta) plane [rad], -pi/2 ... pi/2
  std::vector<double> r;         ///< n_r magnitudes of the normalised creepage [-], from 0
  std::vector<double> c11;       ///< n_g normalisation coefficients (Kalker's C11 at a/b, nu) [-]
  std::vector<double> c22;       ///< n_g (Kalker's C22) [-]
  std::vector<double> c23;       ///< n_g (Kalker's C23) [-]
  /// Per node (r fastest) three values: Fx/(mu N), Fy/(mu N), Mz/(mu N c) (c = sqrt(ab), Mz
  /// about O) [-], in single precision: its 6e-8 relative rounding is far below the
  /// interpolation's error (1e-3 of mu N) and halves the table's memory.
  std::vector<float> values;
  bool has_mz = false;  ///< false for a table written without Mz (its values are 0)
  /// Per direction node [g][psi][theta][beta] (beta fastest) three values: the full-sliding
  /// limit's Fx/(mu N), Fy/(mu N), Mz/(mu N c) (full_sliding_sdec on the node's grid), in
  /// single precision; empty for a table written without them.
  std::vector<float> sliding;
  std::vector<double> log_a_over_b;  ///< n_g values log(a/b) (the interpolation's axis)
};

struct CreepTableData {
  std::vector<CreepTableBlock> blocks;  ///< at least one, increasing nu
  std::string provenance;               ///< the file's description
  std::filesystem::path path;           ///< the file read
  std::string sha256;                   ///< of the file's bytes, lower-case hex
};

/// The library's way into a CreepTable's data.
struct CreepTableAccess {
  static const CreepTableData& data(const CreepTable& table) { return *table.data_; }
  static CreepTable make(std::shared_ptr<const CreepTableData> data) {
    CreepTable table;
    table.data_ = std::move(data);
    return table;
  }
};

}  // namespace wheelwear::tangential::detail
