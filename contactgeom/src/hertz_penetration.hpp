#pragma once
// How far Hertz's ellipse reaches compared with the interpenetration of the undeformed surfaces
// at the approach delta (internal to the Kik-Piotrowski solver): for h = A x^2 + B y^2 its
// semi-axes satisfy A a^2 = eps_x delta and B b^2 = eps_y delta, and the factors depend on B/A
// alone. They sum to 1 (A a^2 + B b^2 = delta holds for every Hertz ellipse; 1/2 each for a
// circle), and the long axis takes the larger one: 0.77 along x for B/A = 100 (a/b = 18).

namespace wheelwear::contactgeom::detail {

/// eps_x = A a^2 / delta of Hertz's ellipse for the curvature ratio B/A, from a table in
/// ln(B/A) built once (interpolation error about 1.2e-6); eps_y = 1 - eps_x. Ratios beyond
/// 1e-6 ... 1e6 take the end values, and a ratio that is not positive (or NaN) the lower one.
double hertz_penetration_x(double curvature_ratio);

}  // namespace wheelwear::contactgeom::detail
