#pragma once
/// The Simple Double-Elliptic Contact (SDEC) region: two half-ellipses joined at the initial
/// contact point O (Liu, Fu & Bruni 2022, Eq. 1-3; Piotrowski, Liu & Bruni 2017).

namespace wheelwear::contactgeom {

/// SDEC region in the contact frame with origin at O: x rolling direction, y lateral.
/// For y > 0 the lateral semi-axis is b(1+psi), for y <= 0 it is b(1-psi), so psi > 0 means the
/// patch reaches further on the +y side of O. The patch spans y in [-b(1-psi), b(1+psi)],
/// its lateral mid-point O' lies at y0 = psi*b, and its area is pi*a*b. psi = 0 is the ellipse.
struct Sdec {
  double a = 0.0;    ///< semi-length along x [m], > 0
  double b = 0.0;    ///< semi-width along y [m], > 0
  double psi = 0.0;  ///< shape number y0/b [-], |psi| < 1

  /// Validates the region; throws InputError naming the bad field.
  void validate() const;

  double ellipticity() const { return a / b; }       ///< g = a/b [-]
  double c() const;                                  ///< sqrt(a*b) [m]
  double area() const;                               ///< pi*a*b [m^2]
  double y0() const { return psi * b; }              ///< lateral position of O' from O [m]
  double y_min() const { return -b * (1.0 - psi); }  ///< lateral edge on the -y side [m]
  double y_max() const { return b * (1.0 + psi); }   ///< lateral edge on the +y side [m]

  /// Leading edge x_l(y) >= 0 [m] (Eq. 3); 0 outside the region.
  double leading_edge(double y) const;
  /// Lateral semi-axis of the half-ellipse that holds y [m].
  double half_width(double y) const { return y > 0.0 ? b * (1.0 + psi) : b * (1.0 - psi); }

  /// Maximum pressure p0 [Pa] of the semi-elliptic distribution (Eq. 4) for normal force N [N]:
  /// N = (2/3) p0 pi a b.
  double peak_pressure(double normal_force) const;
  /// Pressure p_n(x, y) = (p0/a) sqrt(x_l(y)^2 - x^2) [Pa] (Eq. 4); 0 outside.
  double pressure(double x, double y, double normal_force) const;
};

}  // namespace wheelwear::contactgeom
