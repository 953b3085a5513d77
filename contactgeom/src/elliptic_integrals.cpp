#include "wheelwear/contactgeom/elliptic_integrals.hpp"

#include <cmath>
#include <numbers>

#include "strip_kernel.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::contactgeom {
namespace {

// Result of the arithmetic-geometric mean a_n, b_n -> M(1, k') with the weighted sum
// S = sum_{n>=0} 2^(n-1) c_n^2, c_0 = k, c_(n+1) = (a_n - b_n)/2
// (Abramowitz & Stegun 1964, 17.6.3-17.6.4): K = pi/(2 M), E = K (1 - S).
struct AgmResult {
  double mean;
  double weighted_sum;
};

// kc = k' and m = k^2 = 1 - k'^2 are passed separately so that neither is formed from the other
// where that loses digits (m from k' near 1, k' from k near 0).
AgmResult agm(double kc, double m) {
  // c_(n+1) is updated as c_n^2 / (4 a_(n+1)), which equals (a_n - b_n)/2 but does not lose
  // digits when a_n and b_n are close (k -> 0).
  double a = 1.0;
  double b = kc;
  double c = std::sqrt(m);
  double sum = 0.5 * m;
  double weight = 0.5;
  // Convergence is quadratic; 40 steps cover kc down to the smallest normal double.
  for (int n = 0; n < 40 && c > 1e-9 * a; ++n) {
    const double a_next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    c = c * c / (4.0 * a_next);
    a = a_next;
    weight *= 2.0;
    sum += weight * c * c;
  }
  // Stopping test: c_n <= 1e-9 a_n, so a_n - b_n = 2 c_(n+1) = c_n^2/(2 a_(n+1)) <= 5e-19 a_n
  // and the remaining terms of S are below 1e-18 relative.
  return {a, sum};
}

// K, E and their differences from k' and m = k^2 (see agm).
CompleteEllipticIntegrals integrals(double kc, double m) {
  const AgmResult r = agm(kc, m);
  CompleteEllipticIntegrals out;
  out.K = std::numbers::pi / (2.0 * r.mean);
  out.K_minus_E = out.K * r.weighted_sum;
  out.E = out.K - out.K_minus_E;
  // E - k'^2 K = K (m - S); m - S = m/2 - sum_{n>=1} 2^(n-1) c_n^2 keeps its relative accuracy
  // for small k because c_1^2 <= m^2/4. As k' -> 0 it loses digits in proportion to K.
  out.E_minus_kc2_K = out.K * (m - r.weighted_sum);
  return out;
}

}  // namespace

CompleteEllipticIntegrals complete_elliptic_integrals_kc(double kc) {
  require_finite("kc", kc);
  require(kc > 0.0 && kc <= 1.0, "kc", kc,
          "the complementary modulus must lie in (0, 1]; K diverges at kc = 0");
  return integrals(kc, (1.0 - kc) * (1.0 + kc));
}

CompleteEllipticIntegrals complete_elliptic_integrals(double k) {
  require_finite("k", k);
  require(k >= 0.0 && k < 1.0, "k", k, "the modulus must lie in [0, 1); K diverges at k = 1");
  return integrals(std::sqrt((1.0 - k) * (1.0 + k)), k * k);
}

double k_minus_e_unchecked(double kc) {
  return detail::k_minus_e((1.0 - kc) * (1.0 + kc), kc * kc);
}

}  // namespace wheelwear::contactgeom
