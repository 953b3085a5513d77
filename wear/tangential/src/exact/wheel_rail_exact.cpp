#include "wheelwear/tangential/exact/wheel_rail_exact.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "wheelwear/contactgeom/undeformed_distance.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/profiles/profile.hpp"
#include "wheelwear/tangential/exact/normal_contact.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"

namespace wheelwear::tangential {

namespace {

constexpr int kMinElements = 4;     // fewer cannot tell the patch's edge from its centre
constexpr int kMaxElements = 1000;  // 10^6 elements: the FFT arrays need about 1 GB beyond
// Undeformed distance [m] given to elements where a profile ends: they never touch, and a
// contact element next to one is reported (the patch would need the missing surface).
constexpr double kNoSurface = 1.0;
// Samples of a profile turned into the contact plane, either way from O, at most.
constexpr int kMaxPlaneSamples = 20000;

// The least undeformed distance along x in O's cross-section: a parabola through the distance
// at x = -l, 0, l (the wheel's sag is quadratic in x to 1e-4 relative over a patch length;
// a yawed wheel's lowest point moves along x, undeformed_distance.hpp).
struct CrossSectionMinimum {
  double x = 0.0;         // where the distance is least [m]
  double distance = 0.0;  // its value [m], vertical
};

CrossSectionMinimum cross_section_minimum(const contactgeom::WheelRailPair& pair,
                                          const contactgeom::WheelsetPose& pose, double y_O,
                                          double l) {
  const auto back = contactgeom::undeformed_distance(pair, pose, -l, y_O);
  const auto centre = contactgeom::undeformed_distance(pair, pose, 0.0, y_O);
  const auto front = contactgeom::undeformed_distance(pair, pose, l, y_O);
  if (!back || !centre || !front) {
    std::ostringstream m;
    m << "wheel_rail_exact: patch.y_rail = " << -y_O
      << " m: the undeformed distance is undefined at the patch's O (off the wheel or rail "
         "profile); pass a patch found by contactgeom::solve_wheel_rail for the same pair and "
         "pose";
    throw InputError(m.str());
  }
  const double curvature = *back - 2.0 * *centre + *front;
  if (!(curvature > 0.0)) return {0.0, *centre};
  // Kept within the three samples: a nearly flat gap along x would put it far off the patch.
  const double x = std::clamp(0.5 * l * (*back - *front) / curvature, -l, l);
  const double t = x / l;  // the parabola through the three samples, at x
  return {x, *centre + 0.5 * t * (*front - *back) + 0.5 * t * t * curvature};
}

// Throws InputError when the pressure reaches the grid's border or an element where a profile
// ends: the contact area would then be cut off, and the forces wrong without a warning.
void require_inside(const ElementGrid& grid, const std::vector<double>& pn,
                    const std::vector<bool>& no_surface, const WheelRailExactOptions& options) {
  auto at = [&](int i, int j) { return static_cast<std::size_t>(j * grid.nx + i); };
  const char* edge = nullptr;
  for (int j = 0; j < grid.ny && !edge; ++j) {
    if (pn[at(0, j)] > 0.0) edge = "trailing edge (least x)";
    if (pn[at(grid.nx - 1, j)] > 0.0) edge = "leading edge (largest x)";
  }
  for (int i = 0; i < grid.nx && !edge; ++i) {
    if (pn[at(i, 0)] > 0.0) edge = "field-side edge (least s)";
    if (pn[at(i, grid.ny - 1)] > 0.0) edge = "gauge-side edge (largest s)";
  }
  if (edge) {
    std::ostringstream m;
    m << "wheel_rail_exact: the exact contact area reaches the element grid's " << edge
      << " (grid x " << grid.x_min * 1e3 << " ... " << (grid.x_min + grid.nx * grid.dx) * 1e3
      << " mm, s " << grid.y_min * 1e3 << " ... " << (grid.y_min + grid.ny * grid.dy) * 1e3
      << " mm from O): the patch is larger than the Kik-Piotrowski patch the grid was sized "
         "from; increase margin (now "
      << options.margin << "; --exact-margin on the command line)";
    throw InputError(m.str());
  }
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      if (!(pn[at(i, j)] > 0.0)) continue;
      const bool missing_neighbour =
          (i > 0 && no_surface[at(i - 1, j)]) || (i + 1 < grid.nx && no_surface[at(i + 1, j)]) ||
          (j > 0 && no_surface[at(i, j - 1)]) || (j + 1 < grid.ny && no_surface[at(i, j + 1)]);
      if (missing_neighbour) {
        std::ostringstream m;
        m << "wheel_rail_exact: the exact contact area reaches the end of the wheel or rail "
             "profile at s = "
          << grid.y(j) * 1e3 << " mm from O: the profiles do not cover this contact";
        throw InputError(m.str());
      }
    }
}

// The longitudinal creepage each row of `grid` adds where the wheel's rolling radius departs
// from its tangent at O: a material point at lateral offset t from O (in the wheel's unrolled
// profile, where a roll does not change the radius) has the radius r_O + z(y_O + t) - z(y_O)
// (the wheel's z points away from its axle), and the planar theory keeps only the linear part
// z'(y_O) t, which the spin creepage carries. The rest slows (or speeds) that row's surface:
// vx(s) - vx = -omega (r(s) - r_lin(s)) / V = -departure / r_O (omega r_O = V to the order of
// the creepage). The contact plane is the wheel's tangent at O, so row j, at s_j along it
// towards the gauge side (the profile's -y), lies at t = -s_j / sqrt(1 + z'(y_O)^2); rows off
// the wheel add nothing (they have no surface).
std::vector<double> radius_departure_creepage(const profiles::Profile& wheel, double y_O,
                                              double rolling_radius, const ElementGrid& grid) {
  const auto at_O = wheel.surface_at(y_O);
  require(at_O && std::isfinite(at_O->dz_dy), "patch.y_wheel", -y_O,
          "the wheel's surface must have a finite slope at O for radius_variation");
  const double cos_tangent = 1.0 / std::sqrt(1.0 + at_O->dz_dy * at_O->dz_dy);
  std::vector<double> row_vx(static_cast<std::size_t>(grid.ny), 0.0);
  for (int j = 0; j < grid.ny; ++j) {
    const double t = -grid.y(j) * cos_tangent;
    const auto z = wheel.z_at(y_O + t);
    if (!z) continue;
    const double departure = *z - at_O->z - at_O->dz_dy * t;
    row_vx[static_cast<std::size_t>(j)] = -departure / rolling_radius;
  }
  return row_vx;
}

// A profile's points turned into the contact plane: t along it towards the gauge side, n along
// its normal (down, into the rail), both from the rail's point at O.
struct PlaneSection {
  std::vector<double> t, n;
};

// The contact plane through the rail's point O = (y_O, z_O), inclined by delta: turns a point
// (y, z) of the rail frame into (t, n).
struct ContactPlane {
  double y_O, z_O, cos_delta, sin_delta;

  void add(PlaneSection& section, double y, double z) const {
    const double dy = y - y_O, dz = z - z_O;
    section.t.push_back(-dy * cos_delta + dz * sin_delta);
    section.n.push_back(dy * sin_delta + dz * cos_delta);
  }
};

// The value of `section` at plane coordinate t: between its two points about t, the first pair
// found from index `from` outwards (a profile turned by the plane may fold back far from the
// contact); nullopt where none brackets t.
std::optional<double> section_at(const PlaneSection& section, double t, std::size_t from) {
  const std::size_t size = section.t.size();
  if (size < 2) return std::nullopt;
  from = std::min(from, size - 2);
  for (std::size_t d = 0; d < size; ++d) {
    for (const std::size_t i : {from + d, from >= d ? from - d : size}) {
      if (i + 1 >= size) continue;
      const double t0 = section.t[i], t1 = section.t[i + 1];
      if (t0 <= t && t <= t1 && t1 > t0)
        return section.n[i] + (t - t0) / (t1 - t0) * (section.n[i + 1] - section.n[i]);
    }
  }
  return std::nullopt;
}

// The rail's samples (y, z) from O outwards, `step` apart along y at first and then about half
// a row apart along the plane's t, until `beyond(t)` or the rail's end.
struct RailSamples {
  std::vector<double> y, z;
};

template <class Beyond>
RailSamples walk_rail(const profiles::Profile& rail, const ContactPlane& plane, double delta,
                      double half_row, double step, Beyond&& beyond) {
  RailSamples out;
  double y = plane.y_O, t = 0.0;
  for (int k = 0; k < kMaxPlaneSamples && !beyond(t); ++k) {
    y += step;
    const auto r = rail.surface_at(y);
    if (!r) break;
    // dt = dy cos(gamma - delta) / cos(gamma) along the rail.
    const double gamma = std::atan(-r->dz_dy);
    const double dy_per_dt = std::cos(gamma) / std::max(std::cos(gamma - delta), 0.05);
    t = -(y - plane.y_O) * plane.cos_delta + (r->z - plane.z_O) * plane.sin_delta;
    out.y.push_back(y);
    out.z.push_back(r->z);
    step = std::copysign(half_row * dy_per_dt, step);
  }
  return out;
}

// The rail's samples across `grid`'s rows in increasing t: walked out from O on both sides
// until the rail's t passes the rows by two rows and by how far the wheel lies from the rail
// along t (its rigid penetration).
RailSamples rail_across(const profiles::Profile& rail, const ContactPlane& plane,
                        const contactgeom::WheelRailPatch& patch, const ElementGrid& grid) {
  const double margin = 2.0 * grid.dy + std::abs(patch.rigid_penetration);
  const double t_lo = grid.y_min - margin, t_hi = grid.y_min + grid.ny * grid.dy + margin;
  const double half_row = 0.5 * grid.dy, delta = patch.plane_angle;
  const RailSamples gauge = walk_rail(rail, plane, delta, half_row, -half_row * plane.cos_delta,
                                      [&](double t) { return t > t_hi; });
  const RailSamples field = walk_rail(rail, plane, delta, half_row, half_row * plane.cos_delta,
                                      [&](double t) { return t < t_lo; });
  RailSamples out;
  out.y.assign(field.y.rbegin(), field.y.rend());
  out.z.assign(field.z.rbegin(), field.z.rend());
  out.y.push_back(plane.y_O);
  out.z.push_back(plane.z_O);
  out.y.insert(out.y.end(), gauge.y.begin(), gauge.y.end());
  out.z.insert(out.z.end(), gauge.z.begin(), gauge.z.end());
  return out;
}

// The rail's n at a plane coordinate, with the index of its section to search the wheel's from.
struct RailAt {
  std::optional<double> n;
  std::size_t index = 0;
};

RailAt rail_at(const PlaneSection& rail, double t) {
  const auto index =
      static_cast<std::size_t>(std::lower_bound(rail.t.begin(), rail.t.end(), t) - rail.t.begin());
  return {section_at(rail, t, index), index};
}

// The wheel's cross-section at x over the rail's samples, turned into the plane: its surface
// lies the undeformed distance above the rail's, moved down by `wheel_down`.
PlaneSection wheel_section(const contactgeom::WheelRailPair& pair,
                           const contactgeom::WheelsetPose& pose, const ContactPlane& plane,
                           const RailSamples& rail, double x, double wheel_down) {
  PlaneSection wheel;
  for (std::size_t k = 0; k < rail.y.size(); ++k) {
    const auto d = contactgeom::undeformed_distance(pair, pose, x, rail.y[k]);
    if (d) plane.add(wheel, rail.y[k], rail.z[k] - *d + wheel_down);
  }
  return wheel;
}

std::optional<double> gap_at(const PlaneSection& wheel, const RailAt& rail, double t) {
  const auto n_w = section_at(wheel, t, rail.index);
  if (!rail.n || !n_w) return std::nullopt;
  return *rail.n - *n_w;
}

// The undeformed distance along the normal of the patch's plane per element of `grid`, zero at
// O's least distance (`least`, vertical, at its cross-section's lowest x, `least_x`), the wheel
// moved down by the patch's rigid penetration there; kNoSurface (and no_surface set) where a
// profile ends.
std::vector<double> planar_gap(const contactgeom::WheelRailPair& pair,
                               const contactgeom::WheelsetPose& pose,
                               const contactgeom::WheelRailPatch& patch, double least_x,
                               double least, const ElementGrid& grid,
                               std::vector<bool>& no_surface) {
  const double y_O = -patch.y_rail;
  const auto at_O = pair.rail.surface_at(y_O);
  require(at_O.has_value(), "patch.y_rail", patch.y_rail, "O must lie on the rail profile");
  const ContactPlane plane{y_O, at_O->z, std::cos(patch.plane_angle), std::sin(patch.plane_angle)};
  const double wheel_down = least + patch.rigid_penetration;
  const RailSamples samples = rail_across(pair.rail, plane, patch, grid);
  PlaneSection rail;
  for (std::size_t k = 0; k < samples.y.size(); ++k) plane.add(rail, samples.y[k], samples.z[k]);
  // The rail does not depend on x: its n at each row (and at O) once for every column.
  std::vector<RailAt> rows;
  for (int j = 0; j < grid.ny; ++j) rows.push_back(rail_at(rail, grid.y(j)));
  const PlaneSection wheel_at_O = wheel_section(pair, pose, plane, samples, least_x, wheel_down);
  const double at_O_gap = gap_at(wheel_at_O, rail_at(rail, 0.0), 0.0).value_or(0.0);
  std::vector<double> h(static_cast<std::size_t>(grid.size()), kNoSurface);
  for (int i = 0; i < grid.nx; ++i) {
    const PlaneSection wheel = wheel_section(pair, pose, plane, samples, grid.x(i), wheel_down);
    for (int j = 0; j < grid.ny; ++j) {
      const std::size_t e = static_cast<std::size_t>(j * grid.nx + i);
      const auto gap = gap_at(wheel, rows[static_cast<std::size_t>(j)], grid.y(j));
      no_surface[e] = !gap.has_value();
      if (gap) h[e] = *gap - at_O_gap;
    }
  }
  return h;
}

}  // namespace

void WheelRailExactOptions::validate() const {
  require(nx >= kMinElements && nx <= kMaxElements, "nx", nx, "needs 4 ... 1000 elements along x");
  require(ny >= kMinElements && ny <= kMaxElements, "ny", ny, "needs 4 ... 1000 elements along s");
  require_finite("margin", margin);
  require(margin >= 1.0 && margin <= 5.0, "margin", margin,
          "the grid must cover the patch: 1 <= margin <= 5");
  solver.validate();
}

ElementGrid wheel_rail_exact_grid(const contactgeom::WheelRailPatch& patch, double x_centre,
                                  const WheelRailExactOptions& options) {
  options.validate();
  const contactgeom::PatchMeasures& m = patch.measures;
  require_finite("x_centre", x_centre);
  require_finite("patch.measures.length", m.length);
  require_finite("patch.measures.W1", m.W1);
  require_finite("patch.measures.W2", m.W2);
  require(m.length > 0.0, "patch.measures.length", m.length,
          "the patch must have a positive length (metres)");
  require(m.W1 + m.W2 > 0.0, "patch.measures.W1 + W2", m.W1 + m.W2,
          "the patch must have a positive width (metres)");
  ElementGrid grid;
  grid.nx = options.nx;
  grid.ny = options.ny;
  grid.dx = options.margin * m.length / options.nx;
  grid.dy = options.margin * (m.W1 + m.W2) / options.ny;
  grid.x_min = x_centre - 0.5 * options.margin * m.length;
  grid.y_min = 0.5 * (m.W1 - m.W2) - 0.5 * options.margin * (m.W1 + m.W2);
  return grid;
}

WheelRailExactSolution wheel_rail_exact(const contactgeom::WheelRailPair& pair,
                                        const contactgeom::WheelsetPose& pose,
                                        const contactgeom::WheelRailPatch& patch,
                                        const Creepages& creepages, double mu,
                                        const WheelRailExactOptions& options) {
  options.validate();
  pair.validate();
  creepages.validate();
  const ContactLoad load{patch.normal_force, mu};
  require_finite("patch.normal_force", load.N);
  require_finite("mu", mu);
  load.validate();
  require_finite("patch.contact_angle", patch.contact_angle);
  require(std::abs(patch.contact_angle) < 0.5 * std::numbers::pi, "patch.contact_angle",
          patch.contact_angle, "must lie within +-pi/2 rad");
  require_finite("patch.y_rail", patch.y_rail);
  const Material material{pair.youngs_modulus / (2.0 * (1.0 + pair.poisson)), pair.poisson};

  // The contact plane passes through O, inclined by the patch's plane angle delta to the track
  // plane (contactgeom's: CONTACT's weighted plane, or O's tangent plane); its lateral
  // coordinate s points to the gauge side, the rail frame's -y. The undeformed distance of an
  // element is taken along the plane's normal between the rail and the wheel turned into the
  // plane, the wheel placed at its rigid approach (as CONTACT's planar contact takes it, and
  // strips_of in wheel_rail_patches.cpp): planar_gap below.
  const double y_O = -patch.y_rail;
  const CrossSectionMinimum lowest =
      cross_section_minimum(pair, pose, y_O, 0.5 * patch.measures.length);

  WheelRailExactSolution out;
  const ElementGrid grid = wheel_rail_exact_grid(patch, lowest.x, options);
  const auto n = static_cast<std::size_t>(grid.size());
  std::vector<bool> no_surface(n, false);
  out.h = planar_gap(pair, pose, patch, lowest.x, lowest.distance, grid, no_surface);

  const NormalSolution normal = exact_normal(grid, out.h, load.N, material, options.solver);
  out.normal_iterations = normal.iterations;
  out.approach = normal.approach;
  if (normal.status == ExactStatus::no_contact) {
    out.rolling.grid = grid;
    out.rolling.status = ExactStatus::no_contact;
    out.rolling.message = "normal problem: " + normal.message;
    return out;
  }
  require_inside(grid, normal.pn, no_surface, options);

  // exact_rolling solves the same normal problem again (deterministic: the same pressure);
  // the first solve above is what lets the grid be checked before the costlier tangential
  // iteration.
  if (options.radius_variation) {
    require(patch.rolling_radius > 0.0, "patch.rolling_radius", patch.rolling_radius,
            "must be positive (metres) for radius_variation");
    out.row_vx = radius_departure_creepage(pair.wheel, -patch.y_wheel, patch.rolling_radius, grid);
  }
  out.rolling = exact_rolling(grid, out.h, creepages, load, material, options.solver, out.row_vx);
  out.contact_area = out.rolling.contact_elements * grid.area();
  if (out.rolling.contact_elements > 0)
    out.adhesion_fraction =
        static_cast<double>(out.rolling.adhesion_elements) / out.rolling.contact_elements;
  return out;
}

}  // namespace wheelwear::tangential
