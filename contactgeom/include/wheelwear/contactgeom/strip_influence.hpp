#pragma once
/// Influence integrals of a strip of semi-elliptic pressure on the normal displacement at a point:
/// the kernel of the Kik-Piotrowski contact condition (Piotrowski & Kik 2008, VSD 46:27-48).
///
/// With Boussinesq's half-space solution, a pressure p(x, y) on the surface moves the two bodies
/// together at the origin by u = 1/(pi E*) int int p(x, y) / sqrt(x^2 + y^2) dx dy
/// (Johnson 1985, Chapter 3, for one body; E* as in combined_modulus). For the pressure
/// p = q sqrt(c^2 - x^2) of one strip of half-length c, u = q/(pi E*) times the integrals below.

namespace wheelwear::contactgeom {

/// Line influence L(c, y) = int_{-c}^{c} sqrt(c^2 - x^2) / sqrt(x^2 + y^2) dx [m] of a line of
/// semi-elliptic pressure of half-length c [m] >= 0 at lateral distance y [m] from the field point.
/// Closed form (substituting x = c sin t): L = 2 sqrt(c^2 + y^2) (K(k) - E(k)),
/// k^2 = c^2/(c^2 + y^2), evaluated with k_minus_e_unchecked (1.4e-8 relative). L has a
/// logarithmic singularity at y = 0 (returns +inf there when c > 0) and tends to
/// pi c^2 / (2 |y|) far away. Returns 0 for c = 0. No input checks (hot path).
double line_influence(double c, double y);

/// Strip influence S(c, y1, y2) = int_{y1}^{y2} L(c, y) dy [m^2] for y1 <= y2 [m], both measured
/// from the field point; finite also when the strip holds the field point. No input checks.
/// Accuracy (relative, per strip; measured in strip_influence_test against tanh-sinh
/// quadrature of the definition):
/// - strips within two widths of the field point: L's expansion about the field point
///   (log singularity and terms to tau^4 ln tau) integrated in closed form when the strip ends
///   within c/8 of it, else the singular part exactly and the rest by graded 4-point
///   Gauss-Legendre: < 1e-7 (1e-11 ... 1e-8 measured);
/// - strips 2 to 4 widths away: 3-point, 4 to 8 widths: 2-point Gauss-Legendre, < 1e-6;
/// - farther strips: midpoint rule, error (w/y)^2/12 relative at most (w the strip width),
///   below 1.3e-3 per strip and far smaller in a patch's sum because those strips weigh little.
/// L itself carries the 1.4e-8 of Hastings' approximation of K - E (elliptic_integrals.hpp).
/// The rule changes with the distance, so S jumps by up to the rule's error where a strip
/// edge crosses 2, 4 or 8 widths.
double strip_influence(double c, double y1, double y2);

}  // namespace wheelwear::contactgeom
