#include "wheelwear/tangential/exact/steady_rolling.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <utility>

#include "influence_operator.hpp"
#include "tangential_solver.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/exact/normal_contact.hpp"

namespace wheelwear::tangential {

namespace {

// The rigid slip (wx, wy) of element (i, j) at creepages `v` at the origin. The spin part is
// taken dx/6 upstream of the element centre, the offset of CONTACT's steady-rolling
// discretisation (its set_tang_rhs). With it C23 of the circle is within 0.5 % of Kalker's
// table from 40 x 40 elements on and equals CONTACT's to four digits; at the element centre it
// would be 1.3 % low at 80 x 80.
std::pair<double, double> rigid_slip(const ElementGrid& grid, const Creepages& v, int i, int j) {
  return {v.vx - v.phi * grid.y(j), v.vy + v.phi * (grid.x(i) + grid.dx / 6.0)};
}

// Solves the tangential problem of `solution` (grid and pn set) and sums its forces.
// row_vx, where not empty, adds a longitudinal creepage to each row j.
void solve_and_sum(const Creepages& v, std::span<const double> row_vx, double mu,
                   const Material& material, const ExactSolverOptions& options,
                   ExactSolution& solution) {
  const ElementGrid& grid = solution.grid;
  const auto n = static_cast<std::size_t>(grid.size());
  std::vector<double> bound(n), wx(n), wy(n);
  for (int j = 0; j < grid.ny; ++j) {
    const double row = row_vx.empty() ? 0.0 : row_vx[static_cast<std::size_t>(j)];
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = static_cast<std::size_t>(j * grid.nx + i);
      bound[e] = mu * solution.pn[e];
      const auto [x, y] = rigid_slip(grid, v, i, j);
      wx[e] = x + row;
      wy[e] = y;
    }
  }
  const detail::InfluenceOperator op(grid, material, true, false);
  detail::solve_tangential(op, bound, wx, wy, options, solution);
  if (solution.status == ExactStatus::not_converged && op.near_rows() > 0) {
    // Updating the near rows of long elements within the sweep is what makes partial slip on
    // them converge, but under full adhesion on fine grids (a/b = 10 on 80 x 80 and 120 x 120:
    // elements 10 times longer than wide) it stalls, where leaving them to the FFT converges in
    // 100-300 sweeps: the other iteration, where the first one did not converge. Its answer is
    // kept only where it converged: unconverged, it may wander far (46 % of Fx under mixed
    // creepage), whatever its last change.
    ExactSolution other;  // the same problem: solve_tangential sets the rest
    other.grid = solution.grid;
    other.pn = solution.pn;
    detail::solve_tangential(op, bound, wx, wy, options, other, false);
    const int sweeps = solution.iterations + other.iterations;  // both count
    if (other.status == ExactStatus::converged) solution = std::move(other);
    solution.iterations = sweeps;
  }

  const double da = grid.area();
  CreepForces& f = solution.forces;
  f = CreepForces{};
  double mz = 0.0;
  solution.normal_force = solution.frictional_work = solution.row_creepage_work = 0.0;
  solution.contact_elements = solution.adhesion_elements = solution.slip_elements = 0;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const std::size_t e = static_cast<std::size_t>(j * grid.nx + i);
      if (solution.state[e] == ElementState::exterior) continue;
      ++solution.contact_elements;
      if (solution.state[e] == ElementState::adhesion) {
        ++solution.adhesion_elements;
      } else {
        ++solution.slip_elements;
        solution.frictional_work += std::hypot(solution.px[e], solution.py[e]) *
                                    std::hypot(solution.sx[e], solution.sy[e]) * da;
      }
      solution.normal_force += solution.pn[e] * da;
      if (!row_vx.empty())
        solution.row_creepage_work -= row_vx[static_cast<std::size_t>(j)] * solution.px[e] * da;
      f.Fx += solution.px[e] * da;
      f.Fy += solution.py[e] * da;
      mz += (grid.x(i) * solution.py[e] - grid.y(j) * solution.px[e]) * da;
    }
  f.Mz = mz;
}

}  // namespace

ElementGrid sdec_grid(const contactgeom::Sdec& sdec, const SdecGridOptions& options) {
  sdec.validate();
  options.validate();
  ElementGrid grid;
  grid.nx = options.nx;
  grid.ny = options.ny;
  grid.dx = 2.0 * options.margin * sdec.a / options.nx;
  grid.dy = 2.0 * options.margin * sdec.b / options.ny;
  grid.x_min = -options.margin * sdec.a + options.shift_x * grid.dx;
  grid.y_min = sdec.y0() - options.margin * sdec.b + options.shift_y * grid.dy;
  return grid;
}

SdecGridOptions aspect_sdec_grid(const contactgeom::Sdec& sdec, int across, double max_aspect) {
  sdec.validate();
  require(across >= 2 && across <= kMaxElementsPerSide, "across", across,
          "needs 2 ... 4096 elements across the patch");
  require_finite("max_aspect", max_aspect);
  require(max_aspect >= 1.0, "max_aspect", max_aspect, "must be at least 1");
  // Elements dx/dy = (a/nx)/(b/ny): along the long axis as many as keep them within max_aspect.
  const double slender = std::max(sdec.a / sdec.b, sdec.b / sdec.a);
  const double needed = std::ceil(across * slender / max_aspect - 1e-9);
  const int along =
      static_cast<int>(std::clamp(needed, double(across), double(kMaxElementsPerSide)));
  SdecGridOptions grid;
  grid.nx = sdec.a >= sdec.b ? along : across;
  grid.ny = sdec.a >= sdec.b ? across : along;
  return grid;
}

ExactSolution exact_sdec(const contactgeom::Sdec& sdec, const Creepages& creepages,
                         const ContactLoad& load, const Material& material,
                         const SdecGridOptions& grid_options, const ExactSolverOptions& options) {
  creepages.validate();
  load.validate();
  material.validate();
  options.validate();
  ExactSolution solution;
  solution.grid = sdec_grid(sdec, grid_options);
  const ElementGrid& grid = solution.grid;
  solution.pn.resize(static_cast<std::size_t>(grid.size()));
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i)
      solution.pn[static_cast<std::size_t>(j * grid.nx + i)] =
          sdec.pressure(grid.x(i), grid.y(j), load.N);
  solve_and_sum(creepages, {}, load.mu, material, options, solution);
  return solution;
}

CreepForces full_sliding_sdec(const contactgeom::Sdec& sdec, const Creepages& creepages,
                              const ContactLoad& load, const SdecGridOptions& grid_options) {
  creepages.validate();
  load.validate();
  const ElementGrid grid = sdec_grid(sdec, grid_options);
  // The pressure as Sdec::pressure gives it, its leading edge and scale taken once per row: the
  // book of tables sums this near full sliding at every lookup (creep_table.cpp).
  const double scale = sdec.peak_pressure(load.N) / sdec.a;
  double fx = 0.0, fy = 0.0, mz = 0.0;
  for (int j = 0; j < grid.ny; ++j) {
    const double xl = sdec.leading_edge(grid.y(j));
    if (!(xl > 0.0)) continue;
    // The columns that may lie inside the row's extent (t > 0 decides), one to spare each side.
    const int lo = std::max(0, static_cast<int>(std::floor((-xl - grid.x_min) / grid.dx)) - 1);
    const int hi = std::min(grid.nx - 1, static_cast<int>(std::ceil((xl - grid.x_min) / grid.dx)));
    double row_x = 0.0, row_y = 0.0, row_moment = 0.0;
    for (int i = lo; i <= hi; ++i) {
      const double x = grid.x(i), t = xl * xl - x * x;
      const auto [wx, wy] = rigid_slip(grid, creepages, i, j);
      // |p| = mu p_n against the rigid slip's direction. A rigid slip below 1e-150 (whose square
      // underflows, or whose t / w2 overflows) carries no traction, as a vanishing one does.
      const double w2 = wx * wx + wy * wy;
      const double k = t > 0.0 && w2 > 1e-300 ? load.mu * scale * std::sqrt(t / w2) : 0.0;
      row_x -= k * wx;
      row_y -= k * wy;
      row_moment -= k * x * wy;
    }
    fx += row_x;
    fy += row_y;
    mz += row_moment - grid.y(j) * row_x;
  }
  const double da = grid.area();
  CreepForces forces;
  forces.Fx = fx * da;
  forces.Fy = fy * da;
  forces.Mz = mz * da;
  return forces;
}

ExactSolution exact_rolling(const ElementGrid& grid, const std::vector<double>& h,
                            const Creepages& creepages, const ContactLoad& load,
                            const Material& material, const ExactSolverOptions& options,
                            std::span<const double> row_vx) {
  creepages.validate();
  load.validate();
  require(row_vx.empty() || row_vx.size() == static_cast<std::size_t>(grid.ny), "row_vx.size()",
          static_cast<double>(row_vx.size()), "must be 0 or the grid's rows (ny)");
  for (double v : row_vx) require_finite("row_vx", v);
  NormalSolution normal = exact_normal(grid, h, load.N, material, options);
  ExactSolution solution;
  solution.grid = grid;
  solution.pn = std::move(normal.pn);
  solve_and_sum(creepages, row_vx, load.mu, material, options, solution);
  if (normal.status == ExactStatus::not_converged) {
    solution.status = ExactStatus::not_converged;
    solution.message = "normal problem: " + normal.message;
  }
  return solution;
}

}  // namespace wheelwear::tangential
