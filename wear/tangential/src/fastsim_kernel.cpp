#include "fastsim_kernel.hpp"

#include <algorithm>
#include <cmath>

namespace wheelwear::tangential::detail {

namespace {

// Per-strip arrays of the marches, kept per thread so that a call allocates nothing once the
// grid size has been seen.
struct Scratch {
  std::vector<double> dx, step_x, step_y, step_y_change, t, px, py, sum_px, sum_py, sum_xpy, slips;
  void resize(int n) {
    for (auto* v :
         {&dx, &step_x, &step_y, &step_y_change, &t, &px, &py, &sum_px, &sum_py, &sum_xpy, &slips})
      v->assign(static_cast<std::size_t>(n), 0.0);
  }
};

// Bound over traction magnitude, g/|p|: the cell slips when it is below 1, and
// min(1, g/|p|) is the factor that puts the traction on the bound (branch-free, so the strip
// loop vectorises). The floor on |p|^2 keeps 0/0 out.
inline double bound_ratio(double px, double py, double g) {
  return g / std::sqrt(std::max(px * px + py * py, 1e-300));
}

// Advances all strips cell by cell; the arrays are distinct (restrict), which lets the
// compiler vectorise the loop over strips.
template <class BoundAt>
void advance_all_strips(BoundAt bound_at, int nx, int ny, const double* __restrict xl,
                        const double* __restrict dx, const double* __restrict step_x,
                        double* __restrict step_y, const double* __restrict step_y_change,
                        double* __restrict t, double* __restrict px, double* __restrict py,
                        double* __restrict sum_px, double* __restrict sum_py,
                        double* __restrict sum_xpy, double* __restrict slips) {
  for (int i = 0; i < nx; ++i) {
    const double cells_left = nx - 1.0 - i;  // between the node and the trailing edge
    for (int j = 0; j < ny; ++j) {
      px[j] += step_x[j];
      py[j] += step_y[j];
      step_y[j] += step_y_change[j];
      t[j] += dx[j];  // distance of the node from the leading edge
      // x_l^2 - x^2 = t (2 x_l - t) at the node, with 2 x_l - t counted in cells: exactly 0 at
      // the trailing edge. (From 2 x_l - t, rounding left up to 1e-16 x_l^2 there, whose
      // square root under the semi-elliptic bound let the trailing node keep its traction in
      // some strips: up to 3e-3 of the force in the linear limit.)
      const double g = bound_at(t[j] * (cells_left * dx[j]));
      const double p2 = px[j] * px[j] + py[j] * py[j];
      const double ratio = bound_ratio(px[j], py[j], g);
      const double scale = std::min(1.0, ratio);
      px[j] *= scale;
      py[j] *= scale;
      slips[j] += (ratio < 1.0 && p2 > 0.0) ? 1.0 : 0.0;  // a zero traction does not slip
      sum_px[j] += px[j];
      sum_py[j] += py[j];
      sum_xpy[j] += (xl[j] - t[j]) * py[j];
    }
  }
}

}  // namespace

// Layout: the inner loop runs across strips, so each iteration advances all strips by one
// cell with the same instruction sequence; the compiler vectorises it (every strip has nx
// cells, only their length dx differs). Per strip the px increment is constant and the py
// increment changes linearly along x, so both are updated by additions only.
MarchTotals march(const StripGrid& grid, const Creepages& creepages, const Flexibilities& flex,
                  const BoundLaw& bound) {
  thread_local Scratch scratch;
  const int ny = grid.ny;
  scratch.resize(ny);
  double* __restrict dx = scratch.dx.data();
  double* __restrict step_x = scratch.step_x.data();
  double* __restrict step_y = scratch.step_y.data();
  double* __restrict step_y_change = scratch.step_y_change.data();
  double* __restrict t = scratch.t.data();
  double* __restrict px = scratch.px.data();
  double* __restrict py = scratch.py.data();
  double* __restrict sum_px = scratch.sum_px.data();
  double* __restrict sum_py = scratch.sum_py.data();
  double* __restrict sum_xpy = scratch.sum_xpy.data();
  double* __restrict slips = scratch.slips.data();
  const double* __restrict xl = grid.x_lead.data();

  const double inv_nx = 1.0 / grid.nx;
  for (int j = 0; j < ny; ++j) {
    dx[j] = 2.0 * xl[j] * inv_nx;
    // Exact increments of Eq. 15 over one cell: the py slope is evaluated at the cell's
    // mid-point, where it equals the cell average.
    step_x[j] = dx[j] * px_rate(creepages, flex, grid.y_spin[j]);
    step_y[j] = -dx[j] * (creepages.vy * flex.inv_l22 +
                          creepages.phi * (xl[j] - 0.5 * dx[j]) * flex.inv_l23);
    step_y_change[j] = dx[j] * dx[j] * creepages.phi * flex.inv_l23;
  }

  const double k = bound.coefficient;
  if (bound.kind == TractionBound::parabolic) {
    advance_all_strips([k](double q) { return k * q; }, grid.nx, ny, xl, dx, step_x, step_y,
                       step_y_change, t, px, py, sum_px, sum_py, sum_xpy, slips);
  } else {
    advance_all_strips([k](double q) { return k * std::sqrt(q); }, grid.nx, ny, xl, dx, step_x,
                       step_y, step_y_change, t, px, py, sum_px, sum_py, sum_xpy, slips);
  }

  MarchTotals totals;
  double slip_count = 0.0;
  for (int j = 0; j < ny; ++j) {
    totals.Fx += dx[j] * sum_px[j];
    totals.Fy += dx[j] * sum_py[j];
    totals.Mz += dx[j] * (sum_xpy[j] - grid.y_at_o[j] * sum_px[j]);
    slip_count += slips[j];
  }
  totals.scale_by_strip_width(grid.dy);
  totals.slip_cells = static_cast<int>(slip_count);
  return totals;
}

void prepare_fields(CellFields& fields, int nx, int ny, double dy, bool zero, CellFieldSet set) {
  const auto cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  fields.nx = nx;
  fields.ny = ny;
  fields.dy = dy;
  fields.dx.resize(static_cast<std::size_t>(ny));
  fields.strip_y.resize(static_cast<std::size_t>(ny));
  const bool all = set == CellFieldSet::all;
  for (auto* v : {&fields.x, &fields.y, &fields.px, &fields.py, &fields.sx, &fields.sy,
                  &fields.slip_norm, &fields.work, &fields.pressure}) {
    const bool wanted = all || v == &fields.slip_norm || v == &fields.work || v == &fields.pressure;
    if (!wanted) {
      v->clear();  // keeps the storage for a later request of all fields
    } else if (zero) {
      v->assign(cells, 0.0);
    } else {
      v->resize(cells);
    }
  }
  if (!all) {
    fields.slip.clear();
  } else if (zero) {
    fields.slip.assign(cells, 0);
  } else {
    fields.slip.resize(cells);
  }
}

}  // namespace wheelwear::tangential::detail
