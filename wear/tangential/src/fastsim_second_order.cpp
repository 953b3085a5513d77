// Second-order marching of the simplified theory along each strip.
//
// Along a strip the marching distance t = x_l - x runs from the leading edge (t = 0) to the
// trailing edge (t = 2 x_l). Where the surfaces adhere the traction follows the rigid slip,
// dp/dt = r(t); where they slip it lies on the bound, p = g(t) e, and its direction turns
// with the part of r normal to it, de/dt = (r - (e.r) e)/g. Kalker's FASTSIM advances both
// with one explicit step per cell and gives each cell its trailing node's traction, which is
// first-order accurate. Here the point where adhesion turns into slip is located inside the
// cell, the direction in slip follows the exact solution of its equation over each step (with
// the rigid slip and the bound at the step's middle), and the traction is integrated by
// Simpson's rule on each piece; a cell whose adhering traction leaves the bound between its
// ends is halved.

#include <algorithm>
#include <cmath>
#include <vector>

#include "fastsim_kernel.hpp"

namespace wheelwear::tangential::detail {

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
  SecondOrderStepper(const Creepages& v, const Flexibilities& flex, const BoundLaw& bound, int nx)
      : nx_(nx),
        v_(v),
        flex_(flex),
        k_(bound.coefficient),
        parabolic_(bound.kind == TractionBound::parabolic) {}

  // Advances strip `s` over cell i (from node i to node i+1).
  CellOutput advance(StripMarch& s, int i) const {
    const double dx = s.dx;
    const double t0 = i * dx;
    // The last node exactly on the trailing edge, where the bound vanishes (t0 + dx may miss
    // it by a rounding, which the semi-elliptic bound's square root magnifies).
    const double t1 = i + 1 == nx_ ? 2.0 * s.xl : t0 + dx;
    const Vec trial = s.p + adhere(s, Vec{}, t0, dx);  // the cell's adhering end traction
    Piece piece;
    advance_piece(s, t0, t1, 0, piece);
    // A strip of zero length (x_l = 0) has no traction: no 0/0 in its cell averages.
    const double inv_dx = dx > 0.0 ? 1.0 / dx : 0.0;
    CellOutput out{inv_dx * piece.integral, Vec{}, piece.slipped};
    if (piece.slipped) {
      // As in Kalker's scheme: the traction the bound removes, over the cell, is the slip.
      out.slip = (flex_.effective * inv_dx) * (s.p - trial);
      ++s.slip_cells;
    }
    s.sum = s.sum + piece.integral;
    s.sum_xpy += piece.xpy;
    return out;
  }

 private:
  // Integrals over a cell or a part of it, and whether the traction slipped there.
  struct Piece {
    Vec integral;  // of the traction over t
    double xpy = 0.0;
    bool slipped = false;
  };
  // Halvings of a cell at most, where the adhering traction leaves the bound inside it.
  static constexpr int kMaxDepth = 6;

  // Advances strip `s` from t0 to t1, adding to `piece`. Where the adhering
  // traction is within the bound at the end but not at the middle (the rigid slip turns
  // within the piece, as under spin next to the line where it changes sign), the check at the
  // ends alone would let Simpson's rule integrate a traction far beyond the bound (up to 28
  // mu N on a single cell under pure spin): the piece is then halved.
  void advance_piece(StripMarch& s, double t0, double t1, int depth, Piece& piece) const {
    const double h = t1 - t0;
    const double g0 = s.g;
    const double g1 = bound_at(s, t1);
    const Vec d = adhere(s, Vec{}, t0, h);  // exact increment over the piece
    const Vec trial = s.p + d;
    const Vec middle = adhere(s, s.p, t0, 0.5 * h);
    const double g_middle = bound_at(s, t0 + 0.5 * h);
    const bool end_inside = dot(trial, trial) <= g1 * g1;
    if (end_inside && dot(middle, middle) > g_middle * g_middle && depth < kMaxDepth) {
      split_piece(s, t0, t1, depth, piece);
      return;
    }

    // Integral of the traction over the piece, and of x*py for the moment, by Simpson's rule
    // on each part: exact for the quadratic traction of adhesion and for the parabolic bound
    // along which a slipping traction runs.
    auto add = [&](Vec a, Vec m, Vec b, double ta, double tb) {
      const double w = tb - ta;
      const double tm = 0.5 * (ta + tb);
      piece.integral = piece.integral + (w / 6.0) * (a + 4.0 * m + b);
      piece.xpy += w / 6.0 * ((s.xl - ta) * a.y + 4.0 * (s.xl - tm) * m.y + (s.xl - tb) * b.y);
    };

    Vec next;
    if (end_inside) {
      next = trial;  // adhesion at the end of the piece (again, or still)
      add(s.p, middle, next, t0, t1);
      s.slipping = false;
    } else if (!s.slipping) {
      // Adhesion turns into slip inside the piece: locate the point with the bound taken
      // linear, then solve |q(theta)| = g(theta) on the true bound.
      const double theta = crossing_on_bound(s, d, t0, h, crossing_fraction(s.p, d, g0, g1));
      const double t_c = t0 + theta * h;
      const Vec at_crossing = adhere(s, s.p, t0, theta * h);
      const Slide turn = slide(s, at_crossing, t_c, t1);
      next = g1 * turn.end;
      s.e = turn.end;
      add(s.p, adhere(s, s.p, t0, 0.5 * theta * h), at_crossing, t0, t_c);
      // The sliding part starts on the bound, which the crossing reaches to the root's
      // tolerance (from far above it, at_crossing would weigh in Simpson's sum unbounded).
      const double g_c = bound_at(s, t_c);
      const double size = norm(at_crossing);
      const Vec on_bound = size > g_c && size > 0.0 ? (g_c / size) * at_crossing : at_crossing;
      add(on_bound, turn.g_middle * turn.middle, next, t_c, t1);
      s.slipping = piece.slipped = true;
    } else {
      const Slide turn = slide(s, s.e, t0, t1);
      next = g1 * turn.end;
      s.e = turn.end;
      add(s.p, turn.g_middle * turn.middle, next, t0, t1);
      piece.slipped = true;
    }
    s.p = next;
    s.g = g1;
  }

  // The piece [t0, t1] as two halves: out of line, so that the common path stays inlined in
  // the march over strips, whose independent chains the processor then overlaps.
  [[gnu::noinline]] void split_piece(StripMarch& s, double t0, double t1, int depth,
                                     Piece& piece) const {
    const double t_half = 0.5 * (t0 + t1);
    advance_piece(s, t0, t_half, depth + 1, piece);
    advance_piece(s, t_half, t1, depth + 1, piece);
  }

  struct Slide {
    Vec middle, end;  // directions
    double g_middle;  // bound at the middle of the sliding piece
  };

  double bound_at(const StripMarch& s, double t) const {
    const double q = std::max(t * (2.0 * s.xl - t), 0.0);
    return k_ * (parabolic_ ? q : std::sqrt(q));
  }
  // The root of f(theta) = |q(theta)|^2 - g(t0 + theta h)^2 in [0, 1], q the traction
  // adhering from the start of the piece of length h, by Newton's method from `theta` kept inside
  // the bracket [lo, hi] (f(0) <= 0 < f(1)) with bisection where a step would leave it. A lone
  // Newton step fails where the bound's slope term vanishes: at the trailing edge g -> 0, df
  // shrinks to 2 q.d, and a traction far below the bound there (tiny creepage) sent the step to
  // theta = 0, putting the whole last cell on the bound (|F| up to 1e5 times too large at creepages
  // below 1e-10). The converged root is also continuous in the inputs.
  double crossing_on_bound(const StripMarch& s, Vec d, double t0, double h, double theta) const {
    double lo = 0.0, hi = 1.0;
    for (int iteration = 0; iteration < 60; ++iteration) {
      const Vec q = adhere(s, s.p, t0, theta * h);
      const double t_c = t0 + theta * h;
      const double g_c = bound_at(s, t_c);
      const double f = dot(q, q) - g_c * g_c;
      if (f > 0.0) {
        hi = theta;
      } else {
        lo = theta;
      }
      const double df = 2.0 * dot(q, d) - 2.0 * g_c * bound_slope(s, t_c) * h;
      double next = df > 0.0 ? theta - f / df : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      // Relative tolerances (at large creepage the root lies at theta ~ 1e-16 and below);
      // Newton's convergence is quadratic, so a step of 1e-9 leaves an error near 1e-18.
      if (std::abs(next - theta) <= 1e-9 * next || hi - lo <= 1e-12 * hi) return next;
      theta = next;
    }
    return theta;
  }
  // d(bound)/dt, for the Newton steps on the crossing point.
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
  // direction of `from`, under de/dt = (r - (e.r) e)/g with the rigid-slip rate r and the bound
  // g held at their values in the middle of each step. For constant r and g the angle theta
  // from r to e obeys d theta/dt = -(|r|/g) sin theta, solved exactly by
  // tan(theta/2) = tan(theta_0/2) exp(-|r| t/g) (relax()). An explicit step of the equation
  // overshoots once |r| dt > g (low friction, large creepage, near the trailing edge): the
  // direction then jumped by up to 90 degrees on a change of 1e-20 in the spin.
  Slide slide(const StripMarch& s, Vec from, double ta, double tb) const {
    const double h = tb - ta;
    const Vec inc = adhere(s, Vec{}, ta, h);
    // A traction starting from zero (the leading edge) slides along its increment.
    const Vec e0 = dot(from, from) > 0.0 ? unit(from, from) : unit(inc, Vec{1.0, 0.0});
    const double g_quarter = bound_at(s, ta + 0.25 * h);
    const double g_mid = bound_at(s, ta + 0.5 * h);
    if (g_mid <= 0.0) return Slide{e0, e0, 0.0};
    const double size = norm(inc);
    if (size == 0.0) return Slide{e0, e0, g_mid};
    const Vec u = (1.0 / size) * inc;
    const Vec e_mid = relax(e0, u, 0.5 * size / g_quarter);
    return Slide{e_mid, relax(e0, u, size / g_mid), g_mid};
  }
  // e turned towards the unit vector u of the rigid slip by lambda = |r| dt / g: the solution
  // above, without trigonometric functions. In the frame of u, w = (1 + cos theta, sin theta)
  // or (sin theta, 1 - cos theta) (whichever is far from zero) points along
  // +-(cos theta/2, sin theta/2); scaling its second component by exp(-lambda) turns the half
  // angle as the solution does, and doubling the angle (where the sign of w drops out) gives
  // the new direction. At theta = pi exactly (an unstable equilibrium) e stays. (A Pade
  // approximant of the exponential, cheaper, cost the scheme its accuracy at 25 cells:
  // 1.6e-3 instead of 1e-3 of mu N on the pure-spin references.)
  static Vec relax(Vec e, Vec u, double lambda) {
    const double c = dot(u, e), sn = u.x * e.y - u.y * e.x;
    const double wx = c >= 0.0 ? 1.0 + c : sn;
    const double wy = (c >= 0.0 ? sn : 1.0 - c) * std::exp(-lambda);
    const double inv_w2 = 1.0 / (wx * wx + wy * wy);
    const double cos_turned = (wx * wx - wy * wy) * inv_w2, sin_turned = 2.0 * wx * wy * inv_w2;
    return Vec{cos_turned * u.x - sin_turned * u.y, sin_turned * u.x + cos_turned * u.y};
  }

  int nx_;  // cells per strip
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
  if (fields) prepare_fields(*fields, nx, ny, grid.dy, /*zero=*/true, CellFieldSet::all);

  thread_local std::vector<StripMarch> strips;
  strips.assign(static_cast<std::size_t>(ny), StripMarch{});
  for (int j = 0; j < ny; ++j) {
    StripMarch& s = strips[j];
    s.xl = grid.x_lead[j];
    s.dx = 2.0 * s.xl / nx;
    s.rate_x = px_rate(creepages, flex, grid.y_spin[j]);
    s.y_at_o = grid.y_at_o[j];
    if (fields) {
      fields->dx[j] = s.dx;
      fields->strip_y[j] = s.y_at_o;
    }
  }

  // Cells of neighbouring strips are independent: advancing all strips by one cell before the
  // next lets the processor overlap their dependency chains (square roots and divisions).
  const SecondOrderStepper stepper(creepages, flex, bound, nx);
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
        fields->slip_norm[c] = norm(cell.slip);
        fields->work[c] = norm(cell.mean_traction) * fields->slip_norm[c];
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

}  // namespace wheelwear::tangential::detail
