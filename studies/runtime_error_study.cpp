// Run time against error of every tangential method, on CONTACT's reference cases.
//
//   wheelwear_runtime_error_study [RESULTS_DIR] [--quick] [--methods LIST]
//
// writes to RESULTS_DIR (default: the current directory)
//
// * runtime_error.csv: one row per method, scheme, grid and case set, with the time per call and
//   the error against Kalker's exact theory (CONTACT) and against the method's own converged
//   answer. Columns:
//     method          the --method name of `wheelwear creep`; exact: Kalker's exact theory
//                     solved by the library (tangential::exact_sdec, the SDEC pressure of Liu, Fu &
//                     Bruni 2022, Eq. 4, prescribed as in CONTACT's reference runs; `wheelwear
//                     creep --method exact`); table: the built-in book of exact-theory
//                     tables (tangential::creep_table_forces); best: as `wheelwear creep
//                     --method best` gives it, the exact theory on aspect_sdec_grid inside the
//                     table's range and outside it
//     scheme          kalker | second-order (FASTSIM marching); none for the other methods
//     bound           parabolic (Eq. 18 of Liu, Fu & Bruni 2022) | none (the non-FASTSIM
//                     methods: exact applies Coulomb's |p| <= mu p_n itself)
//     n               the grid is n x n cells (nx = ny = n; exact: elements over CONTACT's
//                     potential contact area, 1.02 a by 1.02 b around O'); 0 for the grid-free
//                     methods (linear-sdec, she-sdec, table) and for best (its own grid)
//     cells           n*n
//     case_set        pure_spin: the 17 cases phi > 0 of tests/data/contact/b_pure_spin_mx80.csv
//                     (g = 1, psi = 0.6 with phi = 0.2 ... 1.6 1/m, and phi = 1 1/m with
//                     psi = -0.8 ... 0.8); linear: the 90 patches of a_linear_coeffs_mx80.csv
//                     (g = 0.1 ... 10, psi = -0.8 ... 0.8), each with CONTACT's three unit
//                     creepages (vx = 1e-6, vy = 1e-6, phi = 1e-6/c), 270 calls. Both sets are
//                     CONTACT's runs with G = 80 GPa, nu = 0.25 on 80 x 80 grids
//     calls           solver calls in one pass over the set (table: the cases it covers)
//     time_per_call_s the smallest, over 15 repetitions, of the mean time of one call in a
//                     loop over the set repeated for at least 3 ms, in CPU time of the thread
//                     (one thread; the solution object is reused, as a simulation loop would);
//                     fewer repetitions, at least 3, once they have taken 10 s (only the exact
//                     theory's finer grids do)
//     err_contact     pure_spin: largest |F - F_CONTACT|/(mu N) over the cases and over Fx, Fy;
//                     linear: largest |F - F_CONTACT|/|F_CONTACT| (force vectors (Fx, Fy)) over
//                     the patches and the three creepages
//     err_converged   the same measure against the method's own converged answer (0 for the
//                     grid-free methods; exact: see below)
//     err_contact_fx, err_contact_fy
//                     err_contact of each force component alone (same normaliser: mu N, or
//                     |F_CONTACT| for the linear set)
//     skipped         cases of the set left out of calls, time and errors because the method
//                     does not cover them; only the table skips (creep_table_covers false: on
//                     the linear set the patches with a/b or |psi| outside its range), 0 for
//                     the other methods
//
//   exact runs on n = 10, 20, 30, 40, 60, 80 (--quick: 10, 20). At n = 80 it solves CONTACT's
//   own discretisation, so its err_contact there measures how closely the library reproduces
//   CONTACT, not the exact theory's grid error; on other grids err_contact also contains
//   CONTACT's own 80 x 80 grid error (below 1 % for g = 0.1 ... 1/0.3, up to 1.2 % at
//   b/a = 0.1: tests/data/contact/README.md, section 4). Its err_converged is against its own
//   120 x 120 solution (--quick: 40 x 40), not a Richardson extrapolation: with
//   piecewise-constant elements whose centres sample the patch boundary differently on every
//   grid, the apparent order of convergence changes from grid to grid (measured on pure spin:
//   the largest error falls by 9 % from n = 30 to 40 and by 45 % from 40 to 60; CONTACT's
//   refinement check in that README moves coefficients in both directions), so the order p
//   an extrapolation needs is not known. The 120 x 120 answer has its own grid error, so
//   err_converged understates the error of the finer grids (most at n = 80).
//
//   The table is the one the library loads at run time, generated with the exact solver on the
//   grid creep_table_range().grid (printed on stderr, with its range); the reference cases'
//   nu = 0.25 is the table's lowest tabulated nu, so its nu = 0.25 block is used alone,
//   without interpolation or extrapolation in nu. Its err_contact therefore holds the table's
//   interpolation error and the generating grid's error against CONTACT's 80 x 80 answer.
//
// * grid_error_fit.csv: err_converged on the pure-spin set for every n = 5 ... 200 and
//   n = 250, 300, 400, 500, 600, 800, 1000, every FASTSIM method, both schemes and both traction
//   bounds (columns method, scheme, bound, n, err_converged), against the converged answer
//   from 1600 and 3200, and
// * grid_error_constants.csv: the constants C of the error models e(n) = C/n^p fitted to it as
//   envelopes: C = max over those n >= n_min of e(n) n^p, so the model bounds every measured
//   point from n_min on. p = 1 for Kalker's first-order scheme, 2 for the second-order scheme
//   with the parabolic bound and 1.5 with the semi-elliptic one (Solver::order); n_min = 5 for
//   Kalker's scheme, 10 and 20 for the second-order one (Solver::min_fit_n). Columns method,
//   scheme, bound, order (p), n_min, C, C_n100_200 (the same maximum over n = 100 ... 200
//   only, for comparison) and n_at_max (where the maximum is).
//
// The converged answer of a FASTSIM method is the Richardson extrapolation
// F(1600) + (F(1600) - F(800))/(2^p - 1) of the same method and scheme; its own error is
// estimated by the difference from the extrapolation of 400 and 800 and printed on stderr.
//
// --quick uses fewer grids and converged grids of 200/400 (for a smoke run, not for the
// results).
//
// --methods LIST (comma-separated method names, e.g. exact,table) runs only those methods and
// merges: the rows of the other methods already in RESULTS_DIR's CSV files are read back and
// kept (a column they lack, added since they were written, is filled with its default: 0 for
// skipped), the listed methods' rows are replaced, and rows are written in the order of a full
// run. grid_error_fit.csv and grid_error_constants.csv are rewritten only when the list names
// a FASTSIM method (fastsim-sdec stands for both of its schemes). Do not merge --quick rows
// into full results.
//
// Regenerate the committed results with
//   cmake --build build --target wheelwear_runtime_error_study
//   build/studies/wheelwear_runtime_error_study bench/results
//   /usr/bin/python3 scripts/plot_runtime_error.py bench/results/runtime_error.csv
//       bench/results/runtime_error.png
// or refresh only some methods, e.g. after the creep table was regenerated, with
//   build/studies/wheelwear_runtime_error_study bench/results --methods table

#include <time.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "runtime_error_cases.hpp"
#include "study_csv.hpp"
#include "support/contact_cases.hpp"
#include "wheelwear/core/enum_names.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/tangential.hpp"

namespace {

using wheelwear::bench::rank;
using wheelwear::bench::split;
using wheelwear::bench::StudyCsv;
using namespace wheelwear::bench::runtime_error;

using namespace wheelwear;
namespace contact = wheelwear::testing::contact;

const tangential::Material kSteel = contact::kMaterial;  // CONTACT's: G = 80 GPa, nu = 0.25

/// A tangential method with its discretisation (solve_patch's method and options); FASTSIM's
/// scheme and bound matter only to the FASTSIM methods, n only to those with a grid.
struct Solver {
  tangential::Method method = tangential::Method::fastsim_sdec;
  tangential::FastsimScheme fastsim_scheme = tangential::FastsimScheme::kalker;
  tangential::TractionBound traction_bound = tangential::TractionBound::parabolic;

  // best answers with the exact theory here (exact_inside_table, exact_beyond_table): no FASTSIM
  // grid.
  bool fastsim() const {
    return method != tangential::Method::best && tangential::fastsim_variant(method).has_value();
  }
  bool exact() const { return method == tangential::Method::exact; }
  bool grid() const { return fastsim() || exact(); }
  /// The CSV's names: the creep --method name, and the scheme and bound of a FASTSIM method
  /// ("none" for the others).
  std::string name() const { return std::string(tangential::method_name(method)); }
  std::string scheme() const {
    return fastsim() ? std::string(core::name_of(tangential::kSchemeNames, fastsim_scheme))
                     : "none";
  }
  std::string bound() const {
    return fastsim() ? std::string(core::name_of(tangential::kBoundNames, traction_bound)) : "none";
  }
  // Order of convergence in n: Kalker's scheme is first order. The second-order scheme is
  // second order with the parabolic bound; with the semi-elliptic bound, whose slope is
  // unbounded at the leading and trailing edges, it reaches only 1.5 (measured: e(n) n^2 grows
  // about 2 times from n = 200 to 1000, e(n) n^1.5 changes by about 10 %).
  double order() const {
    if (fastsim_scheme == tangential::FastsimScheme::kalker) return 1.0;
    return traction_bound == tangential::TractionBound::parabolic ? 2.0 : 1.5;
  }
  // The smallest grid the error model is fitted from: below it the second-order scheme is not
  // yet in its asymptotic range (its e(n) n^p peaks at n = 6 at up to 10 times its value at
  // n = 100 ... 1000), and a model fitted there would ask for needlessly fine grids.
  int min_fit_n() const {
    if (fastsim_scheme == tangential::FastsimScheme::kalker) return 5;
    return traction_bound == tangential::TractionBound::parabolic ? 10 : 20;
  }
};

/// Calls the solver on every case through solve_patch; `solution` is reused between calls.
/// Returns the number of exact-theory solves that stopped short (their last iterate is used).
int solve_all(const Solver& s, int n, const CaseSet& set, std::vector<Forces>& out,
              tangential::TangentialSolution& solution) {
  out.resize(set.cases.size());
  tangential::SolveOptions options;
  options.fastsim.nx = options.fastsim.ny = std::max(n, 1);
  options.fastsim.scheme = s.fastsim_scheme;
  options.fastsim.bound = s.traction_bound;
  options.exact_grid.nx = options.exact_grid.ny = std::max(n, 2);
  options.exact_beyond_table = true;  // best as `wheelwear creep` gives it
  options.exact_inside_table = true;
  int not_converged = 0;
  for (std::size_t k = 0; k < set.cases.size(); ++k) {
    const Case& c = set.cases[k];
    tangential::solve_patch(s.method, c.patch, c.creepages, c.load, kSteel, options, solution);
    if (solution.status != tangential::SolveStatus::ok) ++not_converged;
    out[k] = {solution.forces.Fx, solution.forces.Fy};
  }
  return not_converged;
}

/// CPU time of the calling thread [s]: unlike wall time it does not count the time the thread
/// waits while other processes run on a shared machine.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Smallest mean time per call over 15 repetitions of >= 3 ms each, or over fewer (at least 3)
/// once the repetitions have taken 10 s: one pass of the exact theory over the linear set on
/// an 80 x 80 grid takes about 20 s.
double time_per_call(const Solver& s, int n, const CaseSet& set) {
  constexpr int kRepetitions = 15, kMinRepetitions = 3;
  constexpr double kMinRepetitionSeconds = 3e-3, kBudgetSeconds = 10.0;
  std::vector<Forces> out;
  tangential::TangentialSolution solution;
  solve_all(s, n, set, out, solution);  // warm-up: the grid storage is allocated here
  double best = 1e300, spent = 0;
  volatile double sink = 0;
  for (int rep = 0; rep < kRepetitions; ++rep) {
    if (rep >= kMinRepetitions && spent > kBudgetSeconds) break;
    long passes = 0;
    const double start = thread_seconds();
    double elapsed = 0;
    do {
      solve_all(s, n, set, out, solution);
      sink = sink + out.front().fx;
      ++passes;
      elapsed = thread_seconds() - start;
    } while (elapsed < kMinRepetitionSeconds);
    spent += elapsed;
    best = std::min(best, elapsed / static_cast<double>(passes * set.cases.size()));
  }
  return best;
}

/// The converged answer of a FASTSIM solver: Richardson extrapolation of n_fine/2 and n_fine.
/// `spread` receives the largest difference (in the set's measure) from the extrapolation of
/// n_fine/4 and n_fine/2.
std::vector<Forces> converged(const Solver& s, const CaseSet& set, int n_fine, double& spread) {
  std::vector<Forces> f1, f2, f4;
  tangential::TangentialSolution solution;
  solve_all(s, n_fine / 4, set, f4, solution);
  solve_all(s, n_fine / 2, set, f2, solution);
  solve_all(s, n_fine, set, f1, solution);
  const double r = 1.0 / (std::pow(2.0, s.order()) - 1.0);
  std::vector<Forces> result(set.cases.size());
  spread = 0;
  for (std::size_t k = 0; k < set.cases.size(); ++k) {
    result[k] = {f1[k].fx + (f1[k].fx - f2[k].fx) * r, f1[k].fy + (f1[k].fy - f2[k].fy) * r};
    const Forces coarse{f2[k].fx + (f2[k].fx - f4[k].fx) * r, f2[k].fy + (f2[k].fy - f4[k].fy) * r};
    spread = std::max(spread, case_error(set.measure, set.cases[k], coarse.fx, coarse.fy,
                                         result[k].fx, result[k].fy));
  }
  return result;
}

std::vector<Solver> fastsim_solvers(tangential::TractionBound bound, bool every_scheme) {
  using tangential::Method;
  std::vector<Solver> solvers;
  for (const Method method :
       {Method::fastsim_elliptic, Method::fastsim_eqe, Method::fastsim_eqe_shifted,
        Method::fastsim_eql, Method::fastsim_sdec}) {
    for (const auto scheme :
         {tangential::FastsimScheme::kalker, tangential::FastsimScheme::second_order}) {
      const bool second = scheme == tangential::FastsimScheme::second_order;
      if (second && !every_scheme && method != Method::fastsim_sdec) continue;
      solvers.push_back({method, scheme, bound});
    }
  }
  return solvers;
}

/// The methods of Part 1 in the order of a full run (and of the CSV's rows).
std::vector<Solver> plotted_solvers() {
  using tangential::Method;
  std::vector<Solver> solvers = {{Method::linear_sdec}, {Method::she_sdec}};
  for (const Solver& s : fastsim_solvers(tangential::TractionBound::parabolic, false))
    solvers.push_back(s);
  solvers.push_back({Method::exact});
  solvers.push_back({Method::table});
  solvers.push_back({Method::best});
  return solvers;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path dir = ".";
  bool quick = false;
  std::set<std::string> only;  // --methods; empty: every method
  std::vector<std::string> known;
  for (const Solver& s : plotted_solvers())
    if (rank(known, s.name()) == known.size()) known.push_back(s.name());
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quick") {
      quick = true;
    } else if (arg == "--methods" && i + 1 < argc) {
      for (const std::string& name : split(argv[++i], ',')) {
        if (rank(known, name) == known.size()) {
          std::cerr << "--methods: unknown method '" << name << "'; known:";
          for (const std::string& k : known) std::cerr << " " << k;
          std::cerr << "\n";
          return 2;
        }
        only.insert(name);
      }
    } else if (arg.rfind("--", 0) == 0) {
      std::cerr << "unknown option " << arg
                << "; usage: wheelwear_runtime_error_study [RESULTS_DIR] [--quick] "
                   "[--methods LIST]\n";
      return 2;
    } else {
      dir = arg;
    }
  }
  const bool merge = !only.empty();
  const auto selected = [&](const Solver& s) { return !merge || only.contains(s.name()); };
  std::filesystem::create_directories(dir);
  const int n_fine = quick ? 400 : 1600;
  const std::vector<int> plot_grids =
      quick ? std::vector<int>{5, 10, 20, 40, 80}
            : std::vector<int>{5, 7, 10, 14, 20, 28, 40, 56, 80, 113, 160, 200};
  // The exact theory's grids, and the finer grid its err_converged is measured against.
  const std::vector<int> exact_grids =
      quick ? std::vector<int>{10, 20} : std::vector<int>{10, 20, 30, 40, 60, 80};
  const int n_exact_reference = quick ? 40 : 120;
  // Part 2's grids: every n up to 200, then sparser up to the largest grid grid_choice.hpp
  // allows (1000), against a converged answer from 1600 and 3200.
  std::vector<int> fit_grids;
  for (int n = 5; n <= (quick ? 40 : 200); ++n) fit_grids.push_back(n);
  if (!quick)
    for (const int n : {250, 300, 400, 500, 600, 800, 1000}) fit_grids.push_back(n);
  const int n_fit_fine = quick ? 400 : 3200;

  std::vector<CaseSet> sets;
  try {
    sets = {pure_spin_cases(), linear_cases(kSteel)};
  } catch (const std::exception& error) {
    std::cerr << "wheelwear_runtime_error_study: " << error.what() << "\n";
    return 1;
  }
  const std::vector<Solver> solvers = plotted_solvers();

  if (!merge || only.contains("table")) {
    const tangential::CreepTableRange range = tangential::creep_table_range();
    std::fprintf(stderr,
                 "table: nu %g ... %g, a/b %g ... %g, |psi| <= %g, r <= %g, exact solver on "
                 "%d x %d; the reference cases have nu = %g\n",
                 range.nu_min, range.nu_max, range.a_over_b_min, range.a_over_b_max, range.psi_max,
                 range.r_max, range.grid, range.grid, kSteel.nu);
  }

  // Part 1: the plotted methods, timed, on both case sets.
  std::vector<std::string> set_order, method_order;
  for (const CaseSet& set : sets) set_order.push_back(set.name);
  for (const Solver& s : solvers) method_order.push_back(s.name());
  const std::map<std::string, std::string> defaults = {{"skipped", "0"}};
  try {
    StudyCsv csv(dir / "runtime_error.csv",
                 "method,scheme,bound,n,cells,case_set,calls,time_per_call_s,err_contact,"
                 "err_converged,err_contact_fx,err_contact_fy,skipped",
                 merge, only, defaults);
    char line[512];
    for (const CaseSet& full_set : sets) {
      for (const Solver& s : solvers) {
        if (!selected(s)) continue;
        int skipped = 0;
        const CaseSet set = s.method == tangential::Method::table
                                ? table_cases(full_set, kSteel, skipped)
                                : full_set;
        if (set.cases.empty()) {
          std::cerr << s.name() << " " << set.name << ": no case covered, no row\n";
          continue;
        }
        std::vector<Forces> conv;
        if (s.fastsim()) {
          double spread = 0;
          conv = converged(s, set, n_fine, spread);
          std::fprintf(
              stderr,
              "%-20s %-13s %-10s converged answer within %.2e (Richardson %d/%d vs %d/%d)\n",
              s.name().c_str(), s.scheme().c_str(), set.name.c_str(), spread, n_fine / 2, n_fine,
              n_fine / 4, n_fine / 2);
        } else if (s.exact()) {
          tangential::TangentialSolution unused;
          const int failed = solve_all(s, n_exact_reference, set, conv, unused);
          std::fprintf(stderr, "%-20s %-13s %-10s reference answer: %d x %d (%d not converged)\n",
                       s.name().c_str(), s.scheme().c_str(), set.name.c_str(), n_exact_reference,
                       n_exact_reference, failed);
        }
        const std::vector<int> grids =
            s.fastsim() ? plot_grids : (s.exact() ? exact_grids : std::vector<int>{0});
        for (const int n : grids) {
          std::vector<Forces> f;
          tangential::TangentialSolution solution;
          const int failed = solve_all(s, n, set, f, solution);
          if (failed > 0)
            std::fprintf(stderr, "%s n = %d %s: %d solves not converged (last iterate used)\n",
                         s.name().c_str(), n, set.name.c_str(), failed);
          const Errors e = errors(set, f, s.grid() ? &conv : nullptr);
          const double t = time_per_call(s, n, set);
          std::snprintf(line, sizeof line, "%s,%s,%s,%d,%d,%s,%zu,%.4g,%.6g,%.6g,%.6g,%.6g,%d",
                        s.name().c_str(), s.scheme().c_str(), s.bound().c_str(), n, n * n,
                        set.name.c_str(), set.cases.size(), t, e.contact, e.converged, e.contact_fx,
                        e.contact_fy, skipped);
          csv.add(line);
          std::cerr << line << "\n";
        }
      }
    }
    csv.write({{"case_set", set_order}, {"method", method_order}});

    // Part 2: the error model of every FASTSIM method, scheme and bound (pure spin, untimed);
    // with --methods only for the FASTSIM methods listed, and not at all when there is none.
    std::vector<std::pair<tangential::TractionBound, Solver>> fits;
    for (const auto bound :
         {tangential::TractionBound::parabolic, tangential::TractionBound::semi_elliptic})
      for (const Solver& s : fastsim_solvers(bound, true))
        if (selected(s)) fits.emplace_back(bound, s);
    if (fits.empty()) return 0;
    StudyCsv fit(dir / "grid_error_fit.csv", "method,scheme,bound,n,err_converged", merge, only,
                 defaults);
    StudyCsv constants(dir / "grid_error_constants.csv",
                       "method,scheme,bound,order,n_min,C,C_n100_200,n_at_max", merge, only,
                       defaults);
    const CaseSet& spin = sets.front();
    for (const auto& [bound, s] : fits) {
      double spread = 0;
      const std::vector<Forces> conv = converged(s, spin, n_fit_fine, spread);
      std::fprintf(stderr, "fit %s %s %s: converged answer within %.2e\n", s.name().c_str(),
                   s.scheme().c_str(), s.bound().c_str(), spread);
      double c_all = 0, c_fine = 0;
      int n_at_max = 0;
      std::vector<Forces> f;
      tangential::TangentialSolution solution;
      for (const int n : fit_grids) {
        solve_all(s, n, spin, f, solution);
        const double e = errors(spin, f, &conv).converged;
        const double scaled = e * std::pow(static_cast<double>(n), s.order());
        if (n >= s.min_fit_n() && scaled > c_all) {
          c_all = scaled;
          n_at_max = n;
        }
        if (n >= 100 && n <= 200) c_fine = std::max(c_fine, scaled);
        std::snprintf(line, sizeof line, "%s,%s,%s,%d,%.6g", s.name().c_str(), s.scheme().c_str(),
                      s.bound().c_str(), n, e);
        fit.add(line);
      }
      std::snprintf(line, sizeof line, "%s,%s,%s,%g,%d,%.4g,%.4g,%d", s.name().c_str(),
                    s.scheme().c_str(), s.bound().c_str(), s.order(), s.min_fit_n(), c_all, c_fine,
                    n_at_max);
      constants.add(line);
      std::cerr << "fit " << line << "\n";
    }
    const std::vector<std::string> bound_order = {"parabolic", "semi-elliptic"};
    fit.write({{"bound", bound_order}, {"method", method_order}});
    constants.write({{"bound", bound_order}, {"method", method_order}});
  } catch (const std::exception& error) {
    std::cerr << "wheelwear_runtime_error_study: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
