// Kalker's exact theory on slender SDEC patches (a/b 0.05, 0.1 and 5 ... 25, where the flange's
// patches lie; the book of tables covers a/b 0.2 ... 25 at nu 0.25): how the solve converges on
// CONTACT's 80 x 80 grid (elements up to 25 times longer than wide) and on aspect_sdec_grid (40
// across, elements at most twice as long as wide; what method best solves there for single
// evaluations), and how far FASTSIM-SDEC on 50 x 50 (what best gives beyond the table in runs)
// and the book of tables (where it covers the patch) lie from it.
//
// Cases: CONTACT's reference load (p0 = 1000 MPa, c = sqrt(ab) = 4.25 mm, mu 0.35, G 80 GPa,
// nu 0.25), psi -0.8 ... 0.8, pure spin and mixed creepages. Writes bench/results/
// slender_patches.csv (or the file given), one row per case and grid:
//   a_over_b, psi, vx, vy, phi   the case
//   grid                          contact (80 x 80) | aspect (aspect_sdec_grid) | fastsim |
//                                 table (nx, ny: the grid its nodes were solved on)
//   nx, ny                        its elements or cells
//   converged                     1 when the exact solve met its tolerance (fastsim: 1)
//   sweeps, seconds               its iterations and wall time (one thread)
//   Fx_muN, Fy_muN                forces over mu N
//   dF_vs_aspect_muN              max(|dFx|, |dFy|)/(mu N) against the aspect grid's answer
//
//   build/studies/wheelwear_slender_patch_study [CSV]

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "support/contact_cases.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace {

using namespace wheelwear;
using namespace wheelwear::tangential;

struct Row {
  std::string grid;
  int nx = 0, ny = 0;
  bool converged = false;
  int sweeps = 0;
  double seconds = 0.0, fx = 0.0, fy = 0.0;
};

template <typename Solve>
double timed(Solve&& solve) {
  const auto start = std::chrono::steady_clock::now();
  solve();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Row exact_row(const std::string& name, const contactgeom::Sdec& patch, const Creepages& v,
              const ContactLoad& load, const SdecGridOptions& grid) {
  ExactSolution s;
  Row row{name, grid.nx, grid.ny};
  row.seconds = timed([&] { s = exact_sdec(patch, v, load, {}, grid, {}); });
  row.converged = s.status == ExactStatus::converged;
  row.sweeps = s.iterations;
  row.fx = s.forces.Fx / (load.mu * load.N);
  row.fy = s.forces.Fy / (load.mu * load.N);
  return row;
}

// The book of tables where it covers the patch (nullopt beyond it).
std::optional<Row> table_row(const contactgeom::Sdec& patch, const Creepages& v,
                             const ContactLoad& load) {
  if (!creep_table_covers(patch, v, load, {})) return std::nullopt;
  const SdecGridOptions grid = creep_table_grid(patch);
  CreepForces f;
  Row row{"table", grid.nx, grid.ny, true};
  row.seconds = timed([&] { f = creep_table_forces(patch, v, load, {}); });
  row.fx = f.Fx / (load.mu * load.N);
  row.fy = f.Fy / (load.mu * load.N);
  return row;
}

Row fastsim_row(const contactgeom::Sdec& patch, const Creepages& v, const ContactLoad& load) {
  SolveOptions options;  // 50 x 50 cells
  TangentialSolution s;
  Row row{"fastsim", options.fastsim.nx, options.fastsim.ny, true};
  row.seconds = timed([&] { s = solve_patch(Method::fastsim_sdec, patch, v, load, {}, options); });
  row.fx = s.forces.Fx / (load.mu * load.N);
  row.fy = s.forces.Fy / (load.mu * load.N);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : WHEELWEAR_RESULTS "/slender_patches.csv";
  std::ofstream out(path);
  if (!out) {
    std::fprintf(stderr, "cannot write %s\n", path.c_str());
    return 1;
  }
  out << "a_over_b,psi,vx,vy,phi,grid,nx,ny,converged,sweeps,seconds,Fx_muN,Fy_muN,"
         "dF_vs_aspect_muN\n";
  const std::vector<Creepages> creepages = {{0, 0, 0.2},        {0, 0, 1.0},
                                            {5e-4, -5e-4, 0.2}, {1e-3, 5e-4, 0.1},
                                            {-3e-4, 8e-4, 0.4}, {2e-4, 2e-4, 0.05}};
  int count = 0;
  for (const double g : {0.05, 0.1, 5.0, 7.0, 10.0, 15.0, 20.0, 25.0})
    for (const double psi : {-0.8, -0.4, 0.0, 0.4, 0.8})
      for (const Creepages& v : creepages) {
        const contactgeom::Sdec patch = testing::contact::reference_patch(g, psi);
        const ContactLoad load = testing::contact::reference_load(patch);
        SdecGridOptions contact_grid;  // 80 x 80, margin 1.02: CONTACT's
        const Row aspect = exact_row("aspect", patch, v, load, aspect_sdec_grid(patch));
        std::vector<Row> rows = {exact_row("contact", patch, v, load, contact_grid), aspect,
                                 fastsim_row(patch, v, load)};
        if (const auto table = table_row(patch, v, load)) rows.push_back(*table);
        for (const Row& r : rows) {
          const double d = std::max(std::abs(r.fx - aspect.fx), std::abs(r.fy - aspect.fy));
          char line[400];
          std::snprintf(line, sizeof line, "%g,%g,%g,%g,%g,%s,%d,%d,%d,%d,%.4g,%.6f,%.6f,%.6f\n", g,
                        psi, v.vx, v.vy, v.phi, r.grid.c_str(), r.nx, r.ny, int(r.converged),
                        r.sweeps, r.seconds, r.fx, r.fy, d);
          out << line;
        }
        if (++count % 24 == 0) std::fprintf(stderr, "%d of 240 cases\n", count);
      }
  std::fprintf(stderr, "wrote %s\n", path.c_str());
  return 0;
}
