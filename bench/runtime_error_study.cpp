// Run time against error of every tangential method, on CONTACT's reference cases.
//
//   wheelwear_runtime_error_study [RESULTS_DIR] [--quick]
//
// writes to RESULTS_DIR (default: the current directory)
//
// * runtime_error.csv: one row per method, scheme, grid and case set, with the time per call and
//   the error against Kalker's exact theory (CONTACT) and against the method's own converged
//   answer. Columns:
//     method          the --method name of `wheelwear creep`
//     scheme          kalker | second-order (FASTSIM marching); none for the grid-free methods
//     bound           parabolic (Eq. 18 of Liu, Fu & Bruni 2022) | none
//     n               the grid is n x n cells (nx = ny = n); 0 for the grid-free methods
//     cells           n*n
//     case_set        pure_spin: the 17 cases phi > 0 of tests/data/contact/b_pure_spin_mx80.csv
//                     (g = 1, psi = 0.6 with phi = 0.2 ... 1.6 1/m, and phi = 1 1/m with
//                     psi = -0.8 ... 0.8); linear: the 90 patches of a_linear_coeffs_mx80.csv
//                     (g = 0.1 ... 10, psi = -0.8 ... 0.8), each with CONTACT's three unit
//                     creepages (vx = 1e-6, vy = 1e-6, phi = 1e-6/c), 270 calls
//     calls           solver calls in one pass over the set
//     time_per_call_s the smallest, over 15 repetitions, of the mean time of one call in a
//                     loop over the set repeated for at least 3 ms, in CPU time of the thread
//                     (one thread; the solution object is reused, as a simulation loop would)
//     err_contact     pure_spin: largest |F - F_CONTACT|/(mu N) over the cases and over Fx, Fy;
//                     linear: largest |F - F_CONTACT|/|F_CONTACT| (force vectors (Fx, Fy)) over
//                     the patches and the three creepages
//     err_converged   the same measure against the method's own converged answer (0 for the
//                     grid-free methods)
//     err_contact_fx, err_contact_fy
//                     err_contact of each force component alone (same normaliser: mu N, or
//                     |F_CONTACT| for the linear set)
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
// The converged answer is the Richardson extrapolation F(1600) + (F(1600) - F(800))/(2^p - 1)
// of the same method and scheme; its own error is estimated by the difference from the
// extrapolation of 400 and 800 and printed on stderr.
//
// --quick uses fewer grids and converged grids of 200/400 (for a smoke run, not for the
// results).
//
// Regenerate the committed results with
//   cmake --build build --target wheelwear_runtime_error_study
//   build/bench/wheelwear_runtime_error_study bench/results
//   /usr/bin/python3 scripts/plot_runtime_error.py bench/results/runtime_error.csv
//       bench/results/runtime_error.png

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
#include <string>
#include <vector>

#include "support/csv_table.hpp"
#include "wheelwear/wear/fastsim.hpp"
#include "wheelwear/wear/linear_theory.hpp"

namespace {

using namespace wheelwear;
using wheelwear::testing::CsvTable;
using wheelwear::testing::test_data;

const wear::Material kSteel{80e9, 0.25};  // CONTACT: GG = 80 000 N/mm^2, POISS = 0.25

/// One solver call with CONTACT's answer.
struct Case {
  contactgeom::Sdec patch;
  wear::Creepages creepages;
  wear::ContactLoad load;
  double fx_ref = 0, fy_ref = 0;  ///< CONTACT's forces [N]
};

enum class Measure {
  max_component_over_mu_n,  ///< max(|dFx|, |dFy|)/(mu N)
  vector_relative,          ///< |dF|/|F_ref|
};

struct CaseSet {
  std::string name;
  Measure measure;
  std::vector<Case> cases;
};

CaseSet pure_spin_cases() {
  CaseSet set{"pure_spin", Measure::max_component_over_mu_n, {}};
  const CsvTable table(test_data("contact/b_pure_spin_mx80.csv"));
  for (const auto& row : table.rows()) {
    const double phi = row.number("phi_per_m");
    if (phi == 0.0) continue;
    set.cases.push_back({{row.number("a_mm") * 1e-3, row.number("b_mm") * 1e-3, row.number("psi")},
                         {0, 0, phi},
                         {row.number("N_N"), row.number("mu")},
                         row.number("Fx_N"),
                         row.number("Fy_N")});
  }
  return set;
}

// CONTACT's linear coefficients turned back into the forces of its unit creepages (README of
// tests/data/contact, section 3: C11s = -Fx(dvx)/(G c^2 dvx), C13s = -Fx(dphi)/(G c^3 dphi), ...).
CaseSet linear_cases() {
  CaseSet set{"linear", Measure::vector_relative, {}};
  const CsvTable table(test_data("contact/a_linear_coeffs_mx80.csv"));
  for (const auto& row : table.rows()) {
    const contactgeom::Sdec patch{row.number("a_mm") * 1e-3, row.number("b_mm") * 1e-3,
                                  row.number("psi")};
    const wear::ContactLoad load{row.number("N_N"), 0.35};
    const double c = std::sqrt(patch.a * patch.b), g = kSteel.G;
    const double dv = row.number("dvx_dvy"), dphi = row.number("dphi_per_m");
    const double c2 = g * c * c, c3 = g * c * c * c;
    set.cases.push_back(
        {patch, {dv, 0, 0}, load, -c2 * row.number("C11s") * dv, -c2 * row.number("C21s") * dv});
    set.cases.push_back(
        {patch, {0, dv, 0}, load, -c2 * row.number("C12s") * dv, -c2 * row.number("C22s") * dv});
    set.cases.push_back({patch,
                         {0, 0, dphi},
                         load,
                         -c3 * row.number("C13s") * dphi,
                         -c3 * row.number("C23s") * dphi});
  }
  return set;
}

// The set's normaliser: mu N, or the size of CONTACT's force.
double scale(Measure measure, const Case& c) {
  return measure == Measure::max_component_over_mu_n ? c.load.mu * c.load.N
                                                     : std::hypot(c.fx_ref, c.fy_ref);
}

double case_error(Measure measure, const Case& c, double fx, double fy, double fx_ref,
                  double fy_ref) {
  if (measure == Measure::max_component_over_mu_n)
    return std::max(std::abs(fx - fx_ref), std::abs(fy - fy_ref)) / scale(measure, c);
  return std::hypot(fx - fx_ref, fy - fy_ref) / scale(measure, c);
}

/// A tangential method with its discretisation; n = 0 for the grid-free ones.
struct Solver {
  std::string method;
  std::string scheme;  // "kalker", "second-order", "none"
  std::string bound;   // "parabolic", "semi-elliptic", "none"
  bool grid = true;
  wear::FastsimMethod fastsim_method = wear::FastsimMethod::sdec;
  wear::FastsimScheme fastsim_scheme = wear::FastsimScheme::kalker;
  wear::TractionBound traction_bound = wear::TractionBound::parabolic;
  // Order of convergence in n: Kalker's scheme is first order. The second-order scheme is
  // second order with the parabolic bound; with the semi-elliptic bound, whose slope is
  // unbounded at the leading and trailing edges, it reaches only 1.5 (measured: e(n) n^2 grows
  // about 2 times from n = 200 to 1000, e(n) n^1.5 changes by about 10 %).
  double order() const {
    if (fastsim_scheme == wear::FastsimScheme::kalker) return 1.0;
    return traction_bound == wear::TractionBound::parabolic ? 2.0 : 1.5;
  }
  // The smallest grid the error model is fitted from: below it the second-order scheme is not
  // yet in its asymptotic range (its e(n) n^p peaks at n = 6 at up to 10 times its value at
  // n = 100 ... 1000), and a model fitted there would ask for needlessly fine grids.
  int min_fit_n() const {
    if (fastsim_scheme == wear::FastsimScheme::kalker) return 5;
    return traction_bound == wear::TractionBound::parabolic ? 10 : 20;
  }
};

struct Forces {
  double fx = 0, fy = 0;
};

/// Calls the solver on every case; `solution` is reused between calls.
void solve_all(const Solver& s, int n, const CaseSet& set, std::vector<Forces>& out,
               wear::TangentialSolution& solution) {
  out.resize(set.cases.size());
  wear::FastsimOptions options;
  options.nx = options.ny = std::max(n, 1);
  options.scheme = s.fastsim_scheme;
  options.bound = s.traction_bound;
  for (std::size_t k = 0; k < set.cases.size(); ++k) {
    const Case& c = set.cases[k];
    if (!s.grid) {
      const wear::CreepForces f = s.method == "linear-sdec"
                                      ? wear::linear_sdec_forces(c.patch, c.creepages, kSteel)
                                      : wear::she_sdec_forces(c.patch, c.creepages, kSteel, c.load);
      out[k] = {f.Fx, f.Fy};
    } else {
      wear::fastsim(s.fastsim_method, c.patch, c.creepages, c.load, kSteel, options, solution);
      out[k] = {solution.forces.Fx, solution.forces.Fy};
    }
  }
}

/// CPU time of the calling thread [s]: unlike wall time it does not count the time the thread
/// waits while other processes run on a shared machine.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Smallest mean time per call over 15 repetitions of >= 3 ms each.
double time_per_call(const Solver& s, int n, const CaseSet& set) {
  std::vector<Forces> out;
  wear::TangentialSolution solution;
  solve_all(s, n, set, out, solution);  // warm-up: the grid storage is allocated here
  double best = 1e300;
  volatile double sink = 0;
  for (int rep = 0; rep < 15; ++rep) {
    long passes = 0;
    const double start = thread_seconds();
    double elapsed = 0;
    do {
      solve_all(s, n, set, out, solution);
      sink = sink + out.front().fx;
      ++passes;
      elapsed = thread_seconds() - start;
    } while (elapsed < 3e-3);
    best = std::min(best, elapsed / static_cast<double>(passes * set.cases.size()));
  }
  return best;
}

/// The converged answer of a grid solver: Richardson extrapolation of n_fine/2 and n_fine.
/// `spread` receives the largest difference (in the set's measure) from the extrapolation of
/// n_fine/4 and n_fine/2.
std::vector<Forces> converged(const Solver& s, const CaseSet& set, int n_fine, double& spread) {
  std::vector<Forces> f1, f2, f4;
  wear::TangentialSolution solution;
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

struct Errors {
  double contact = 0, converged = 0;
  double contact_fx = 0, contact_fy = 0;  // each component alone, same normaliser
};

Errors errors(const CaseSet& set, const std::vector<Forces>& f, const std::vector<Forces>* conv) {
  Errors e;
  for (std::size_t k = 0; k < set.cases.size(); ++k) {
    const Case& c = set.cases[k];
    e.contact =
        std::max(e.contact, case_error(set.measure, c, f[k].fx, f[k].fy, c.fx_ref, c.fy_ref));
    e.contact_fx = std::max(e.contact_fx, std::abs(f[k].fx - c.fx_ref) / scale(set.measure, c));
    e.contact_fy = std::max(e.contact_fy, std::abs(f[k].fy - c.fy_ref) / scale(set.measure, c));
    if (conv)
      e.converged = std::max(
          e.converged, case_error(set.measure, c, f[k].fx, f[k].fy, (*conv)[k].fx, (*conv)[k].fy));
  }
  return e;
}

std::vector<Solver> fastsim_solvers(wear::TractionBound bound, bool every_scheme) {
  const std::string bound_name =
      bound == wear::TractionBound::parabolic ? "parabolic" : "semi-elliptic";
  std::vector<Solver> solvers;
  for (const auto method :
       {wear::FastsimMethod::elliptic, wear::FastsimMethod::eqe, wear::FastsimMethod::eqe_shifted,
        wear::FastsimMethod::eql, wear::FastsimMethod::sdec}) {
    for (const auto scheme : {wear::FastsimScheme::kalker, wear::FastsimScheme::second_order}) {
      const bool second = scheme == wear::FastsimScheme::second_order;
      if (second && !every_scheme && method != wear::FastsimMethod::sdec) continue;
      solvers.push_back({std::string(wear::method_name(method)), second ? "second-order" : "kalker",
                         bound_name, true, method, scheme, bound});
    }
  }
  return solvers;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path dir = ".";
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--quick") {
      quick = true;
    } else {
      dir = arg;
    }
  }
  std::filesystem::create_directories(dir);
  const int n_fine = quick ? 400 : 1600;
  const std::vector<int> plot_grids =
      quick ? std::vector<int>{5, 10, 20, 40, 80}
            : std::vector<int>{5, 7, 10, 14, 20, 28, 40, 56, 80, 113, 160, 200};
  // Part 2's grids: every n up to 200, then sparser up to the largest grid grid_choice.hpp
  // allows (1000), against a converged answer from 1600 and 3200.
  std::vector<int> fit_grids;
  for (int n = 5; n <= (quick ? 40 : 200); ++n) fit_grids.push_back(n);
  if (!quick)
    for (const int n : {250, 300, 400, 500, 600, 800, 1000}) fit_grids.push_back(n);
  const int n_fit_fine = quick ? 400 : 3200;

  const std::vector<CaseSet> sets = {pure_spin_cases(), linear_cases()};

  // Part 1: the plotted methods, timed, on both case sets.
  std::vector<Solver> solvers = {
      {"linear-sdec", "none", "none", false},
      {"she-sdec", "none", "none", false},
  };
  for (const Solver& s : fastsim_solvers(wear::TractionBound::parabolic, false))
    solvers.push_back(s);

  std::ofstream csv(dir / "runtime_error.csv");
  csv << "method,scheme,bound,n,cells,case_set,calls,time_per_call_s,err_contact,err_converged,"
         "err_contact_fx,err_contact_fy\n";
  char line[512];
  for (const CaseSet& set : sets) {
    for (const Solver& s : solvers) {
      std::vector<Forces> conv;
      if (s.grid) {
        double spread = 0;
        conv = converged(s, set, n_fine, spread);
        std::fprintf(stderr,
                     "%-20s %-13s %-10s converged answer within %.2e (Richardson %d/%d vs %d/%d)\n",
                     s.method.c_str(), s.scheme.c_str(), set.name.c_str(), spread, n_fine / 2,
                     n_fine, n_fine / 4, n_fine / 2);
      }
      for (const int n : s.grid ? plot_grids : std::vector<int>{0}) {
        std::vector<Forces> f;
        wear::TangentialSolution solution;
        solve_all(s, n, set, f, solution);
        const Errors e = errors(set, f, s.grid ? &conv : nullptr);
        const double t = time_per_call(s, n, set);
        std::snprintf(line, sizeof line, "%s,%s,%s,%d,%d,%s,%zu,%.4g,%.6g,%.6g,%.6g,%.6g\n",
                      s.method.c_str(), s.scheme.c_str(), s.bound.c_str(), n, n * n,
                      set.name.c_str(), set.cases.size(), t, e.contact, e.converged, e.contact_fx,
                      e.contact_fy);
        csv << line;
        std::cerr << line;
      }
    }
  }

  // Part 2: the error model of every FASTSIM method, scheme and bound (pure spin, untimed).
  std::ofstream fit(dir / "grid_error_fit.csv");
  std::ofstream constants(dir / "grid_error_constants.csv");
  fit << "method,scheme,bound,n,err_converged\n";
  constants << "method,scheme,bound,order,n_min,C,C_n100_200,n_at_max\n";
  const CaseSet& spin = sets.front();
  for (const auto bound : {wear::TractionBound::parabolic, wear::TractionBound::semi_elliptic}) {
    for (const Solver& s : fastsim_solvers(bound, true)) {
      double spread = 0;
      const std::vector<Forces> conv = converged(s, spin, n_fit_fine, spread);
      std::fprintf(stderr, "fit %s %s %s: converged answer within %.2e\n", s.method.c_str(),
                   s.scheme.c_str(), s.bound.c_str(), spread);
      double c_all = 0, c_fine = 0;
      int n_at_max = 0;
      std::vector<Forces> f;
      wear::TangentialSolution solution;
      for (const int n : fit_grids) {
        solve_all(s, n, spin, f, solution);
        const double e = errors(spin, f, &conv).converged;
        const double scaled = e * std::pow(static_cast<double>(n), s.order());
        if (n >= s.min_fit_n() && scaled > c_all) {
          c_all = scaled;
          n_at_max = n;
        }
        if (n >= 100 && n <= 200) c_fine = std::max(c_fine, scaled);
        std::snprintf(line, sizeof line, "%s,%s,%s,%d,%.6g\n", s.method.c_str(), s.scheme.c_str(),
                      s.bound.c_str(), n, e);
        fit << line;
      }
      std::snprintf(line, sizeof line, "%s,%s,%s,%g,%d,%.4g,%.4g,%d\n", s.method.c_str(),
                    s.scheme.c_str(), s.bound.c_str(), s.order(), s.min_fit_n(), c_all, c_fine,
                    n_at_max);
      constants << line;
      std::cerr << "fit " << line;
    }
  }
  return 0;
}
