#pragma once
/// Kalker's exact theory of steady rolling for elastically similar half-spaces (Kalker 1990,
/// Ch. 5; as solved by Vollebregt's CONTACT): piecewise-constant tractions on a rectangular
/// grid, analytical influence coefficients, Coulomb friction with adhesion and slip areas.

#include <span>
#include <vector>

#include "wheelwear/contactgeom/sdec.hpp"
#include "wheelwear/tangential/creep_types.hpp"
#include "wheelwear/tangential/exact/exact_types.hpp"

namespace wheelwear::tangential {

/// The grid of an SDEC patch: [-margin a, margin a] x [y0 - margin b, y0 + margin b] around
/// the patch's mid-point O' (y0 = psi b from O), options.nx x options.ny elements.
ElementGrid sdec_grid(const contactgeom::Sdec& sdec, const SdecGridOptions& options);

/// A grid of an SDEC patch that resolves a slender patch along its long axis: `across`
/// elements over the short one and elements at most `max_aspect` times longer than wide (an
/// N x N grid over a patch of a/b = 10 has elements 10 times longer than wide; its forces
/// converge slowly in the long direction: Fy of pure spin 0.7 % of mu N off the converged
/// value on 80 x 80, 0.4 % on 200 x 40). Margin 1.02, as CONTACT's. across >= 2, max_aspect >= 1.
SdecGridOptions aspect_sdec_grid(const contactgeom::Sdec& sdec, int across = 40,
                                 double max_aspect = 2.0);

/// Steady rolling on an SDEC patch with the prescribed pressure of Liu, Fu & Bruni 2022, Eq. 4,
/// p_n = (p0/a) sqrt(x_l(y)^2 - x^2), p0 = 3N/(2 pi a b), evaluated at element centres (as
/// CONTACT's SDEC option does; its sum over the grid differs from N by the grid's error).
/// Creepages are at O: the rigid slip is w = (vx - phi y, vy + phi (x + dx/6)) with y from O
/// (the spin term dx/6 upstream of the element centre, as in CONTACT's steady-rolling
/// discretisation). The slip of element i is s = w + (u(x_i) - u(x_i + dx))/dx (Kalker's
/// backward difference; material enters at the leading edge x > 0); where it slips
/// |p| = mu p_n and p opposes s.
/// Throws InputError on invalid input.
ExactSolution exact_sdec(const contactgeom::Sdec& sdec, const Creepages& creepages,
                         const ContactLoad& load, const Material& material,
                         const SdecGridOptions& grid = {}, const ExactSolverOptions& options = {});

/// The limit of exact_sdec as the creepages grow in a fixed direction: every element slides
/// with |p| = mu p_n against its rigid slip w. The elastic part of the slip is bounded by the
/// tractions, so exact_sdec's forces approach these as 1/|w|. Same grid, pressure and rigid
/// slip as exact_sdec, without iteration: forces on the wheel (Kalker's convention), Mz about O.
/// An element whose rigid slip vanishes (below 1e-150) carries no traction. Throws InputError on
/// invalid input.
CreepForces full_sliding_sdec(const contactgeom::Sdec& sdec, const Creepages& creepages,
                              const ContactLoad& load, const SdecGridOptions& grid = {});

/// Steady rolling for a given undeformed distance `h` [m] per element of `grid` (index
/// j*nx + i, before the approach; the contact area follows from the normal problem,
/// exact_normal) with normal force load.N and friction load.mu. Creepages are at the origin
/// of the grid's coordinates; rigid slip, slip and friction as for exact_sdec. Forces are on
/// body 1 against body 2 (Kalker's convention). `row_vx`, where not empty (one value per row
/// j, grid.ny), is added to vx in each row: a rolling radius whose departure from the contact
/// plane's varies across the patch (conformal contact, wheel_rail_exact). Throws InputError on
/// invalid input.
ExactSolution exact_rolling(const ElementGrid& grid, const std::vector<double>& h,
                            const Creepages& creepages, const ContactLoad& load,
                            const Material& material, const ExactSolverOptions& options = {},
                            std::span<const double> row_vx = {});

}  // namespace wheelwear::tangential
