#pragma once
/// Regularisation of a non-elliptic patch into a Simple Double-Elliptic Contact region
/// (Liu, Fu & Bruni 2022, Eq. 13-14, after Piotrowski, Liu & Bruni 2017), and the equivalent
/// ellipse of the FASTSIM-EQ.E comparator (same paper, Section 5 and Fig. 4).

#include "wheelwear/contactgeom/patch_measures.hpp"
#include "wheelwear/contactgeom/sdec.hpp"

namespace wheelwear::contactgeom {

/// The SDEC with the patch's area (pi a b = A_n), its length-to-width ratio (a/b = L_n/W_n) and
/// its origin at O (Liu, Fu & Bruni 2022, Eq. 13-14):
/// a = sqrt(A_n L_n / (pi W_n)), b = sqrt(A_n W_n / (pi L_n)), psi = (W1 - W2) / W_n.
/// W1 is the extent on the +y (gauge) side of O (PatchMeasures), so psi > 0 when the patch
/// reaches further towards +y: the convention of Sdec and of the reference data's psi_equiv.
/// Throws InputError when area, length or width is not positive, when W1 + W2 differs from the
/// width by more than 1e-9 relative, or when O is not strictly inside the lateral extent
/// (|psi| >= 1).
Sdec regularise_sdec(const PatchMeasures& measures);

/// Where the equivalent ellipse of FASTSIM-EQ.E is centred.
enum class EllipseCentre {
  at_O,        ///< at the initial contact point O (the usual choice)
  at_O_prime,  ///< at O' = O + psi b, the lateral mid-point of the SDEC (paper, Fig. 4)
};

/// Ellipse with the SDEC's semi-axes a, b, centred on the lateral axis at y_centre from O.
struct EquivalentEllipse {
  double a = 0.0;         ///< semi-axis along x [m]
  double b = 0.0;         ///< semi-axis along y [m]
  double y_centre = 0.0;  ///< lateral position of its centre measured from O [m]
  /// The ellipse as an SDEC (psi = 0) in its own frame, centred at y_centre.
  Sdec shape() const { return {a, b, 0.0}; }
};

/// The equivalent ellipse of an SDEC for FASTSIM-EQ.E (Liu, Fu & Bruni 2022, Section 5):
/// same a, b; centred at O (y_centre = 0) or at O' (y_centre = psi b). With the centre at O',
/// creepages given at O map to vx' = vx - phi psi b (Eq. 10). Validates `sdec`.
EquivalentEllipse equivalent_ellipse(const Sdec& sdec, EllipseCentre centre);

}  // namespace wheelwear::contactgeom
