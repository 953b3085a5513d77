// creep(): the forces of SDEC patches, one per element of flat arrays (the package broadcasts
// numpy's shapes and reshapes), each solved as `wheelwear creep` solves it.

#include <oneapi/tbb/parallel_for.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "creep_request.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/table_correction.hpp"

namespace wheelwear::python {

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The per-patch inputs, as flat arrays of one length.
struct Inputs {
  const std::vector<Array>& arrays;  // a, b, psi, vx, vy, phi, N, G, nu, mu
  py::ssize_t size = 0;
  double at(std::size_t which, py::ssize_t i) const { return arrays[which].data()[i]; }
};

// Patches per check for Ctrl-C: a few milliseconds of FASTSIM, some tens of the exact theory.
py::ssize_t chunk_of(tangential::Method method) {
  if (method == tangential::Method::exact) return 4;
  return method == tangential::Method::best ? 16 : 256;  // best: lookups, or slender exact solves
}

py::dict creep_arrays(const cli::CreepOptions& options, const std::vector<Array>& arrays,
                      std::optional<int> threads) {
  const cli::CreepSolver solver(options);
  Inputs in{arrays, arrays.at(0).size()};
  for (const Array& a : arrays)
    if (a.size() != in.size) throw InputError("creep: the inputs must have one shape");
  const auto n = static_cast<std::size_t>(in.size);
  std::vector<double> Fx(n), Fy(n), Mz(n), work(n);
  std::vector<int> cells(n), slip(n);
  // Bytes, not std::vector<bool>: the threads write neighbouring elements.
  std::vector<std::uint8_t> from_table(n), extrapolated(n);
  std::vector<std::string> status(n);
  std::vector<std::vector<std::string>> warnings(n);
  run_on_threads(threads, [&] {
    const py::ssize_t chunk = chunk_of(solver.method());
    for (py::ssize_t first = 0; first < in.size; first += chunk) {
      check_interrupt();
      const py::ssize_t last = std::min(in.size, first + chunk);
      oneapi::tbb::parallel_for(first, last, [&](py::ssize_t i) {
        const contactgeom::Sdec sdec{in.at(0, i), in.at(1, i), in.at(2, i)};
        const tangential::Creepages c{in.at(3, i), in.at(4, i), in.at(5, i)};
        const tangential::ContactLoad load{in.at(6, i), in.at(9, i)};
        const tangential::Material material{in.at(7, i), in.at(8, i)};
        const auto k = static_cast<std::size_t>(i);
        cli::check_creep_inputs(sdec, c, load, warnings[k]);
        const tangential::TangentialSolution s = solver.solve(sdec, c, load, material);
        Fx[k] = s.forces.Fx;
        Fy[k] = s.forces.Fy;
        Mz[k] = s.forces.Mz.value_or(std::nan(""));
        // The rigid slip's work, which every method with a spin moment defines (the exact
        // theory's cells sum to it as the grid is refined; table_correction.hpp).
        work[k] = s.forces.Mz ? tangential::rigid_slip_work(s.forces, c) : std::nan("");
        // The exact theory's own status, as the command line's JSON gives it ("converged").
        status[k] = std::string(s.exact ? tangential::status_name(s.exact->status)
                                        : tangential::status_name(s.status));
        cells[k] = s.cells;
        slip[k] = s.slip_cells;
        from_table[k] = s.from_table;
        extrapolated[k] = s.forces.flags.any();
      });
    }
  });
  // Each distinct warning once (a creep curve repeats them point after point).
  std::set<std::string> distinct;
  std::vector<std::string> ordered;
  for (const auto& list : warnings)
    for (const std::string& w : list)
      if (distinct.insert(w).second) ordered.push_back(w);
  py::dict out;
  out["Fx"] = py::array_t<double>(in.size, Fx.data());
  out["Fy"] = py::array_t<double>(in.size, Fy.data());
  out["Mz"] = py::array_t<double>(in.size, Mz.data());
  out["rigid_slip_work"] = py::array_t<double>(in.size, work.data());
  out["status"] = status;
  out["cells"] = py::array_t<int>(in.size, cells.data());
  out["slip_cells"] = py::array_t<int>(in.size, slip.data());
  py::array_t<bool> table(in.size), flags(in.size);
  for (std::size_t k = 0; k < n; ++k) {
    table.mutable_data()[k] = from_table[k];
    flags.mutable_data()[k] = extrapolated[k];
  }
  out["from_table"] = table;
  out["extrapolated"] = flags;
  out["warnings"] = ordered;
  return out;
}

}  // namespace

void bind_creep(py::module_& m) {
  m.def(
      "creep_arrays",
      [](const std::string& method, std::optional<int> nx, std::optional<int> ny,
         std::optional<std::string> bound, std::optional<std::string> scheme,
         std::optional<double> target_error, std::optional<int> exact_grid,
         std::optional<std::string> beyond_table, std::optional<std::string> inside_table,
         const std::vector<Array>& arrays, std::optional<int> threads) {
        cli::CreepOptions o;
        o.method = method;
        o.nx = nx;
        o.ny = ny;
        o.bound = std::move(bound);
        o.scheme = std::move(scheme);
        o.target_error = target_error;
        o.exact_grid = exact_grid;
        o.beyond_table = std::move(beyond_table);
        o.inside_table = std::move(inside_table);
        if (arrays.size() != 10)
          throw InputError("creep_arrays: give a, b, psi, vx, vy, phi, N, G, nu, mu");
        return creep_arrays(o, arrays, threads);
      },
      py::arg("method"), py::arg("nx"), py::arg("ny"), py::arg("bound"), py::arg("scheme"),
      py::arg("target_error"), py::arg("exact_grid"), py::arg("beyond_table"),
      py::arg("inside_table"), py::arg("arrays"), py::arg("threads"),
      "Creep forces of SDEC patches given as ten flat float64 arrays of one length (a, b, psi, "
      "vx, vy, phi, N, G, nu, mu): a dict of flat arrays. Use wheelwear.creep().");
}

}  // namespace wheelwear::python
