#pragma once
// Interpolation in the book of creep tables' blocks (creep_table_data.hpp): four-node Lagrange
// stencils in log(a/b), psi, the direction (theta, beta) and the magnitude r of the normalised
// creepage, with the symmetries psi -> -psi and v -> -v, and linear in nu between two blocks.
// What the table answers from it (its range, near and beyond full sliding) is creep_table.cpp's.

#include <array>

#include "creep_table_data.hpp"
#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"

namespace wheelwear::tangential::detail {

// The blocks (one or two) and weights for nu; nullptr second when one block suffices.
struct NuBlocks {
  const CreepTableBlock* lower = nullptr;
  const CreepTableBlock* upper = nullptr;
  double t = 0.0;  // weight of upper
};

// Normalised forces interpolated in a block: Fx/(mu N), Fy/(mu N), Mz/(mu N c) (Mz 0 when the
// block has none), and the full-sliding limit interpolated the same way from the block's
// direction nodes (zero when the block has none).
struct Interpolated {
  std::array<double, 3> f{};
  std::array<double, 3> sliding{};
};

/// The normalised creepage's magnitude r: the larger of the two blocks' (their C's differ).
double magnitude(const NuBlocks& nb, const contactgeom::Sdec& sdec, const Creepages& v,
                 const ContactLoad& load, const Material& material);

/// The forces and the full-sliding limit interpolated in the blocks, linear in nu between them.
Interpolated interpolate(const NuBlocks& nb, const contactgeom::Sdec& sdec, const Creepages& v,
                         const ContactLoad& load, const Material& material);

/// True when the blocks hold the full-sliding limits.
bool has_sliding(const NuBlocks& nb);

}  // namespace wheelwear::tangential::detail
