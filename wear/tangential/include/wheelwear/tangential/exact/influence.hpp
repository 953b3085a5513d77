#pragma once
/// Half-space influence coefficients of piecewise-constant surface tractions (Love 1929;
/// Kalker 1990, Ch. 5), as used by Kalker's exact theory.

#include "wheelwear/tangential/creep_types.hpp"

namespace wheelwear::tangential {

/// Displacement difference u = u(body 1) - u(body 2) [m] at one surface point caused by a
/// uniform traction of 1 Pa on a rectangle, for two elastically similar half-spaces with
/// combined shear modulus G and Poisson's ratio nu. For such bodies the normal-tangential
/// coupling vanishes, so only these four entries exist (xy = yx).
struct InfluenceCoefficients {
  double xx = 0.0;  ///< u_x per unit p_x [m/Pa]
  double xy = 0.0;  ///< u_x per unit p_y = u_y per unit p_x [m/Pa]
  double yy = 0.0;  ///< u_y per unit p_y [m/Pa]
  double nn = 0.0;  ///< u_n per unit p_n (compression of the pair) [m/Pa]
};

/// Coefficients of the rectangle [x1, x2] x [y1, y2] [m], given relative to the point where the
/// displacement is evaluated (x1 < x2, y1 < y2). Closed-form integrals of the Boussinesq and
/// Cerruti point-load solutions (Johnson 1985, Eq. 3.19 and 3.86a-c) over the rectangle:
/// u_x = 1/(pi G) int [(1 - nu)/r + nu x^2/r^3] p_x, u_y|p_x = 1/(pi G) int nu x y/r^3 p_x,
/// u_n = (1 - nu)/(pi G) int p_n/r (Love 1929).
InfluenceCoefficients rectangle_influence(double x1, double x2, double y1, double y2,
                                          const Material& material);

}  // namespace wheelwear::tangential
