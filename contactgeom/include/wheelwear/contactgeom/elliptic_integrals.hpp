#pragma once
/// Complete elliptic integrals of the first and second kind, evaluated by the arithmetic-geometric
/// mean (Abramowitz & Stegun 1964, 17.6; DLMF 19.8.1 and 19.8.6).

namespace wheelwear::contactgeom {

/// K(k), E(k) and the two differences that Hertz theory needs, each to about 1e-14 relative
/// (the loss grows like K(k) as k -> 1).
/// The differences are computed directly from the AGM sequence (K - E = K*S,
/// E - k'^2 K = K*(k^2 - S) with S = sum 2^(n-1) c_n^2), so they keep their relative accuracy
/// where subtracting K and E would cancel (k -> 0).
struct CompleteEllipticIntegrals {
  double K = 0.0;              ///< K(k) = int_0^(pi/2) dt / sqrt(1 - k^2 sin^2 t) [-]
  double E = 0.0;              ///< E(k) = int_0^(pi/2) sqrt(1 - k^2 sin^2 t) dt [-]
  double K_minus_E = 0.0;      ///< K(k) - E(k) >= 0 [-]
  double E_minus_kc2_K = 0.0;  ///< E(k) - k'^2 K(k) >= 0, k' = sqrt(1 - k^2) [-]
};

/// Complete elliptic integrals for the complementary modulus kc = k' = sqrt(1 - k^2) [-],
/// 0 < kc <= 1. Taking k' as the argument keeps full precision for the very eccentric case
/// (k -> 1, k' -> 0) that slender contact patches produce. Throws InputError for kc outside
/// (0, 1] or not finite.
CompleteEllipticIntegrals complete_elliptic_integrals_kc(double kc);

/// Same as complete_elliptic_integrals_kc, for the modulus k [-], 0 <= k < 1.
CompleteEllipticIntegrals complete_elliptic_integrals(double k);

/// K(k) - E(k) for the complementary modulus kc [-], 0 < kc <= 1, without input checks: the
/// fast kernel of the strip influence integrals. Uses the Maclaurin series in m = 1 - kc^2 where
/// it converges fast (m <= 0.1, truncation < 1e-15 relative) and Hastings' approximations
/// otherwise (Abramowitz & Stegun 1964, 17.3.34 and 17.3.36: absolute error <= 4e-8 by their
/// bounds, 1.4e-8 relative measured against the AGM).
double k_minus_e_unchecked(double kc);

}  // namespace wheelwear::contactgeom
