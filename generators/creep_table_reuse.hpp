#pragma once
// --reuse: the solved nodes of an earlier table, copied into a new one instead of solved again.

#include <cstddef>
#include <string>
#include <vector>

#include "creep_table_nodes.hpp"

namespace wheelwear::generators {

/// The solved nodes of one nu group of an earlier table, to reuse where they are nodes of the new
/// one too (same nu, grid rule and spin scale; each axis value of the node among the old axis's).
struct Reused {
  Axes axes;
  std::vector<double> fx, fy, mz;
  bool square_only = false;  // written before the grid rule: n x n nodes only
};

/// Group `group_name` of the table at `path` when it was solved as the new one is (nu, n,
/// max_aspect, spin_scale), else nothing to reuse; throws when `path` is no HDF5 file.
Reused reusable(const std::string& path, const char* group_name, double nu, int n,
                double max_aspect, double spin_scale);

/// Copies into (fx, fy, mz) every node of `axes` that `old` holds and `reused` does not mark
/// yet, and marks it; returns how many.
std::size_t copy_reused(const Reused& old, const Axes& axes, double max_aspect,
                        std::vector<double>& fx, std::vector<double>& fy, std::vector<double>& mz,
                        std::vector<char>& reused);

}  // namespace wheelwear::generators
