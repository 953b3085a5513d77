#pragma once
/// Hertz's elliptic contact from the principal relative curvatures: the elliptic comparator of the
/// non-Hertzian normal problem (Hertz 1882; Johnson 1985, Contact Mechanics, Sections 3.6, 4.2).

#include "wheelwear/contactgeom/sdec.hpp"

namespace wheelwear::contactgeom {

/// Combined modulus E* = [(1 - nu1^2)/E1 + (1 - nu2^2)/E2]^-1 [Pa] of two elastic half-spaces
/// (Johnson 1985, Section 4.2). E1, E2 [Pa] > 0; nu1, nu2 [-] in [0, 0.5).
double combined_modulus(double E1, double nu1, double E2, double nu2);

/// Combined modulus E* = E / (2 (1 - nu^2)) [Pa] of two bodies of the same material
/// (E [Pa] > 0, nu [-] in [0, 0.5)); 200 GPa and 0.25 give 106.7 GPa.
double combined_modulus(double E, double nu);

/// Hertz's solution for the undeformed distance h(x, y) = A x^2 + B y^2 - delta.
/// The patch is the ellipse x^2/a^2 + y^2/b^2 <= 1 with the pressure
/// p = p0 sqrt(1 - x^2/a^2 - y^2/b^2) (Johnson 1985, Sections 3.6 and 4.2).
struct HertzSolution {
  double a = 0.0;             ///< semi-axis along x [m]
  double b = 0.0;             ///< semi-axis along y [m]
  double p0 = 0.0;            ///< peak pressure [Pa]; N = (2/3) pi a b p0
  double delta = 0.0;         ///< approach of distant points of the two bodies [m]
  double normal_force = 0.0;  ///< N [N]

  double ellipticity() const { return a / b; }  ///< g = a/b [-]
  double area() const;                          ///< pi a b [m^2]
  /// The patch as an SDEC with psi = 0, for the tangential solvers and for comparisons.
  Sdec ellipse() const { return {a, b, 0.0}; }
};

/// Hertz contact for a prescribed normal force.
/// @param[in] A       relative curvature coefficient along x [1/m], > 0 (h = A x^2 + B y^2)
/// @param[in] B       relative curvature coefficient along y [1/m], > 0; any ratio A/B works
///                    (tested from 1e-4 to 1e4)
/// @param[in] E_star  combined modulus [Pa], > 0 (see combined_modulus)
/// @param[in] N       normal force [N], >= 0; N = 0 gives the zero solution
/// The eccentricity e of the ellipse solves B/A = (E(e) - k'^2 K(e)) / (k'^2 (K(e) - E(e))) with
/// k' = minor/major axis (Johnson 1985, Sections 3.6 and 4.2, written for A <= B; the roles of
/// x and y swap when A > B); then a^3 = 3 N (K - E) / (2 pi E* A e^2), p0 = 3N/(2 pi a b),
/// delta = p0 b K(e) / E* (b the minor semi-axis). Throws InputError on bad input.
HertzSolution hertz_from_load(double A, double B, double E_star, double N);

/// Hertz contact for a prescribed approach delta [m] >= 0 (delta = 0 gives the zero solution);
/// A, B, E_star as for hertz_from_load. N grows as delta^(3/2).
HertzSolution hertz_from_approach(double A, double B, double E_star, double delta);

}  // namespace wheelwear::contactgeom
