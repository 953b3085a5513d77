#pragma once
/// Kalker's creepage coefficients of the linear theory for elliptic contact areas.

namespace wheelwear::tangential {

/// C11, C22, C23 of Kalker's linear theory (Kalker 1990, Table E.3).
struct KalkerCoefficients {
  double c11 = 0.0;           ///< longitudinal coefficient [-]
  double c22 = 0.0;           ///< lateral coefficient [-]
  double c23 = 0.0;           ///< lateral-spin coefficient [-]
  bool extrapolated = false;  ///< true when a/b lies outside the table (0.1 ... 10)
};

/// Kalker's coefficients for the ellipse with semi-axes ratio `a_over_b` = a/b (a along the
/// rolling direction) and Poisson's ratio `nu` in [0, 0.5].
///
/// Inside the table (0.1 <= a/b <= 10) the values are interpolated linearly in a/b for a/b <= 1
/// and in b/a for a/b >= 1 (the table's own abscissae), and through nu = 0, 0.25, 0.5 by a
/// quadratic in nu of 1/C, which follows the near-hyperbolic growth of C with nu.
/// Outside it Kalker's asymptotic expressions for slender ellipses are used (Kalker 1990,
/// App. E; as listed in CONTACT's linrol), rescaled so that they meet the table's end row
/// continuously, and the result is flagged as extrapolated. Throws InputError for a/b <= 0,
/// non-finite input or nu outside [0, 0.5].
KalkerCoefficients kalker_coefficients(double a_over_b, double nu);

}  // namespace wheelwear::tangential
