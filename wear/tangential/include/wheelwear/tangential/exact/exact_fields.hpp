#pragma once
/// A solution of Kalker's exact theory in the form the wear laws read: per-element fields as
/// FASTSIM's per-cell fields, so that a wear run can take its patches from the exact theory.

#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"
#include "wheelwear/tangential/fastsim.hpp"

namespace wheelwear::tangential {

/// `exact`'s totals and its elements as CellFields (every field; strips are the grid's rows j,
/// cells its elements i; positions relative to O): tractions, pressure, slip and the work
/// density |p| |s|. The slip and the work density are scaled by one factor so that the work
/// sums to the rigid slip's work of the totals, rigid_slip_work(exact.forces, creepages) plus
/// exact.row_creepage_work (a per-row creepage, wheel_rail_exact's radius_variation):
/// Kalker's backward difference makes the sum of |p| |s| converge only to first order in the
/// element size (9 % low on 40 x 40 at large spin), while the totals converge faster and in the
/// continuum the two works are equal (table_correction.hpp). Returns frictional_work as that
/// work; solves without contact give zero fields.
TangentialSolution exact_tangential_solution(const ExactSolution& exact,
                                             const Creepages& creepages);

}  // namespace wheelwear::tangential
