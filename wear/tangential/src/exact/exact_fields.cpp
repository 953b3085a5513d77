#include "wheelwear/tangential/exact/exact_fields.hpp"

#include <algorithm>
#include <cmath>

#include "wheelwear/tangential/table_correction.hpp"

namespace wheelwear::tangential {

TangentialSolution exact_tangential_solution(const ExactSolution& exact,
                                             const Creepages& creepages) {
  const ElementGrid& g = exact.grid;
  const auto n = static_cast<std::size_t>(g.size());
  TangentialSolution out;
  out.forces = exact.forces;
  out.cells = g.size();
  out.slip_cells = exact.slip_elements;
  CellFields f;
  f.nx = g.nx;
  f.ny = g.ny;
  f.dy = g.dy;
  f.dx.assign(static_cast<std::size_t>(g.ny), g.dx);
  f.strip_y.resize(static_cast<std::size_t>(g.ny));
  for (int j = 0; j < g.ny; ++j) f.strip_y[static_cast<std::size_t>(j)] = g.y(j);
  f.x.resize(n);
  f.y.resize(n);
  f.work.resize(n);
  f.slip_norm.resize(n);
  f.slip.resize(n);
  const bool solved = exact.px.size() == n && exact.py.size() == n && exact.sx.size() == n &&
                      exact.sy.size() == n && exact.pn.size() == n && exact.state.size() == n;
  f.px = solved ? exact.px : std::vector<double>(n, 0.0);
  f.py = solved ? exact.py : std::vector<double>(n, 0.0);
  f.sx = solved ? exact.sx : std::vector<double>(n, 0.0);
  f.sy = solved ? exact.sy : std::vector<double>(n, 0.0);
  f.pressure = solved ? exact.pn : std::vector<double>(n, 0.0);
  double work = 0.0;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const auto k = static_cast<std::size_t>(j * g.nx + i);
      f.x[k] = g.x(i);
      f.y[k] = g.y(j);
      f.slip_norm[k] = std::hypot(f.sx[k], f.sy[k]);
      f.work[k] = std::hypot(f.px[k], f.py[k]) * f.slip_norm[k];
      f.slip[k] = solved && exact.state[k] == ElementState::slip ? 1 : 0;
      work += f.work[k];
    }
  }
  work *= g.area();
  const double rigid =
      std::max(0.0, rigid_slip_work(exact.forces, creepages) + exact.row_creepage_work);
  if (work > 0.0) {
    const double factor = rigid / work;
    for (std::vector<double>* v : {&f.sx, &f.sy, &f.slip_norm, &f.work})
      for (double& x : *v) x *= factor;
    out.frictional_work = rigid;
  }
  out.fields = std::move(f);
  return out;
}

}  // namespace wheelwear::tangential
