#pragma once
// The full-sliding limits of the book of creep-force tables: per direction node
// [g][psi][theta][beta] the forces of a patch sliding everywhere (full_sliding_sdec on the node's
// grid), normalised as the table's forces, which its interpolation uses near full sliding
// (creep_table.cpp). No iteration: a second on two threads for the whole table.

#include <hdf5.h>

#include <string>
#include <vector>

#include "creep_table_nodes.hpp"

namespace wheelwear::generators {

struct Sliding {
  std::vector<double> fx, fy, mz;  ///< [g][psi][theta][beta]
};

Sliding sliding_limits(const Axes& axes, const Normalisation& k, int n, double max_aspect,
                       unsigned threads);

/// Writes the limits as the datasets Fx_sliding_muN, Fy_sliding_muN, Mz_sliding_muNc.
void write_sliding(hid_t group, const Sliding& s, const Axes& axes);

/// --add-sliding: writes (or rewrites) the limits into every group of the table at `path`, its
/// forces untouched, through a copy renamed over it only when the library reads it back as a
/// table. Returns the program's exit status; on failure the file is as it was.
int add_sliding(const std::string& path, unsigned threads);

}  // namespace wheelwear::generators
