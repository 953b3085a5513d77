#include "wheelwear/tangential/fastsim.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "fastsim_kernel.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/kalker_coefficients.hpp"
#include "wheelwear/tangential/sdec_coefficients.hpp"

namespace wheelwear::tangential {

namespace {

constexpr double pi = std::numbers::pi;

constexpr core::NameTable<FastsimMethod, 5> kNames = {{
    {FastsimMethod::sdec, "fastsim-sdec"},
    {FastsimMethod::eql, "fastsim-eql"},
    {FastsimMethod::eqe, "fastsim-eqe"},
    {FastsimMethod::eqe_shifted, "fastsim-eqe-shifted"},
    {FastsimMethod::elliptic, "fastsim-elliptic"},
}};

// A single flexibility that turns excess traction into slip: the three flexibilities weighted
// by the squares of their creepages (a convex combination, after Kalker's 1982 weighting by
// magnitudes, whose weights add up to more than 1 for combined creepages and inflate the
// slip by up to sqrt(3)). Exact for a single creepage.
double weighted_flexibility(const Creepages& v, double c, double l11, double l22, double l23) {
  const double wx = v.vx * v.vx, wy = v.vy * v.vy, wphi = c * c * v.phi * v.phi;
  const double total = wx + wy + wphi;
  if (total == 0.0) return l11;
  return (wx * l11 + wy * l22 + wphi * l23) / total;
}

// Flexibilities of Eq. 17 from the coefficients C11, C22, C23 (possibly the SDEC ones) and K13.
// For classic FASTSIM, K13 is not used: the spin term of px shares L3 = L23 with py.
detail::Flexibilities flexibilities(double a, double c, double G, double c11, double c22,
                                    double c23, const double* k13, const Creepages& v) {
  const double l11 = 8.0 * a / (3.0 * G * c11);
  const double l22 = 8.0 * a / (3.0 * G * c22);
  // L23 = pi a^2/(4 G c C23): the paper's Eq. 17 prints C22s here, a typo (equating Eq. 16
  // with Eq. 11 gives C23s).
  const double l23 = pi * a * a / (4.0 * G * c * c23);
  const double l13 = k13 ? 2.0 * c / (G * *k13) : l23;
  return {1.0 / l11, 1.0 / l13, 1.0 / l22, 1.0 / l23, weighted_flexibility(v, c, l11, l22, l23)};
}

// ny strips of equal width over y in [y_lo, y_lo + width] (relative to O); the spin terms use
// y - spin_origin.
void fill_strips(detail::StripGrid& grid, const contactgeom::Sdec& region, double centre_shift,
                 double spin_origin, int nx, int ny) {
  grid.nx = nx;
  grid.resize(ny);
  const double width = 2.0 * region.b;
  grid.dy = width / ny;
  const double y_lo = region.y_min() + centre_shift;
  for (int j = 0; j < ny; ++j) {
    const double y = y_lo + (j + 0.5) * grid.dy;
    grid.y_at_o[j] = y;
    grid.y_spin[j] = y - spin_origin;
    grid.x_lead[j] = region.leading_edge(y - centre_shift);
  }
}

}  // namespace

void FastsimOptions::validate() const {
  require(nx >= 1 && nx <= 100000, "nx", nx, "cells per strip must lie in 1 ... 100000");
  require(ny >= 1 && ny <= 100000, "ny", ny, "strips must lie in 1 ... 100000");
  require(static_cast<double>(nx) * ny <= 1e8, "nx*ny", static_cast<double>(nx) * ny,
          "the grid must have at most 1e8 cells");
}

std::string_view method_name(FastsimMethod method) {
  return core::name_of(kNames, method);
}

std::optional<FastsimMethod> parse_fastsim_method(std::string_view name) {
  return core::value_named(kNames, name);
}

TangentialSolution fastsim(FastsimMethod method, const contactgeom::Sdec& sdec,
                           const Creepages& creepages, const ContactLoad& load,
                           const Material& material, const FastsimOptions& options) {
  TangentialSolution solution;
  fastsim(method, sdec, creepages, load, material, options, solution);
  return solution;
}

void fastsim(FastsimMethod method, const contactgeom::Sdec& sdec, const Creepages& creepages,
             const ContactLoad& load, const Material& material, const FastsimOptions& options,
             TangentialSolution& solution) {
  sdec.validate();
  creepages.validate();
  load.validate();
  material.validate();
  options.validate();

  const double a = sdec.a;
  const double c = sdec.c();
  Creepages at_origin = creepages;
  // The region the tractions live on, and where it sits relative to O.
  contactgeom::Sdec region = sdec;
  double centre_shift = 0.0;
  double spin_origin = 0.0;
  solution.forces = CreepForces{};
  // Keep the field storage (its capacity) when fields are asked for again.
  if (options.cell_fields && !solution.fields) solution.fields.emplace();
  if (!options.cell_fields) solution.fields.reset();
  detail::Flexibilities flex;

  if (method == FastsimMethod::sdec) {
    const SdecCoefficients k = sdec_coefficients(sdec, material.nu);
    flex = flexibilities(a, c, material.G, k.c11s, k.c22s, k.c23s, &k.row.k13, creepages);
    solution.forces.flags = k.flags;
  } else {
    const KalkerCoefficients k = kalker_coefficients(sdec.ellipticity(), material.nu);
    flex = flexibilities(a, c, material.G, k.c11, k.c22, k.c23, nullptr, creepages);
    solution.forces.flags.kalker_extrapolated = k.extrapolated;
    if (method != FastsimMethod::eql) region.psi = 0.0;
    if (method == FastsimMethod::eqe_shifted) {
      // Classic FASTSIM about the ellipse centre O' = O + y0: Eq. 10 moves vx there.
      centre_shift = sdec.y0();
      spin_origin = centre_shift;
      at_origin.vx = creepages.vx - creepages.phi * centre_shift;
      flex.effective = weighted_flexibility(at_origin, c, 1.0 / flex.inv_l11, 1.0 / flex.inv_l22,
                                            1.0 / flex.inv_l23);
    }
  }

  thread_local detail::StripGrid grid;
  fill_strips(grid, region, centre_shift, spin_origin, options.nx, options.ny);

  detail::BoundLaw bound{options.bound, 0.0};
  if (options.bound == TractionBound::parabolic) {
    bound.coefficient = load.mu * 2.0 * load.N / (pi * a * a * a * sdec.b);  // Eq. 18
  } else {
    bound.coefficient = load.mu * sdec.peak_pressure(load.N) / a;  // mu p_n, Eq. 4
  }

  detail::MarchTotals totals;
  if (options.scheme == FastsimScheme::second_order) {
    totals = detail::march_second_order(grid, at_origin, flex, bound,
                                        solution.fields ? &*solution.fields : nullptr);
  } else if (options.cell_fields) {
    totals = detail::march_with_fields(grid, at_origin, flex, bound, options.field_set,
                                       *solution.fields);
  } else {
    totals = detail::march(grid, at_origin, flex, bound);
  }
  if (solution.fields) {
    // Semi-elliptic pressure (Eq. 4) of the region the tractions live on, at the cell centres.
    // Per strip p = (p0/a) sqrt(x_l^2 - x^2), with the strip's own leading edge and the cell
    // centres x = x_l - (i + 1/2) dx.
    CellFields& f = *solution.fields;
    const double p0_over_a = region.peak_pressure(load.N) / region.a;
    for (int j = 0; j < f.ny; ++j) {
      const double xl = grid.x_lead[j];
      const double dx = f.dx[j];
      const double x_first = xl - 0.5 * dx;
      double* __restrict pressure = f.pressure.data() + static_cast<std::size_t>(j) * f.nx;
      for (int i = 0; i < f.nx; ++i) {
        const double x = x_first - i * dx;
        pressure[i] = p0_over_a * std::sqrt(std::max((xl - x) * (xl + x), 0.0));
      }
    }
  }
  solution.forces.Fx = totals.Fx;
  solution.forces.Fy = totals.Fy;
  solution.forces.Mz = totals.Mz;
  solution.cells = options.nx * options.ny;
  solution.slip_cells = totals.slip_cells;
  solution.frictional_work = totals.work;
}

}  // namespace wheelwear::tangential
