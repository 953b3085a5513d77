// Kalker's FASTSIM march with per-cell fields, vectorised across strips.
//
// The march along a strip is a recurrence (each cell starts from the previous cell's
// traction), so the parallelism lies across strips: all strips advance by one cell with the
// same instruction sequence, one strip per SIMD lane and many independent lanes in flight (the
// saturation is branch-free). Their cells go to small cell-major buffers, which stay in the L1
// cache; every kChunk cells these are copied, strip by strip, into the strip-major CellFields.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "fastsim_kernel.hpp"

namespace wheelwear::tangential::detail {

namespace {

constexpr int kLanes = 8;  // strips are padded to a multiple of this: one AVX-512 register
constexpr int kChunk = 8;  // cells per strip marched before their fields are copied out

// Per-strip state and constants of the march, and the cell-major chunk buffers (value of cell
// i0 + ci of strip j at [ci * stride + j]), kept per thread: no allocation once the grid size
// has been seen.
struct Scratch {
  int nx = 0;
  int stride = 0;  // strips rounded up to a multiple of kLanes
  std::vector<double> xl, dx, step_x, release_scale, px, py, p_mag, sum_px, sum_py, sum_xpy,
      sum_work, slips;
  std::vector<double> out_px, out_py, out_sx, out_sy, out_snorm, out_work, out_slip;
  void resize(int ny) {
    stride = (ny + kLanes - 1) / kLanes * kLanes;
    const auto n = static_cast<std::size_t>(stride);
    for (auto* v : {&xl, &dx, &step_x, &release_scale, &px, &py, &p_mag, &sum_px, &sum_py, &sum_xpy,
                    &sum_work, &slips})
      v->assign(n, 0.0);
    for (auto* v : {&out_px, &out_py, &out_sx, &out_sy, &out_snorm, &out_work, &out_slip})
      v->resize(n * kChunk);
  }
};

// Advances every strip over cell i, writing the cell's fields to row ci of the chunk buffers:
// all of them when kAll, else only the slip's magnitude and the work. The arithmetic per cell is
// that of Kalker's scheme (see march() for the increments): trial traction, one square root for its
// magnitude, the scale that puts it on the bound, and from the removed part the slip and the work
// over the cell with the traction's mean over it.
template <bool kAll, class BoundAt>
void advance_cell(BoundAt bound_at, int i, int ci, double rate_y, double rate_y_spin, Scratch& s) {
  const int n = s.stride;
  const double nodes = i + 1.0;  // the cell's trailing node, counted from the leading edge
  const double cells_left = s.nx - nodes;  // between that node and the trailing edge
  const std::size_t row = static_cast<std::size_t>(ci) * n;
  const double* __restrict xl = s.xl.data();
  const double* __restrict dx = s.dx.data();
  const double* __restrict step_x = s.step_x.data();
  const double* __restrict release_scale = s.release_scale.data();
  double* __restrict px = s.px.data();
  double* __restrict py = s.py.data();
  double* __restrict p_mag = s.p_mag.data();
  double* __restrict sum_px = s.sum_px.data();
  double* __restrict sum_py = s.sum_py.data();
  double* __restrict sum_xpy = s.sum_xpy.data();
  double* __restrict sum_work = s.sum_work.data();
  double* __restrict slips = s.slips.data();
  double* __restrict o_px = s.out_px.data() + row;
  double* __restrict o_py = s.out_py.data() + row;
  double* __restrict o_sx = s.out_sx.data() + row;
  double* __restrict o_sy = s.out_sy.data() + row;
  double* __restrict o_snorm = s.out_snorm.data() + row;
  double* __restrict o_work = s.out_work.data() + row;
  double* __restrict o_slip = s.out_slip.data() + row;
#pragma GCC ivdep
  for (int j = 0; j < n; ++j) {
    const double t = nodes * dx[j];
    const double x_node = xl[j] - t;
    const double x_mid = x_node + 0.5 * dx[j];
    const double trial_x = px[j] + step_x[j];
    const double trial_y = py[j] - dx[j] * (rate_y + x_mid * rate_y_spin);
    // x_l^2 - x^2 = t (2 x_l - t) at the node, 2 x_l - t counted in cells: exactly 0 at the
    // trailing edge (see march()).
    const double g = bound_at(t * (cells_left * dx[j]));
    // One square root per cell: |p_trial| gives the bound ratio, the end traction's magnitude
    // (carried to the next cell as its start) and the slip's magnitude.
    // The floor keeps 0/0 out of the ratio; the magnitude itself stays exact, so that a zero
    // traction carries no slip and no work.
    const double trial_norm = std::sqrt(trial_x * trial_x + trial_y * trial_y);
    const double ratio = g / std::max(trial_norm, 1e-150);
    const double scale = std::min(1.0, ratio);
    const double p_start = p_mag[j];
    p_mag[j] = scale * trial_norm;
    px[j] = trial_x * scale;
    py[j] = trial_y * scale;
    // Simplified theory u = L p: the part of the trial traction the bound removes is the
    // elastic displacement released by slip over this cell, s = L (p - p_trial)/dx, and
    // p - p_trial = (scale - 1) p_trial keeps s exactly opposite to p. The work over the
    // cell takes the traction's mean over it (start and end nodes), which integrates the
    // work to second order; the end node alone underestimates it by O(1/nx) (-11 % at 50).
    // Adhering cells get (scale - 1) = 0: no slip, no work.
    const double release = release_scale[j] * (scale - 1.0);
    const double work = -release * trial_norm * 0.5 * (p_start + p_mag[j]);
    const double slipping = (ratio < 1.0 && trial_norm > 1e-150) ? 1.0 : 0.0;
    o_snorm[j] = -release * trial_norm;
    o_work[j] = work;
    if constexpr (kAll) {
      o_px[j] = px[j];
      o_py[j] = py[j];
      o_sx[j] = release * trial_x;
      o_sy[j] = release * trial_y;
      o_slip[j] = slipping;
    }
    sum_work[j] += work;
    slips[j] += slipping;
    sum_px[j] += px[j];
    sum_py[j] += py[j];
    sum_xpy[j] += x_node * py[j];
  }
}

// Cells of strip j in the first `cells` rows of a chunk buffer into its strip-major row.
inline void copy_strip(const double* __restrict from, int stride, int j, int cells,
                       double* __restrict to) {
  for (int ci = 0; ci < cells; ++ci) to[ci] = from[static_cast<std::size_t>(ci) * stride + j];
}

// Eight doubles as one vector of the GCC/Clang vector extension (one AVX-512 register; the
// compiler splits it where the target has narrower registers).
using Vec8 = double __attribute__((vector_size(64)));
using Bytes8 = std::uint8_t __attribute__((vector_size(8)));
static_assert(kLanes == 8 && kChunk == 8, "the transpose below is 8 x 8");

inline Vec8 load8(const double* p) {
  Vec8 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Transposes the 8 x 8 block r (r[ci][l]: cell ci of strip l) in place into r[l][ci], by
// interleaving pairs, then pairs of pairs, then halves.
inline void transpose8(Vec8 (&r)[8]) {
  Vec8 t[8], u[8];
  for (int k = 0; k < 8; k += 2) {
    t[k] = __builtin_shufflevector(r[k], r[k + 1], 0, 8, 2, 10, 4, 12, 6, 14);
    t[k + 1] = __builtin_shufflevector(r[k], r[k + 1], 1, 9, 3, 11, 5, 13, 7, 15);
  }
  for (int k = 0; k < 8; k += 4) {
    for (int h = 0; h < 2; ++h) {
      u[k + h] = __builtin_shufflevector(t[k + h], t[k + h + 2], 0, 1, 8, 9, 4, 5, 12, 13);
      u[k + h + 2] = __builtin_shufflevector(t[k + h], t[k + h + 2], 2, 3, 10, 11, 6, 7, 14, 15);
    }
  }
  for (int h = 0; h < 4; ++h) {
    r[h] = __builtin_shufflevector(u[h], u[h + 4], 0, 1, 2, 3, 8, 9, 10, 11);
    r[h + 4] = __builtin_shufflevector(u[h], u[h + 4], 4, 5, 6, 7, 12, 13, 14, 15);
  }
}

// The 8 cells of strips j0 ... j0+7 of a full chunk buffer into their strip-major rows, which
// start at to + l*nx for strip j0 + l.
inline void copy_block(const double* from, int stride, int j0, double* to, int nx) {
  Vec8 r[8];
  for (int ci = 0; ci < 8; ++ci) r[ci] = load8(from + static_cast<std::size_t>(ci) * stride + j0);
  transpose8(r);
  for (int l = 0; l < 8; ++l)
    std::memcpy(to + static_cast<std::size_t>(l) * nx, &r[l], sizeof r[l]);
}

// The chunk of `cells` cells starting at cell i0 from the chunk buffers into the strip-major
// fields: 8 x 8 transposes where a block of 8 strips has a full chunk, cell by cell at the ends.
template <bool kAll>
void copy_chunk(const Scratch& s, int i0, int cells, CellFields& fields) {
  const int nx = fields.nx;
  const int ny = fields.ny;
  int j_done = 0;
  if (cells == kChunk) {
    for (; j_done + kLanes <= ny; j_done += kLanes) {
      const std::size_t at = static_cast<std::size_t>(j_done) * nx + i0;
      copy_block(s.out_snorm.data(), s.stride, j_done, fields.slip_norm.data() + at, nx);
      copy_block(s.out_work.data(), s.stride, j_done, fields.work.data() + at, nx);
      if constexpr (kAll) {
        copy_block(s.out_px.data(), s.stride, j_done, fields.px.data() + at, nx);
        copy_block(s.out_py.data(), s.stride, j_done, fields.py.data() + at, nx);
        copy_block(s.out_sx.data(), s.stride, j_done, fields.sx.data() + at, nx);
        copy_block(s.out_sy.data(), s.stride, j_done, fields.sy.data() + at, nx);
        Vec8 r[8];
        for (int ci = 0; ci < 8; ++ci) {
          r[ci] = load8(s.out_slip.data() + static_cast<std::size_t>(ci) * s.stride + j_done);
        }
        transpose8(r);
        for (int l = 0; l < kLanes; ++l) {
          const Bytes8 flags = __builtin_convertvector(r[l], Bytes8);
          std::memcpy(fields.slip.data() + at + static_cast<std::size_t>(l) * nx, &flags,
                      sizeof flags);
        }
      }
    }
  }
  for (int j = j_done; j < ny; ++j) {
    const std::size_t at = static_cast<std::size_t>(j) * nx + i0;
    copy_strip(s.out_snorm.data(), s.stride, j, cells, fields.slip_norm.data() + at);
    copy_strip(s.out_work.data(), s.stride, j, cells, fields.work.data() + at);
    if constexpr (kAll) {
      copy_strip(s.out_px.data(), s.stride, j, cells, fields.px.data() + at);
      copy_strip(s.out_py.data(), s.stride, j, cells, fields.py.data() + at);
      copy_strip(s.out_sx.data(), s.stride, j, cells, fields.sx.data() + at);
      copy_strip(s.out_sy.data(), s.stride, j, cells, fields.sy.data() + at);
      for (int ci = 0; ci < cells; ++ci) {
        fields.slip[at + ci] =
            static_cast<std::uint8_t>(s.out_slip[static_cast<std::size_t>(ci) * s.stride + j]);
      }
    }
  }
}

// Marches all strips chunk by chunk and copies each chunk out.
template <bool kAll, class BoundAt>
void march_chunks(BoundAt bound_at, double rate_y, double rate_y_spin, Scratch& s,
                  CellFields& fields) {
  for (int i0 = 0; i0 < fields.nx; i0 += kChunk) {
    const int cells = std::min(kChunk, fields.nx - i0);
    for (int ci = 0; ci < cells; ++ci) {
      advance_cell<kAll>(bound_at, i0 + ci, ci, rate_y, rate_y_spin, s);
    }
    copy_chunk<kAll>(s, i0, cells, fields);
  }
}

template <bool kAll>
void march_chunks(const BoundLaw& bound, double rate_y, double rate_y_spin, Scratch& s,
                  CellFields& fields) {
  const double k = bound.coefficient;
  if (bound.kind == TractionBound::parabolic) {
    march_chunks<kAll>([k](double q) { return k * q; }, rate_y, rate_y_spin, s, fields);
  } else {
    march_chunks<kAll>([k](double q) { return k * std::sqrt(q); }, rate_y, rate_y_spin, s, fields);
  }
}

}  // namespace

MarchTotals march_with_fields(const StripGrid& grid, const Creepages& creepages,
                              const Flexibilities& flex, const BoundLaw& bound, CellFieldSet set,
                              CellFields& fields) {
  const int nx = grid.nx;
  const int ny = grid.ny;
  prepare_fields(fields, nx, ny, grid.dy, /*zero=*/false, set);
  thread_local Scratch s;
  s.resize(ny);
  s.nx = nx;
  for (int j = 0; j < s.stride; ++j) {
    // Padding strips repeat the last strip; their results are dropped.
    const int strip = std::min(j, ny - 1);
    s.xl[j] = grid.x_lead[strip];
    s.dx[j] = 2.0 * s.xl[j] / nx;
    s.step_x[j] = s.dx[j] * px_rate(creepages, flex, grid.y_spin[strip]);
    // A strip of zero length (x_l = 0) carries no traction, so it neither slips nor works.
    s.release_scale[j] = s.dx[j] > 0.0 ? flex.effective / s.dx[j] : 0.0;
  }
  for (int j = 0; j < ny; ++j) {
    fields.dx[j] = s.dx[j];
    fields.strip_y[j] = grid.y_at_o[j];
  }

  const double rate_y = creepages.vy * flex.inv_l22;
  const double rate_y_spin = creepages.phi * flex.inv_l23;
  if (set == CellFieldSet::all) {
    for (int j = 0; j < ny; ++j) {
      const std::size_t row = static_cast<std::size_t>(j) * nx;
      const double x_first = s.xl[j] - 0.5 * s.dx[j];
      double* __restrict x = fields.x.data() + row;
      double* __restrict y = fields.y.data() + row;
      for (int i = 0; i < nx; ++i) {
        x[i] = x_first - i * s.dx[j];
        y[i] = grid.y_at_o[j];
      }
    }
    march_chunks<true>(bound, rate_y, rate_y_spin, s, fields);
  } else {
    march_chunks<false>(bound, rate_y, rate_y_spin, s, fields);
  }

  MarchTotals totals;
  double slip_count = 0.0;
  for (int j = 0; j < ny; ++j) {
    totals.Fx += s.dx[j] * s.sum_px[j];
    totals.Fy += s.dx[j] * s.sum_py[j];
    totals.Mz += s.dx[j] * (s.sum_xpy[j] - grid.y_at_o[j] * s.sum_px[j]);
    totals.work += s.dx[j] * s.sum_work[j];
    slip_count += s.slips[j];
  }
  totals.scale_by_strip_width(grid.dy);
  totals.slip_cells = static_cast<int>(slip_count);
  return totals;
}

}  // namespace wheelwear::tangential::detail
