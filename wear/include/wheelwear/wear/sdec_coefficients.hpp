#pragma once
/// Coefficients of the linear theory generalised to the SDEC region (Liu, Fu & Bruni 2022).

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/wear/creep_types.hpp"

namespace wheelwear::wear {

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

/// Table row for ellipticity a/b and Poisson's ratio nu.
///
/// K13 and the B's exist only for nu = 0.25 (Table 1), interpolated in a/b (a/b <= 1) or b/a
/// (a/b >= 1) like Kalker's table; outside 0.1 ... 10 the end row is held (flagged). For other nu
/// each of them is scaled with the ratio of its companion Kalker coefficient at nu and at 0.25
/// (K13 and B11 with C11, B22 with C22, B23 with C23), an approximation that keeps the SDEC
/// correction proportional to the elliptic stiffness it modifies (flagged). C11, C22, C23 are
/// always Kalker's (kalker_coefficients), as in the paper.
SdecTableRow sdec_table_row(double a_over_b, double nu, CoefficientFlags* flags = nullptr);

/// C11s, C13s, C22s, C23s of Eq. 12 for the region `sdec` and Poisson's ratio `nu`.
SdecCoefficients sdec_coefficients(const contactgeom::Sdec& sdec, double nu);

}  // namespace wheelwear::wear
