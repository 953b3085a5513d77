#pragma once
/// The SDEC coefficients of Liu, Fu & Bruni 2022 (Table 1) from Kalker's exact theory, fitted
/// as CONTACT's reference data and the paper's Table 1 were.

#include <span>

#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"

namespace wheelwear::tangential {

/// The no-slip coefficients of Eq. 9 (creepages at O): C11s = -Fx/(G c^2 vx),
/// C22s = -Fy/(G c^2 vy), C23s = -Fy/(G c^3 phi), C13s = -Fx/(G c^3 phi), c = sqrt(ab).
struct SdecNoSlipCoefficients {
  double c11 = 0.0, c22 = 0.0, c23 = 0.0, c13 = 0.0;
  /// False when a solve did not converge or some element slipped (the friction is set so
  /// high that none should): the coefficients are then not the linear theory's.
  bool clean = true;
};

/// The coefficients of the SDEC patch a = 4.25 mm, b = a / a_over_b, shape number psi, from
/// three exact solves with unit creepages (1e-6) on options' grid.
SdecNoSlipCoefficients exact_no_slip_coefficients(double a_over_b, double psi,
                                                  const Material& material,
                                                  const SdecGridOptions& options);

/// Table 1's row at a_over_b: K13 by least squares of C13s = -K13 psi and each B by least
/// squares of Cs(psi) - Cs(0) = B psi^2 over `psis` (positive; the negative psi give the same
/// equations by symmetry), and the psi = 0 coefficients they rest on.
struct SdecCoefficientFit {
  double k13 = 0.0, b11 = 0.0, b22 = 0.0, b23 = 0.0;
  SdecNoSlipCoefficients at_zero;  ///< psi = 0
  bool clean = true;               ///< every solve converged without slip
};
SdecCoefficientFit fit_sdec_coefficients(double a_over_b, const Material& material,
                                         const SdecGridOptions& options, std::span<const double> psis);

}  // namespace wheelwear::tangential
