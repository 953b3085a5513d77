#include "fastsim_kernel.hpp"

#include <algorithm>
#include <cmath>

namespace wheelwear::wear::detail {

namespace {

// Per-strip arrays of the marches, kept per thread so that a call allocates nothing once the
// grid size has been seen.
struct Scratch {
  std::vector<double> dx, step_x, step_y, step_y_change, t, px, py, sum_px, sum_py, sum_xpy, slips,
      work;
  void resize(int n) {
    for (auto* v : {&dx, &step_x, &step_y, &step_y_change, &t, &px, &py, &sum_px, &sum_py, &sum_xpy,
                    &slips, &work})
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
    for (int j = 0; j < ny; ++j) {
      px[j] += step_x[j];
      py[j] += step_y[j];
      step_y[j] += step_y_change[j];
      t[j] += dx[j];  // distance of the node from the leading edge
      // x_l^2 - x^2 at the node; rounding can make it slightly negative at the trailing edge.
      const double g = bound_at(std::max(t[j] * (2.0 * xl[j] - t[j]), 0.0));
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

MarchTotals march_with_fields(const StripGrid& grid, const Creepages& creepages,
                              const Flexibilities& flex, const BoundLaw& bound,
                              CellFields& fields) {
  const int nx = grid.nx;
  const int ny = grid.ny;
  prepare_fields(fields, nx, ny, grid.dy);
  thread_local Scratch scratch;
  scratch.resize(ny);
  double* __restrict px = scratch.px.data();
  double* __restrict py = scratch.py.data();
  double* __restrict sum_px = scratch.sum_px.data();
  double* __restrict sum_py = scratch.sum_py.data();
  double* __restrict sum_xpy = scratch.sum_xpy.data();
  double* __restrict work = scratch.work.data();
  double* __restrict p_mag = scratch.t.data();  // |p| at each strip's current node
  double* __restrict step_x = scratch.step_x.data();
  double* __restrict dx = scratch.dx.data();
  for (int j = 0; j < ny; ++j) {
    dx[j] = 2.0 * grid.x_lead[j] / nx;
    fields.dx[j] = dx[j];
    step_x[j] = dx[j] * px_rate(creepages, flex, grid.y_spin[j]);
  }

  // Cell by cell across a block of strips: the strips' chains are independent, so the
  // processor overlaps them (the saturation is branch-free), while the block keeps the rows
  // being written few enough to stay in the L1 cache.
  const bool parabolic = bound.kind == TractionBound::parabolic;
  constexpr int kBlock = 8;
  for (int j0 = 0; j0 < ny; j0 += kBlock) {
    const int j1 = std::min(ny, j0 + kBlock);
    for (int i = 0; i < nx; ++i) {
      for (int j = j0; j < j1; ++j) {
        const double xl = grid.x_lead[j];
        const double t = (i + 1) * dx[j];
        const double x_node = xl - t;
        const double x_mid = x_node + 0.5 * dx[j];
        const double trial_x = px[j] + step_x[j];
        const double trial_y =
            py[j] - dx[j] * (creepages.vy * flex.inv_l22 + creepages.phi * x_mid * flex.inv_l23);
        const double q = std::max(t * (2.0 * xl - t), 0.0);
        const double g = bound.coefficient * (parabolic ? q : std::sqrt(q));
        // One square root per cell: |p_trial| gives the bound ratio, the end traction's
        // magnitude (carried to the next cell as its start) and the slip's magnitude.
        const double trial_norm =
            std::sqrt(std::max(trial_x * trial_x + trial_y * trial_y, 1e-300));
        const double ratio = g / trial_norm;
        const double scale = std::min(1.0, ratio);
        const double p_start = p_mag[j];
        p_mag[j] = scale * trial_norm;
        px[j] = trial_x * scale;
        py[j] = trial_y * scale;
        // Simplified theory u = L p: the part of the trial traction the bound removes is the
        // elastic displacement released by slip over this cell, s = L (p - p_trial)/dx, and
        // p - p_trial = (scale - 1) p_trial keeps s exactly opposite to p. The work over the
        // cell takes the traction's mean over it (start and end nodes), which integrates the
        // work to second order; the end node alone underestimates it by O(1/nx) (-11 % at
        // 50). Adhering cells get (scale - 1) = 0: no slip, no work.
        const double release = flex.effective * (scale - 1.0) / dx[j];
        const std::size_t c = static_cast<std::size_t>(j) * nx + i;
        fields.x[c] = x_mid;
        fields.y[c] = grid.y_at_o[j];
        fields.px[c] = px[j];
        fields.py[c] = py[j];
        fields.sx[c] = release * trial_x;
        fields.sy[c] = release * trial_y;
        fields.work[c] = -release * trial_norm * 0.5 * (p_start + p_mag[j]);
        fields.slip[c] = (ratio < 1.0 && trial_norm > 1e-150) ? 1 : 0;
        work[j] += fields.work[c];
        sum_px[j] += px[j];
        sum_py[j] += py[j];
        sum_xpy[j] += x_node * py[j];
      }
    }
  }

  MarchTotals totals;
  for (int j = 0; j < ny; ++j) {
    totals.Fx += dx[j] * sum_px[j];
    totals.Fy += dx[j] * sum_py[j];
    totals.Mz += dx[j] * (sum_xpy[j] - grid.y_at_o[j] * sum_px[j]);
    totals.work += dx[j] * work[j];
  }
  for (const std::uint8_t slipping : fields.slip) totals.slip_cells += slipping;
  totals.scale_by_strip_width(grid.dy);
  return totals;
}

void prepare_fields(CellFields& fields, int nx, int ny, double dy) {
  const auto cells = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  fields.nx = nx;
  fields.ny = ny;
  fields.dy = dy;
  fields.dx.assign(static_cast<std::size_t>(ny), 0.0);
  for (auto* v :
       {&fields.x, &fields.y, &fields.px, &fields.py, &fields.sx, &fields.sy, &fields.work})
    v->assign(cells, 0.0);
  fields.slip.assign(cells, 0);
}

}  // namespace wheelwear::wear::detail
