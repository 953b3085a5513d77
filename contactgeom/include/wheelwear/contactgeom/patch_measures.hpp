#pragma once
/// Size and position measures of a contact patch, as the SDEC regularisation needs them
/// (Liu, Fu & Bruni 2022, Section 3 and Fig. 3: A_n, L_n, W_n, W1, W2).
///
/// Lateral convention, used throughout contactgeom: +y points to the gauge side (towards the
/// track centre); W1 is the extent of the patch on the +y side of the initial contact point O
/// and W2 on the -y side, so W1 - W2 > 0 when the patch reaches further towards the gauge side.
/// This is the convention of the reference data's W_pos (= W1) and W_neg (= W2).

#include <Eigen/Core>
#include <vector>

#include "wheelwear/contactgeom/kik_piotrowski.hpp"

namespace wheelwear::contactgeom {

/// Measures of one patch in the contact frame (x rolling direction, y lateral, +y gauge side).
struct PatchMeasures {
  double area = 0.0;        ///< A_n [m^2]
  double length = 0.0;      ///< L_n, extent along x [m]
  double width = 0.0;       ///< W_n, extent along y [m]
  double centroid_x = 0.0;  ///< area centroid, x [m]
  double centroid_y = 0.0;  ///< area centroid, y [m]
  double y_O = 0.0;         ///< lateral position of the initial contact point O [m]
  double W1 = 0.0;          ///< y_max - y_O: extent on the +y (gauge) side of O [m]
  double W2 = 0.0;          ///< y_O - y_min: extent on the -y side of O [m]
};

/// A closed patch outline: #vertices (x [m], y [m]) without repeating the first vertex; either
/// orientation.
using PatchRing = std::vector<Eigen::Vector2d>;

/// Measures of a patch made of one or more disjoint, simple polygons, computed with
/// Boost.Geometry (area, centroid, envelope). y_O [m] is the lateral position of O.
/// Throws InputError for an empty patch, a ring with fewer than 3 vertices or non-finite
/// coordinates, or a zero total area.
PatchMeasures measure_polygons(const std::vector<PatchRing>& rings, double y_O);

/// Measures of a Kik-Piotrowski patch computed directly from its strips (the fast path):
/// area = sum 2 x_lead ds, length = 2 max x_lead, centroid_x = 0 (strips are symmetric in x),
/// O = patch.s_O: equal to measure_polygons(patch_outline(patch), patch.s_O) to rounding
/// (tested). The width ends where x_lead^2, taken linear from the outermost strip in contact to
/// the strip beyond it (its -KpStrip::opening, or KpPatch::opening_before/after beyond the list),
/// falls to zero, within one strip beyond the outer strip's centre: it moves continuously as a
/// strip comes into contact and as one leaves it, so the SDEC and the creep forces are
/// continuous in the wheelset's position, which Newton's method on a vehicle's balance needs.
/// Where the strip beyond is not known (no opening: strips built without them), x_lead^2 is
/// extrapolated from the two outermost strips instead (half a strip, as the staircase outline,
/// for a one-strip side), continuous only as strips come into contact. A piece of the patch beyond
/// strips out of contact (a worn tread's separate band) moves the edge from the piece that
/// holds O by the share d / (d + r) of its reach, d its deepest x_lead^2 and r the largest
/// KpStrip::opening between them: nothing as it appears or vanishes, all of it as the two join.
/// Throws InputError when no strip of the patch is in contact.
PatchMeasures measure_patch(const KpPatch& patch);

/// Outline of a Kik-Piotrowski patch: each strip in contact is the rectangle
/// [-x_lead, x_lead] x [s - ds/2, s + ds/2]; each run of neighbouring strips in contact gives
/// one counter-clockwise staircase ring. Allocates: for output and checks, not the hot path.
std::vector<PatchRing> patch_outline(const KpPatch& patch);

}  // namespace wheelwear::contactgeom
