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
#include <vector>

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
  const double n2 = dot(a, a);
  return n2 > 0.0 ? (1.0 / std::sqrt(n2)) * a : fallback;
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

namespace {

// The march of one strip, advanced one cell at a time.
struct StripMarch {
  // Strip constants.
  double xl = 0.0, dx = 0.0, rate_x = 0.0, y_at_o = 0.0;
  // State at the current node.
  double g = 0.0;  // bound: zero at the leading edge
  Vec p;           // traction
  Vec e;           // its direction while slipping
  bool slipping = false;
  // Sums along the strip.
  Vec sum;  // integral of p dt
  double sum_xpy = 0.0, work = 0.0;
  int slip_cells = 0;
};

// Where the cell's values go when per-cell fields are wanted.
struct CellOutput {
  Vec mean_traction, slip;
  bool slipping = false;
};

class SecondOrderStepper {
 public:
  SecondOrderStepper(const Creepages& v, const Flexibilities& flex, const BoundLaw& bound)
      : v_(v),
        flex_(flex),
        k_(bound.coefficient),
        parabolic_(bound.kind == TractionBound::parabolic) {}

  // Advances strip `s` over cell i (from node i to node i+1).
  CellOutput advance(StripMarch& s, int i) const {
    const double dx = s.dx;
    const double t0 = i * dx;
    const double t1 = t0 + dx;
    const double g0 = s.g;
    const double g1 = bound_at(s, t1);
    const Vec d = adhere(s, Vec{}, t0, dx);  // exact increment over the cell
    const Vec trial = s.p + d;

    // Integral of the traction over the cell, and of x*py for the moment, by Simpson's rule on
    // each piece: exact for the quadratic traction of adhesion and for the parabolic bound
    // along which a slipping traction runs.
    Vec integral;
    double xpy = 0.0;
    auto add_piece = [&](Vec a, Vec m, Vec b, double ta, double tb) {
      const double h = tb - ta;
      const double tm = 0.5 * (ta + tb);
      integral = integral + (h / 6.0) * (a + 4.0 * m + b);
      xpy += h / 6.0 * ((s.xl - ta) * a.y + 4.0 * (s.xl - tm) * m.y + (s.xl - tb) * b.y);
    };

    Vec next;
    bool slip_in_cell = false;
    if (dot(trial, trial) <= g1 * g1) {
      next = trial;  // adhesion at the end of the cell (again, or still)
      add_piece(s.p, adhere(s, s.p, t0, 0.5 * dx), next, t0, t1);
      s.slipping = false;
    } else if (!s.slipping) {
      // Adhesion turns into slip inside the cell: locate the point with the bound taken
      // linear, then refine it by one Newton step on the true bound.
      double theta = crossing_fraction(s.p, d, g0, g1);
      {
        const Vec q = adhere(s, s.p, t0, theta * dx);
        const double t_c = t0 + theta * dx;
        const double g_c = bound_at(s, t_c);
        const double f = dot(q, q) - g_c * g_c;
        const double df = 2.0 * dot(q, d) - 2.0 * g_c * bound_slope(s, t_c) * dx;
        if (df > 0.0) theta = std::min(std::max(theta - f / df, 0.0), 1.0);
      }
      const double t_c = t0 + theta * dx;
      const Vec at_crossing = adhere(s, s.p, t0, theta * dx);
      const Slide turn = slide(s, at_crossing, t_c, t1);
      next = g1 * turn.end;
      s.e = turn.end;
      add_piece(s.p, adhere(s, s.p, t0, 0.5 * theta * dx), at_crossing, t0, t_c);
      add_piece(at_crossing, turn.g_middle * turn.middle, next, t_c, t1);
      s.slipping = slip_in_cell = true;
    } else {
      const Slide turn = slide(s, s.e, t0, t1);
      next = g1 * turn.end;
      s.e = turn.end;
      add_piece(s.p, turn.g_middle * turn.middle, next, t0, t1);
      slip_in_cell = true;
    }

    CellOutput out{(1.0 / dx) * integral, Vec{}, slip_in_cell};
    if (slip_in_cell) {
      // As in Kalker's scheme: the traction the bound removes, over the cell, is the slip.
      out.slip = (flex_.effective / dx) * (next - trial);
      ++s.slip_cells;
    }
    s.sum = s.sum + integral;
    s.sum_xpy += xpy;
    s.p = next;
    s.g = g1;
    return out;
  }

 private:
  struct Slide {
    Vec middle, end;  // directions
    double g_middle;  // bound at the middle of the sliding piece
  };

  double bound_at(const StripMarch& s, double t) const {
    const double q = std::max(t * (2.0 * s.xl - t), 0.0);
    return k_ * (parabolic_ ? q : std::sqrt(q));
  }
  // d(bound)/dt, for the Newton step on the crossing point.
  double bound_slope(const StripMarch& s, double t) const {
    const double q = t * (2.0 * s.xl - t);
    const double dq = 2.0 * (s.xl - t);
    if (parabolic_) return k_ * dq;
    return q > 0.0 ? k_ * 0.5 * dq / std::sqrt(q) : 0.0;
  }
  // Traction after adhering from (ta, a) over a distance h: the exact rigid-slip integral
  // (the x rate is constant along a strip, the y rate linear in x).
  Vec adhere(const StripMarch& s, Vec a, double ta, double h) const {
    const double x_mid = s.xl - ta - 0.5 * h;
    return a + Vec{s.rate_x * h, -(v_.vy * flex_.inv_l22 + v_.phi * x_mid * flex_.inv_l23) * h};
  }
  // Directions at the middle and the end of [ta, tb] for a traction slipping from the
  // direction of `from`: a midpoint step of de/dt = (r - (e.r) e)/g.
  Slide slide(const StripMarch& s, Vec from, double ta, double tb) const {
    const double h = tb - ta;
    const Vec inc = adhere(s, Vec{}, ta, h);
    // A traction starting from zero (the leading edge) slides along its increment.
    const Vec e0 = dot(from, from) > 0.0 ? unit(from, from) : unit(inc, Vec{1.0, 0.0});
    const double g_quarter = bound_at(s, ta + 0.25 * h);
    const double g_mid = bound_at(s, ta + 0.5 * h);
    if (g_mid <= 0.0) return Slide{e0, e0, 0.0};
    const Vec e_mid = unit(e0 + (0.5 / g_quarter) * normal_part(inc, e0), e0);
    return Slide{e_mid, unit(e0 + (1.0 / g_mid) * normal_part(inc, e_mid), e0), g_mid};
  }

  Creepages v_;
  Flexibilities flex_;
  double k_;
  bool parabolic_;
};

}  // namespace

MarchTotals march_second_order(const StripGrid& grid, const Creepages& creepages,
                               const Flexibilities& flex, const BoundLaw& bound,
                               CellFields* fields) {
  const int nx = grid.nx;
  const int ny = grid.ny;
  if (fields) prepare_fields(*fields, nx, ny, grid.dy);

  thread_local std::vector<StripMarch> strips;
  strips.assign(static_cast<std::size_t>(ny), StripMarch{});
  for (int j = 0; j < ny; ++j) {
    StripMarch& s = strips[j];
    s.xl = grid.x_lead[j];
    s.dx = 2.0 * s.xl / nx;
    s.rate_x = px_rate(creepages, flex, grid.y_spin[j]);
    s.y_at_o = grid.y_at_o[j];
    if (fields) fields->dx[j] = s.dx;
  }

  // Cells of neighbouring strips are independent: advancing all strips by one cell before the
  // next lets the processor overlap their dependency chains (square roots and divisions).
  const SecondOrderStepper stepper(creepages, flex, bound);
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      StripMarch& s = strips[j];
      const CellOutput cell = stepper.advance(s, i);
      if (!fields) continue;
      const std::size_t c = static_cast<std::size_t>(j) * nx + i;
      fields->x[c] = s.xl - (i + 0.5) * s.dx;
      fields->y[c] = s.y_at_o;
      fields->px[c] = cell.mean_traction.x;
      fields->py[c] = cell.mean_traction.y;
      if (cell.slipping) {
        fields->sx[c] = cell.slip.x;
        fields->sy[c] = cell.slip.y;
        fields->work[c] = norm(cell.mean_traction) * norm(cell.slip);
        fields->slip[c] = 1;
        s.work += fields->work[c];
      }
    }
  }

  MarchTotals totals;
  for (const StripMarch& s : strips) {
    totals.Fx += s.sum.x;
    totals.Fy += s.sum.y;
    totals.Mz += s.sum_xpy - s.y_at_o * s.sum.x;
    totals.work += s.dx * s.work;
    totals.slip_cells += s.slip_cells;
  }
  totals.scale_by_strip_width(grid.dy);
  return totals;
}

}  // namespace wheelwear::wear::detail
