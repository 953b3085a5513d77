#pragma once
// Points of the book of creep-force tables' parameter space (creep_table.hpp) and the table's
// error at a point against a fresh exact solve on the table's own grid, so that the difference
// is the interpolation's error, not the grid's. Shared by tests/tangential/creep_table_test.cpp
// and studies/table_interpolation_study.cpp, which draw their points from the same sequence.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/kalker_coefficients.hpp"

namespace wheelwear::testing::creep_table {

/// A point of the table's parameter space, as physical input (at kLoad).
struct Point {
  contactgeom::Sdec sdec;
  tangential::Creepages creepages;
  tangential::Material material;
};

inline const tangential::ContactLoad kLoad{2e4, 0.3};

/// Creepages whose normalised magnitude and direction are (r, theta, beta) (creep_table.hpp),
/// with Kalker's C's at the patch's a/b and the material's nu.
inline tangential::Creepages creepages_for(const contactgeom::Sdec& s,
                                           const tangential::Material& m, double r, double theta,
                                           double beta) {
  const tangential::KalkerCoefficients k = tangential::kalker_coefficients(s.ellipticity(), m.nu);
  const double c = s.c(), mu_n = kLoad.mu * kLoad.N, gc2 = m.G * c * c;
  return {
      r * std::sin(theta) * std::cos(beta) * mu_n / (gc2 * k.c11),
      r * std::sin(theta) * std::sin(beta) * mu_n / (gc2 * k.c22),
      r * std::cos(theta) * mu_n / (tangential::creep_table_range().spin_scale * gc2 * c * k.c23)};
}

/// A fixed sequence of points spread over the whole range of the table (or the Shapes given):
/// a/b log-uniform, psi uniform in +-psi_max, nu between the tabulated ratios, directions
/// uniform on the sphere, r uniform in 0 ... r_max (a linear congruential generator, the same on
/// every platform).
class PointSequence {
 public:
  explicit PointSequence(std::uint64_t seed = 12345) : state_(seed) {}

  /// Where the points lie in a/b (log-uniform), nu (uniform) and up to which normalised
  /// creepage (next: r uniform in 0 ... r_max).
  struct Shapes {
    double a_over_b_min, a_over_b_max, nu_min, nu_max, r_max;
  };

  /// What the table covers at every nu.
  static Shapes whole_table() {
    const tangential::CreepTableRange range = tangential::creep_table_range();
    return {range.a_over_b_min, range.a_over_b_max, range.nu_min, range.nu_max, range.r_max};
  }

  /// A point inside the table's creepages (r up to r_max).
  Point next(const Shapes& shapes = whole_table()) { return draw(0.0, shapes); }

  /// A point beyond them: r log-uniform in r_max ... r_top, where the table answers only near
  /// full sliding (creep_table_forces).
  Point next_beyond(double r_top) { return draw(r_top, whole_table()); }

 private:
  Point draw(double r_top, const Shapes& shapes) {
    const tangential::CreepTableRange range = tangential::creep_table_range();
    const double g =
        shapes.a_over_b_min * std::pow(shapes.a_over_b_max / shapes.a_over_b_min, uniform());
    const double psi = range.psi_max * (2 * uniform() - 1);
    const double nu = shapes.nu_min + (shapes.nu_max - shapes.nu_min) * uniform();
    const double u = uniform();
    const double r =
        r_top > 0.0 ? range.r_max * std::pow(r_top / range.r_max, u) : shapes.r_max * u;
    const double theta = std::acos(2 * uniform() - 1);
    const double beta = std::numbers::pi * (2 * uniform() - 1);
    const contactgeom::Sdec s{5e-3, 5e-3 / g, psi};
    const tangential::Material m{80e9, nu};
    tangential::Creepages v = creepages_for(s, m, r, theta, beta);
    if (r_top <= 0.0) {
      // Kalker's C's at a/b stand in for the table's normalisation (its C's are interpolated
      // between nodes): keep the table's own magnitude inside r_max.
      const double scale =
          std::min(1.0, 0.999 * shapes.r_max / tangential::creep_table_magnitude(s, v, kLoad, m));
      v = {v.vx * scale, v.vy * scale, v.phi * scale};
    }
    return {s, v, m};
  }

  double uniform() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state_ >> 11) / 9007199254740992.0;
  }
  std::uint64_t state_;
};

/// The table's error at a point: |F_table - F_exact| / (mu N) and |Mz_table - Mz_exact| /
/// (mu N c), with the exact solve's status (a point whose solve did not converge is no
/// measure of the table).
struct TableError {
  double force = 0.0, moment = 0.0;
  tangential::ExactStatus status = tangential::ExactStatus::converged;
};

inline TableError table_error(const Point& p) {
  const tangential::ExactSolution exact = tangential::exact_sdec(
      p.sdec, p.creepages, kLoad, p.material, tangential::creep_table_grid(p.sdec));
  const tangential::CreepForces table =
      tangential::creep_table_forces(p.sdec, p.creepages, kLoad, p.material);
  const double mu_n = kLoad.mu * kLoad.N;
  return {std::hypot(table.Fx - exact.forces.Fx, table.Fy - exact.forces.Fy) / mu_n,
          std::abs(table.Mz.value_or(std::nan("")) - exact.forces.Mz.value_or(std::nan(""))) /
              (mu_n * p.sdec.c()),
          exact.status};
}

}  // namespace wheelwear::testing::creep_table
