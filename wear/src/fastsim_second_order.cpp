// Second-order marching of the simplified theory along each strip.
//
// Along a strip the marching distance t = x_l - x runs from the leading edge (t = 0) to the
// trailing edge (t = 2 x_l). Where the surfaces adhere the traction follows the rigid slip,
// dp/dt = r(t); where they slip it lies on the bound, p = g(t) e, and its direction turns
// with the part of r normal to it, de/dt = (r - (e.r) e)/g. Kalker's FASTSIM advances both
// with one explicit step per cell and gives each cell its trailing node's traction, which is
// first-order accurate. Here each cell is integrated with the trapezoidal rule, the point
// where adhesion turns into slip is located inside the cell, the direction in slip takes a
// midpoint step, and the traction is integrated by Simpson's rule on each piece.

#include <algorithm>
#include <cmath>

#include "fastsim_kernel.hpp"

namespace wheelwear::wear::detail {

namespace {

struct Vec {
  double x = 0.0, y = 0.0;
};
inline Vec operator+(Vec a, Vec b) {
  return {a.x + b.x, a.y + b.y};
}
inline Vec operator-(Vec a, Vec b) {
  return {a.x - b.x, a.y - b.y};
}
inline Vec operator*(double s, Vec a) {
  return {s * a.x, s * a.y};
}
inline double dot(Vec a, Vec b) {
  return a.x * b.x + a.y * b.y;
}
inline double norm(Vec a) {
  return std::sqrt(dot(a, a));
}
inline Vec unit(Vec a, Vec fallback) {
  const double n = norm(a);
  return n > 0.0 ? (1.0 / n) * a : fallback;
}
// The part of v normal to the unit vector e.
inline Vec normal_part(Vec v, Vec e) {
  return v - dot(v, e) * e;
}

// Fraction theta in [0, 1] of a cell where |p + theta d| first reaches the bound, the bound
// taken linear between its node values g0 and g1 (its error is O(dt^2) within a cell).
// |p + theta d|^2 - (g0 + theta (g1 - g0))^2 is negative at 0 and positive at 1, so it has
// exactly one root in between.
double crossing_fraction(Vec p, Vec d, double g0, double g1) {
  const double dg = g1 - g0;
  const double qa = dot(d, d) - dg * dg;
  const double qb = 2.0 * (dot(p, d) - g0 * dg);
  const double qc = dot(p, p) - g0 * g0;
  if (qc >= 0.0) return 0.0;
  const double disc = std::max(qb * qb - 4.0 * qa * qc, 0.0);
  // Stable roots: q/qa and qc/q with q = -(qb + sign(qb) sqrt(disc))/2.
  const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
  const double r1 = qa != 0.0 ? q / qa : -1.0;
  const double r2 = q != 0.0 ? qc / q : -1.0;
  const double theta = (r1 >= 0.0 && r1 <= 1.0) ? r1 : r2;
  return std::min(std::max(theta, 0.0), 1.0);
}

}  // namespace

MarchTotals march_second_order(const StripGrid& grid, const Creepages& creepages,
                               const Flexibilities& flex, const BoundLaw& bound,
                               CellFields* fields) {
  const int nx = grid.nx;
  const bool parabolic = bound.kind == TractionBound::parabolic;
  if (fields) {
    const auto cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(grid.ny);
    fields->nx = nx;
    fields->ny = grid.ny;
    fields->dy = grid.dy;
    fields->dx.assign(static_cast<std::size_t>(grid.ny), 0.0);
    for (auto* v : {&fields->x, &fields->y, &fields->px, &fields->py, &fields->sx, &fields->sy,
                    &fields->work})
      v->assign(cells, 0.0);
    fields->slip.assign(cells, 0);
  }

  MarchTotals totals;
  for (int j = 0; j < grid.ny; ++j) {
    const double xl = grid.x_lead[j];
    const double dx = 2.0 * xl / nx;
    auto bound_at = [&](double t) {
      const double q = std::max(t * (2.0 * xl - t), 0.0);
      return bound.coefficient * (parabolic ? q : std::sqrt(q));
    };
    // Rigid-slip rate: x part constant along the strip, y part linear in x.
    const double rate_x =
        -(creepages.vx * flex.inv_l11 - creepages.phi * grid.y_spin[j] * flex.inv_l13);
    auto rate_y = [&](double x) {
      return -(creepages.vy * flex.inv_l22 + creepages.phi * x * flex.inv_l23);
    };

    Vec p;  // traction at the current node
    Vec e;  // its direction while slipping
    bool slipping = false;
    Vec sum;  // integral of p dt along the strip
    double sum_xpy = 0.0;
    double work = 0.0;
    for (int i = 0; i < nx; ++i) {
      const double t0 = i * dx;
      const double t1 = t0 + dx;
      const double x0 = xl - t0;
      const double g0 = bound_at(t0);
      const double g1 = bound_at(t1);
      const Vec d{rate_x * dx, rate_y(x0 - 0.5 * dx) * dx};  // exact increment over the cell
      const Vec trial = p + d;

      // Integral of the traction over the cell, and of x*py for the moment, by Simpson's rule
      // on each piece: exact for the quadratic traction of adhesion and for the parabolic
      // bound along which a slipping traction runs.
      Vec cell_integral;
      double cell_xpy = 0.0;
      auto add_piece = [&](Vec a, Vec m, Vec b, double ta, double tb) {
        const double h = tb - ta;
        const double tm = 0.5 * (ta + tb);
        cell_integral = cell_integral + (h / 6.0) * (a + 4.0 * m + b);
        cell_xpy += h / 6.0 * ((xl - ta) * a.y + 4.0 * (xl - tm) * m.y + (xl - tb) * b.y);
      };
      // Traction after adhering from (ta, a) over a distance h: the exact rigid-slip integral.
      auto adhere = [&](Vec a, double ta, double h) {
        return a + Vec{rate_x * h, rate_y(xl - ta - 0.5 * h) * h};
      };
      // Directions at the middle and the end of [ta, t1] for a traction slipping from the
      // direction of `from`: a midpoint step of de/dt = (r - (e.r) e)/g.
      struct Slide {
        Vec middle, end;
      };
      auto slide = [&](Vec from, double ta) {
        const double h = t1 - ta;
        const Vec inc = adhere(Vec{}, ta, h);
        const Vec e0 = unit(from, unit(inc, Vec{1.0, 0.0}));
        const double g_quarter = bound_at(ta + 0.25 * h);
        const double g_mid = bound_at(ta + 0.5 * h);
        if (g_mid <= 0.0) return Slide{e0, e0};
        const Vec e_mid = unit(e0 + (0.5 / g_quarter) * normal_part(inc, e0), e0);
        return Slide{e_mid, unit(e0 + (1.0 / g_mid) * normal_part(inc, e_mid), e0)};
      };

      Vec next;
      bool slip_in_cell = false;
      if (norm(trial) <= g1) {
        next = trial;  // adhesion at the end of the cell (again, or still)
        add_piece(p, adhere(p, t0, 0.5 * dx), next, t0, t1);
        slipping = false;
      } else if (!slipping) {
        // Adhesion turns into slip inside the cell: locate the point with the bound taken
        // linear, then refine it by one Newton step on the true bound.
        double theta = crossing_fraction(p, d, g0, g1);
        {
          const double t_c = t0 + theta * dx;
          const Vec q = adhere(p, t0, theta * dx);
          const double g_c = bound_at(t_c);
          const double slope =
              (bound_at(t_c + 1e-3 * dx) - bound_at(t_c - 1e-3 * dx)) / (2e-3 * dx);
          const double f = dot(q, q) - g_c * g_c;
          const double df = 2.0 * dot(q, d) - 2.0 * g_c * slope * dx;
          if (df > 0.0) theta = std::min(std::max(theta - f / df, 0.0), 1.0);
        }
        const double t_c = t0 + theta * dx;
        const Vec at_crossing = adhere(p, t0, theta * dx);
        const Slide turn = slide(at_crossing, t_c);
        next = g1 * turn.end;
        e = turn.end;
        add_piece(p, adhere(p, t0, 0.5 * theta * dx), at_crossing, t0, t_c);
        add_piece(at_crossing, bound_at(0.5 * (t_c + t1)) * turn.middle, next, t_c, t1);
        slipping = slip_in_cell = true;
      } else {
        const Slide turn = slide(e, t0);
        next = g1 * turn.end;
        e = turn.end;
        add_piece(p, bound_at(t0 + 0.5 * dx) * turn.middle, next, t0, t1);
        slip_in_cell = true;
      }

      if (fields) {
        const std::size_t c = static_cast<std::size_t>(j) * nx + i;
        fields->dx[j] = dx;
        fields->x[c] = x0 - 0.5 * dx;
        fields->y[c] = grid.y_at_o[j];
        fields->px[c] = cell_integral.x / dx;
        fields->py[c] = cell_integral.y / dx;
        if (slip_in_cell) {
          // As in Kalker's scheme: the traction the bound removes, over the cell, is the slip.
          const Vec s = (flex.effective / dx) * (next - trial);
          fields->sx[c] = s.x;
          fields->sy[c] = s.y;
          fields->work[c] = norm(next) * norm(s);
          fields->slip[c] = 1;
          work += fields->work[c];
        }
      }
      if (slip_in_cell) ++totals.slip_cells;
      sum = sum + cell_integral;
      sum_xpy += cell_xpy;
      p = next;
    }
    totals.Fx += sum.x;
    totals.Fy += sum.y;
    totals.Mz += sum_xpy - grid.y_at_o[j] * sum.x;
    totals.work += dx * work;
  }
  totals.Fx *= grid.dy;
  totals.Fy *= grid.dy;
  totals.Mz *= grid.dy;
  totals.work *= grid.dy;
  return totals;
}

}  // namespace wheelwear::wear::detail
