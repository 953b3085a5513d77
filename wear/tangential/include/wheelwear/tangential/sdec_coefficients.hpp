#pragma once
/// Coefficients of the linear theory generalised to the SDEC region (Liu, Fu & Bruni 2022).

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"

namespace wheelwear::tangential {

/// The table coefficients of one ellipticity: Kalker's C11, C22, C23 and the paper's K13,
/// B11, B22, B23 (Liu, Fu & Bruni 2022, Table 1).
struct SdecTableRow {
  double c11 = 0.0, c22 = 0.0, c23 = 0.0;
  double k13 = 0.0, b11 = 0.0, b22 = 0.0, b23 = 0.0;
};

/// The SDEC coefficients of Eq. 11-12 for one patch.
struct SdecCoefficients {
  double c11s = 0.0;  ///< C11 + B11 psi^2 [-]
  double c13s = 0.0;  ///< -K13 psi [-]
  double c22s = 0.0;  ///< C22 + B22 psi^2 [-]
  double c23s = 0.0;  ///< C23 + B23 psi^2 [-]
  SdecTableRow row;   ///< the interpolated table row the values come from
  CoefficientFlags flags;
};

/// Table row for ellipticity a/b and Poisson's ratio nu in [0, 0.5].
///
/// K13 and the B's are Table 1 of Liu, Fu & Bruni 2022 (nu = 0.25), interpolated in a/b
/// (a/b <= 1) or b/a (a/b >= 1) like Kalker's table; outside 0.1 ... 10 the end row is held
/// (flagged). For other nu, Table 1 is carried to nu with the change the exact theory gives
/// between 0.25 and nu (K13 by ratio, the B's by difference), from the coefficients generated
/// for nu = 0, 0.25, 0.28, 0.3, 0.5 by generators/sdec_table_generator.cpp (data/
/// sdec_coefficients.csv: Kalker's exact theory, no slip, Table 1's least-squares fit over
/// psi = 0.2 ... 0.8) and a natural cubic spline in nu between them. C11, C22, C23 are always
/// Kalker's (kalker_coefficients), as in the paper.
SdecTableRow sdec_table_row(double a_over_b, double nu, CoefficientFlags* flags = nullptr);

/// C11s, C13s, C22s, C23s of Eq. 12 for the region `sdec` and Poisson's ratio `nu`.
SdecCoefficients sdec_coefficients(const contactgeom::Sdec& sdec, double nu);

}  // namespace wheelwear::tangential
