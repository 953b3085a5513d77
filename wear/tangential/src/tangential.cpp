#include "wheelwear/tangential/tangential.hpp"

#include <algorithm>
#include <utility>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/exact/exact_fields.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/linear_theory.hpp"
#include "wheelwear/tangential/table_correction.hpp"

namespace wheelwear::tangential {

namespace {

constexpr core::NameTable<SolveStatus, 3> kStatusNames = {{
    {SolveStatus::ok, "ok"},
    {SolveStatus::not_converged, "not converged"},
    {SolveStatus::no_contact, "no contact"},
}};

SolveStatus solve_status(ExactStatus status) {
  switch (status) {
    case ExactStatus::converged:
      return SolveStatus::ok;
    case ExactStatus::not_converged:
      return SolveStatus::not_converged;
    case ExactStatus::no_contact:
      return SolveStatus::no_contact;
  }
  return SolveStatus::ok;
}

// Totals only: the per-cell storage a reused solution holds is dropped with its meaning.
void totals_only(const CreepForces& forces, TangentialSolution& solution) {
  solution.forces = forces;
  solution.cells = solution.slip_cells = 0;
  solution.fields.reset();
  solution.frictional_work = 0.0;
}

void solve_exact(const contactgeom::Sdec& sdec, const Creepages& creepages, const ContactLoad& load,
                 const Material& material, const SolveOptions& options,
                 TangentialSolution& solution) {
  ExactSolution exact =
      exact_sdec(sdec, creepages, load, material, options.exact_grid, options.exact_solver);
  if (options.fastsim.cell_fields) {
    TangentialSolution cells = exact_tangential_solution(exact, creepages);
    solution.fields = std::move(cells.fields);
    solution.frictional_work = cells.frictional_work;
  } else {
    // As with cells: the rigid slip's work, to which the discrete sum converges only to first
    // order in the element size (exact_fields.hpp).
    solution.fields.reset();
    solution.frictional_work = std::max(0.0, rigid_slip_work(exact.forces, creepages));
  }
  solution.forces = exact.forces;
  solution.cells = exact.contact_elements;
  solution.slip_cells = exact.slip_elements;
  solution.status = solve_status(exact.status);
  solution.message = exact.message;
  solution.exact = std::move(exact);
}

// The exact theory on a grid that resolves the patch's long axis (best for single evaluations).
void solve_exact_resolved(const contactgeom::Sdec& sdec, const Creepages& creepages,
                          const ContactLoad& load, const Material& material,
                          const SolveOptions& options, TangentialSolution& solution) {
  SolveOptions resolved = options;
  resolved.exact_grid = aspect_sdec_grid(sdec);
  // Slender patches under small mixed creepage took up to 700 sweeps on this grid in the
  // slender-patch study: room above that.
  resolved.exact_solver.max_iterations = std::max(options.exact_solver.max_iterations, 3000);
  solve_exact(sdec, creepages, load, material, resolved, solution);
}

// best: for one patch (exact_inside_table) the exact theory on the resolving grid wherever the
// patch lies; in runs the table's totals inside its range, with cell fields FASTSIM-SDEC's
// distribution carried to them, without them the table alone (FASTSIM would only be thrown
// away).
void solve_best(const contactgeom::Sdec& sdec, const Creepages& creepages, const ContactLoad& load,
                const Material& material, const SolveOptions& options,
                TangentialSolution& solution) {
  if (options.exact_inside_table) {
    solve_exact_resolved(sdec, creepages, load, material, options, solution);
    return;
  }
  CreepTableLookup lookup = creep_table_lookup(sdec, creepages, load, material);
  if (lookup.forces && !lookup.forces->Mz) {  // a table without Mz cannot give the work
    lookup.forces.reset();
    lookup.outside = "the table has no spin moment Mz, which the frictional work needs";
  }
  solution.table_outside = std::move(lookup.outside);
  if (lookup.forces && !options.fastsim.cell_fields) {
    totals_only(*lookup.forces, solution);
    solution.from_table = true;
    // The work of the rigid slip, as correct_with_creep_table gives it with cells.
    solution.frictional_work = std::max(0.0, rigid_slip_work(*lookup.forces, creepages));
    return;
  }
  if (solution.table_outside && options.exact_beyond_table) {
    const std::optional<std::string> why = std::move(solution.table_outside);
    solve_exact_resolved(sdec, creepages, load, material, options, solution);
    solution.table_outside = why;
    return;
  }
  fastsim(FastsimMethod::sdec, sdec, creepages, load, material, options.fastsim, solution);
  if (lookup.forces)
    solution.from_table = correct_with_table_totals(*lookup.forces, creepages, solution);
}

}  // namespace

std::string_view method_name(Method method) {
  return core::name_of(kMethodNames, method);
}

std::optional<Method> parse_method(std::string_view name) {
  return core::value_named(kMethodNames, name);
}

std::string_view status_name(SolveStatus status) {
  return core::name_of(kStatusNames, status);
}

std::optional<FastsimMethod> fastsim_variant(Method method) {
  switch (method) {
    case Method::fastsim_sdec:
    case Method::best:
      return FastsimMethod::sdec;
    case Method::fastsim_eql:
      return FastsimMethod::eql;
    case Method::fastsim_eqe:
      return FastsimMethod::eqe;
    case Method::fastsim_eqe_shifted:
      return FastsimMethod::eqe_shifted;
    case Method::fastsim_elliptic:
      return FastsimMethod::elliptic;
    case Method::linear_sdec:
    case Method::she_sdec:
    case Method::table:
    case Method::exact:
      return std::nullopt;
  }
  return std::nullopt;
}

bool has_cell_fields(Method method) {
  return fastsim_variant(method) || method == Method::exact;
}

void SolveOptions::validate() const {
  fastsim.validate();
  exact_grid.validate();
  exact_solver.validate();
}

TangentialSolution solve_patch(Method method, const contactgeom::Sdec& sdec,
                               const Creepages& creepages, const ContactLoad& load,
                               const Material& material, const SolveOptions& options) {
  TangentialSolution solution;
  solve_patch(method, sdec, creepages, load, material, options, solution);
  return solution;
}

void solve_patch(Method method, const contactgeom::Sdec& sdec, const Creepages& creepages,
                 const ContactLoad& load, const Material& material, const SolveOptions& options,
                 TangentialSolution& solution) {
  solution.status = SolveStatus::ok;
  solution.message.clear();
  solution.from_table = false;
  solution.table_outside.reset();
  solution.exact.reset();
  switch (method) {
    case Method::linear_sdec:
      sdec.validate();
      load.validate();
      totals_only(linear_sdec_forces(sdec, creepages, material), solution);
      return;
    case Method::she_sdec:
      sdec.validate();
      load.validate();
      totals_only(she_sdec_forces(sdec, creepages, material, load), solution);
      return;
    case Method::table:
      totals_only(creep_table_forces(sdec, creepages, load, material), solution);
      solution.from_table = true;
      return;
    case Method::best:
      solve_best(sdec, creepages, load, material, options, solution);
      return;
    case Method::exact:
      solve_exact(sdec, creepages, load, material, options, solution);
      return;
    case Method::fastsim_sdec:
    case Method::fastsim_eql:
    case Method::fastsim_eqe:
    case Method::fastsim_eqe_shifted:
    case Method::fastsim_elliptic:
      fastsim(*fastsim_variant(method), sdec, creepages, load, material, options.fastsim, solution);
      return;
  }
}

}  // namespace wheelwear::tangential
