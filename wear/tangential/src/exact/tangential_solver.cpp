#include "tangential_solver.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace wheelwear::tangential::detail {

namespace {

// Iterates kept by the Anderson acceleration, which removes the slowly convergent and unstable
// modes of the row-wise sweep (those smooth across rows). On the pure-spin cases of CONTACT's
// reference set at 80 x 80, depth 20 needs 90-110 sweeps, depth 10 120-135.
constexpr int kAndersonDepth = 20;

// Traction of one element from the slip r [-] that the other elements and the rigid slip
// cause there, the element's own diagonal compliance (dxx, dyy) [1/Pa] and its traction
// bound g [Pa]: adhesion p = -r/d if that lies within the bound; otherwise slip with
// p = -g e and s = r + d p = lambda e, lambda >= 0 (Coulomb: p opposes the slip), i.e.
// e_k = r_k/(lambda + g d_k) with |e| = 1. The function |e(lambda)|^2 - 1 is convex and
// decreasing, so Newton's method from the lower bound lambda >= |r| - g max(d) converges
// monotonically.
ElementState solve_element(double rx, double ry, double dxx, double dyy, double g, double& px,
                           double& py) {
  const double ax = -rx / dxx, ay = -ry / dyy;
  if (ax * ax + ay * ay <= g * g) {
    px = ax;
    py = ay;
    return ElementState::adhesion;
  }
  if (!(g > 0.0)) {
    px = py = 0.0;
    return ElementState::slip;
  }
  const double gx = g * dxx, gy = g * dyy;
  double lambda = std::max(0.0, std::hypot(rx, ry) - std::max(gx, gy));
  double ex = 0.0, ey = 0.0;
  for (int it = 0; it < 60; ++it) {
    const double qx = 1.0 / (lambda + gx), qy = 1.0 / (lambda + gy);
    ex = rx * qx;
    ey = ry * qy;
    const double f = ex * ex + ey * ey - 1.0;
    if (std::abs(f) < 1e-14) break;
    const double df = -2.0 * (ex * ex * qx + ey * ey * qy);
    lambda -= f / df;
  }
  const double norm = std::hypot(ex, ey);
  px = -g * ex / norm;
  py = -g * ey / norm;
  return ElementState::slip;
}

}  // namespace

void solve_tangential(const InfluenceOperator& op, const std::vector<double>& bound,
                      const std::vector<double>& wx, const std::vector<double>& wy,
                      const ExactSolverOptions& options, ExactSolution& solution,
                      bool with_near_rows) {
  const ElementGrid& grid = op.grid();
  const int near_rows = with_near_rows ? op.near_rows() : 0;
  const int nx = grid.nx, ny = grid.ny;
  const auto n = static_cast<std::size_t>(grid.size());
  auto& px = solution.px;
  auto& py = solution.py;
  auto& sx = solution.sx;
  auto& sy = solution.sy;
  auto& state = solution.state;
  px.assign(n, 0.0);
  py.assign(n, 0.0);
  sx.assign(n, 0.0);
  sy.assign(n, 0.0);
  state.assign(n, ElementState::exterior);

  // Contact elements row by row, ascending in x.
  std::vector<std::vector<int>> rows(static_cast<std::size_t>(ny));
  std::vector<int> elements;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t e = static_cast<std::size_t>(j * nx + i);
      if (solution.pn[e] > 0.0) {
        rows[static_cast<std::size_t>(j)].push_back(i);
        elements.push_back(j * nx + i);
        state[e] = ElementState::adhesion;
      }
    }
  if (elements.empty()) {
    solution.status = ExactStatus::no_contact;
    solution.message = "no element carries pressure";
    return;
  }

  const double inv_dx = 1.0 / grid.dx;
  // Last contact element of each row (the update below runs contiguously up to it; updating
  // the slip of non-contact elements in between is harmless, they are never solved).
  std::vector<int> row_hi(static_cast<std::size_t>(ny), -1);
  for (int j = 0; j < ny; ++j) {
    const auto& cols = rows[static_cast<std::size_t>(j)];
    if (!cols.empty()) row_hi[static_cast<std::size_t>(j)] = cols.back();
  }
  const double* kxx0 = op.kxx_row();
  const double* kyy0 = op.kyy_row();

  // Adds to the slip of elements lo ... hi of the current row the effect of shifting by
  // (ux, uy) the tractions of its elements i_end + 1 ... i: (K(f - i) - K(f - i_end))/dx (ux, uy).
  // Within a row K_xy vanishes (it is odd in y).
  auto update_row = [&](double* sxr, double* syr, int lo, int hi, int i, int i_end, double ux,
                        double uy) {
    const double vx = ux * inv_dx, vy = uy * inv_dx;
    for (int f = lo; f <= hi; ++f) {
      sxr[f] += (kxx0[f - i] - kxx0[f - i_end]) * vx;
      syr[f] += (kyy0[f - i] - kyy0[f - i_end]) * vy;
    }
  };

  // The slip a row's change of traction (dpx, dpy at its contact columns) causes in the near
  // rows above it, which this sweep has still to solve.
  std::vector<double> dpx(static_cast<std::size_t>(nx)), dpy(static_cast<std::size_t>(nx));
  auto update_near_rows = [&](int j) {
    const auto& src = rows[static_cast<std::size_t>(j)];
    for (int up = 1; up <= near_rows && j + up < ny; ++up) {
      const auto& dst = rows[static_cast<std::size_t>(j + up)];
      if (dst.empty()) continue;
      const double* cxx = op.cxx_near(up);
      const double* cxy = op.cxy_near(up);
      const double* cyy = op.cyy_near(up);
      const std::size_t row0 = static_cast<std::size_t>((j + up) * nx);
      for (const int f : dst) {
        double ax = 0.0, ay = 0.0;
        for (const int i : src) {
          const double ux = dpx[static_cast<std::size_t>(i)], uy = dpy[static_cast<std::size_t>(i)];
          ax += cxx[f - i] * ux + cxy[f - i] * uy;
          ay += cxy[f - i] * ux + cyy[f - i] * uy;
        }
        sx[row0 + static_cast<std::size_t>(f)] += ax;
        sy[row0 + static_cast<std::size_t>(f)] += ay;
      }
    }
  };

  // One Gauss-Seidel sweep after SteadyGS, the steady-rolling variant of Vollebregt's ConvexGS
  // (Vollebregt 1995, J. Optim. Theory Appl. 87) in his program CONTACT:
  // the slip of the current tractions by FFT, then every row from its trailing to its leading
  // edge. The unknown of element i is the traction step q_i = p_i - p_(i+1) from its upstream
  // neighbour, in which the steady-rolling slip s = w + K q/dx has the symmetric, diagonally
  // strong half-space kernel K. Changing q_i by d with q fixed elsewhere shifts by d the
  // traction of i and of the adhesion elements downstream of it, up to the first element in
  // slip or outside the contact (index i_end), where q changes by -d. Each element is solved
  // with the diagonal (K(0) - K(i - i_end))/dx of that move; the slip it changes upstream in
  // its row (the elements still to be solved there) is updated directly, the other rows see it
  // at the next sweep's FFT (the Anderson acceleration below takes care of that coupling), but
  // for the near rows above a solved row on long elements (InfluenceOperator::near_rows), whose
  // slip is updated at once.
  // Processing a row from its trailing edge, as SteadyGS does, converges; from the leading
  // edge the sweep diverges under large spin. Returns true when an element changed state.
  auto sweep = [&]() {
    op.slip(px.data(), py.data(), sx.data(), sy.data());
    for (std::size_t e = 0; e < n; ++e) {
      sx[e] += wx[e];
      sy[e] += wy[e];
    }
    bool changed = false;
    for (int j = 0; j < ny; ++j) {
      const auto& cols = rows[static_cast<std::size_t>(j)];
      const std::size_t row0 = static_cast<std::size_t>(j * nx);
      const bool near = near_rows > 0 && !cols.empty();
      if (near) {  // the row's tractions before
        for (const int i : cols) {
          dpx[static_cast<std::size_t>(i)] = -px[row0 + static_cast<std::size_t>(i)];
          dpy[static_cast<std::size_t>(i)] = -py[row0 + static_cast<std::size_t>(i)];
        }
      }
      for (std::size_t k = 0; k < cols.size(); ++k) {
        const int i = cols[k];
        const std::size_t e = row0 + static_cast<std::size_t>(i);
        // The adhesion chain downstream of i: cols[first ... k-1], ending before i_end.
        std::size_t first = k;
        int i_end = i - 1;
        while (first > 0 && cols[first - 1] == i_end &&
               state[row0 + static_cast<std::size_t>(i_end)] == ElementState::adhesion) {
          --first;
          --i_end;
        }
        const double dxx = (kxx0[0] - kxx0[i - i_end]) * inv_dx;
        const double dyy = (kyy0[0] - kyy0[i - i_end]) * inv_dx;
        const double rx = sx[e] - dxx * px[e], ry = sy[e] - dyy * py[e];
        double qx = 0.0, qy = 0.0;
        const ElementState st = solve_element(rx, ry, dxx, dyy, bound[e], qx, qy);
        changed = changed || st != state[e];
        state[e] = st;
        const double ux = qx - px[e], uy = qy - py[e];
        if (ux == 0.0 && uy == 0.0) continue;
        for (std::size_t t = first; t < k; ++t) {
          const std::size_t f = row0 + static_cast<std::size_t>(cols[t]);
          px[f] += ux;
          py[f] += uy;
        }
        px[e] = qx;
        py[e] = qy;
        update_row(sx.data() + row0, sy.data() + row0, i + 1, row_hi[static_cast<std::size_t>(j)],
                   i, i_end, ux, uy);
      }
      if (!near) continue;
      for (const int i : cols) {
        dpx[static_cast<std::size_t>(i)] += px[row0 + static_cast<std::size_t>(i)];
        dpy[static_cast<std::size_t>(i)] += py[row0 + static_cast<std::size_t>(i)];
      }
      update_near_rows(j);
    }
    return changed;
  };

  // Anderson acceleration (Walker & Ni 2011) of the fixed-point map "one sweep" over the
  // tractions of the contact elements: the next iterate combines the last `depth` sweep
  // results so as to minimise the linearised change, then is projected onto the traction
  // bound. The least-squares problem is solved through its Gram matrix, updated by one column
  // per iteration, with a relative regularisation of 1e-12 against nearly dependent columns.
  const auto dim = static_cast<Eigen::Index>(2 * elements.size());
  const int depth = kAndersonDepth;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(dim);
  Eigen::VectorXd g(dim), f(dim), f_prev(dim), g_prev(dim);
  Eigen::MatrixXd df(dim, depth), dg(dim, depth), gram(depth, depth);
  Eigen::VectorXd rhs(depth), gamma(depth);
  int stored = 0, next_slot = 0;
  auto unpack = [&](const Eigen::VectorXd& v) {
    for (std::size_t k = 0; k < elements.size(); ++k) {
      const auto e = static_cast<std::size_t>(elements[k]);
      px[e] = v[static_cast<Eigen::Index>(2 * k)];
      py[e] = v[static_cast<Eigen::Index>(2 * k + 1)];
    }
  };
  auto pack = [&](Eigen::VectorXd& v) {
    for (std::size_t k = 0; k < elements.size(); ++k) {
      const auto e = static_cast<std::size_t>(elements[k]);
      v[static_cast<Eigen::Index>(2 * k)] = px[e];
      v[static_cast<Eigen::Index>(2 * k + 1)] = py[e];
    }
  };

  solution.status = ExactStatus::not_converged;
  for (int it = 1; it <= options.max_iterations; ++it) {
    unpack(x);
    const bool changed = sweep();
    pack(g);
    f = g - x;
    solution.iterations = it;
    const double norm_g = g.norm();
    solution.change = norm_g > 0.0 ? f.norm() / norm_g : f.norm();
    if (!std::isfinite(solution.change)) {
      solution.message = "the iteration produced a non-finite traction";
      break;
    }
    if (!changed && (solution.change <= options.tolerance || norm_g == 0.0)) {
      solution.status = ExactStatus::converged;
      break;
    }
    if (it > 1) {
      const int s = next_slot;
      df.col(s) = f - f_prev;
      dg.col(s) = g - g_prev;
      next_slot = (next_slot + 1) % depth;
      stored = std::min(stored + 1, depth);
      for (int t = 0; t < stored; ++t) gram(s, t) = gram(t, s) = df.col(s).dot(df.col(t));
    }
    f_prev = f;
    g_prev = g;
    if (stored == 0) {
      x = g;
      continue;
    }
    double scale = 0.0;
    for (int t = 0; t < stored; ++t) {
      rhs[t] = df.col(t).dot(f);
      scale = std::max(scale, gram(t, t));
    }
    Eigen::MatrixXd a = gram.topLeftCorner(stored, stored);
    a.diagonal().array() += 1e-12 * scale;
    gamma.head(stored) = a.ldlt().solve(rhs.head(stored));
    x = g;
    for (int t = 0; t < stored; ++t) x -= gamma[t] * dg.col(t);
    if (!x.allFinite()) {  // a singular least-squares step: restart from the plain sweep
      x = g;
      stored = next_slot = 0;
    }
    for (std::size_t k = 0; k < elements.size(); ++k) {
      const auto e = static_cast<std::size_t>(elements[k]);
      const auto ix = static_cast<Eigen::Index>(2 * k);
      const double mag = std::hypot(x[ix], x[ix + 1]);
      if (mag > bound[e]) {
        x[ix] *= bound[e] / mag;
        x[ix + 1] *= bound[e] / mag;
      }
    }
  }
  // Tractions of the last sweep; the slip consistent with them.
  op.slip(px.data(), py.data(), sx.data(), sy.data());
  for (std::size_t e = 0; e < n; ++e) {
    if (state[e] == ElementState::exterior) {
      sx[e] = sy[e] = 0.0;
      continue;
    }
    sx[e] += wx[e];
    sy[e] += wy[e];
  }
  if (solution.status == ExactStatus::not_converged && solution.message.empty())
    solution.message = "max_iterations reached";
}

}  // namespace wheelwear::tangential::detail
