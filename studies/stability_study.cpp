// Stability study: the random sweep of tests/wear/stress_test.cpp over many more cases, every
// tangential method and both wear laws, writing each case and its invariant margins to a CSV
// file ordered worst first, and a summary of the worst margin of each invariant.
//
// Usage: wheelwear_stability_study SEED COUNT [OUTPUT.csv]
//   SEED    seed of the random cases (the unit test uses 20261122)
//   COUNT   number of cases
//   OUTPUT  CSV file to write (default stability_study.csv)
// Columns (inputs to all 17 digits, so that a row can be rerun): the case (method, grid, a_m, b_m,
// psi, vx, vy, phi_per_m, N_N, mu, nu, mixture), its margins (force_ratio = |F|/(mu N),
// sliding_ratio = |F| over the full-sliding force on the same grid, quadrature = that force's
// relative error against mu N, lipschitz and its input, monotone_drop, wear_imbalance,
// wear_negative, finite), exception (text of any exception thrown) and severity = the largest
// margin over its limit (above 1: the case breaks an invariant).

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <random>
#include <string>
#include <vector>

#include "wear/stability_sweep.hpp"

namespace {

using namespace wheelwear::wear;
using namespace wheelwear::tangential;

struct Row {
  stability::Case c;
  stability::Margins m;
  std::string exception;
  double severity = 0.0;
};

double severity(const stability::Margins& m, const stability::Case& c,
                const stability::Limits& limits) {
  const bool second_order =
      c.method == stability::Method::fastsim && c.options.scheme == FastsimScheme::second_order;
  const double force_excess = c.method == stability::Method::she_sdec
                                  ? (m.force_ratio - 1) / 1e-12
                                  : (m.force_ratio - 1) / limits.force_ratio_excess;
  const double sliding_excess =
      (m.sliding_ratio - 1) /
      (second_order ? limits.second_order_sliding_excess : limits.sliding_excess);
  return std::max(
      {m.finite ? 0.0 : 1e300, force_excess, sliding_excess, m.quadrature / limits.quadrature,
       m.lipschitz / (second_order ? limits.second_order_lipschitz : limits.lipschitz),
       m.monotone_drop / (second_order ? limits.second_order_drop : limits.monotone_drop),
       m.wear_imbalance / limits.wear_imbalance, m.wear_negative > 0 ? 1e300 : 0.0});
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s SEED COUNT [OUTPUT.csv]\n", argv[0]);
    return 2;
  }
  const auto seed = std::strtoull(argv[1], nullptr, 10);
  const long count = std::strtol(argv[2], nullptr, 10);
  const std::string output = argc > 3 ? argv[3] : "stability_study.csv";
  if (count <= 0) {
    std::fprintf(stderr, "COUNT = %s: must be a positive number of cases\n", argv[2]);
    return 2;
  }

  std::mt19937_64 rng(seed);
  const stability::Ranges ranges;
  const stability::Limits limits;
  std::vector<Row> rows;
  rows.reserve(static_cast<std::size_t>(count));
  for (long n = 0; n < count; ++n) {
    std::array<double, 3> direction{};
    Row row{stability::random_case(rng, ranges, direction), {}, {}, 0.0};
    try {
      row.m = stability::check(row.c, direction, limits);
      row.severity = severity(row.m, row.c, limits);
    } catch (const std::exception& e) {
      row.exception = e.what();
      row.severity = 1e300;
    }
    rows.push_back(std::move(row));
  }
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Row& a, const Row& b) { return a.severity > b.severity; });

  std::FILE* out = std::fopen(output.c_str(), "w");
  if (!out) {
    std::fprintf(stderr, "%s: cannot write there\n", output.c_str());
    return 1;
  }
  std::fprintf(out,
               "severity,method,nx,ny,a_m,b_m,psi,vx,vy,phi_per_m,N_N,mu,nu,mixture,finite,"
               "force_ratio,sliding_ratio,quadrature,lipschitz,lipschitz_input,monotone_drop,"
               "wear_imbalance,wear_negative,exception\n");
  int failing = 0;
  stability::Margins worst;
  for (const Row& r : rows) {
    const stability::Case& c = r.c;
    failing += r.severity > 1.0;
    worst.force_ratio = std::max(worst.force_ratio, r.m.force_ratio);
    worst.sliding_ratio = std::max(worst.sliding_ratio, r.m.sliding_ratio);
    worst.quadrature = std::max(worst.quadrature, r.m.quadrature);
    worst.lipschitz = std::max(worst.lipschitz, r.m.lipschitz);
    worst.monotone_drop = std::max(worst.monotone_drop, r.m.monotone_drop);
    worst.wear_imbalance = std::max(worst.wear_imbalance, r.m.wear_imbalance);
    std::string exception = r.exception;
    std::replace(exception.begin(), exception.end(), ',', ';');
    std::fprintf(out, "%.6g,%s,%d,%d,", r.severity, stability::case_method_name(c).c_str(),
                 c.options.nx, c.options.ny);
    std::fprintf(out, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s,", c.patch.a,
                 c.patch.b, c.patch.psi, c.creepages.vx, c.creepages.vy, c.creepages.phi, c.load.N,
                 c.load.mu, c.material.nu,
                 std::string(stability::kMixtureNames[static_cast<int>(c.mixture)]).c_str());
    std::fprintf(out, "%d,%.9g,%.12g,%.6g,%.6g,%s,%.6g,%.6g,%.6g,%s\n", r.m.finite ? 1 : 0,
                 r.m.force_ratio, r.m.sliding_ratio, r.m.quadrature, r.m.lipschitz,
                 r.m.worst_input.c_str(), r.m.monotone_drop, r.m.wear_imbalance, r.m.wear_negative,
                 exception.c_str());
  }
  std::fclose(out);
  std::printf(
      "%ld cases (seed %llu): %d break an invariant; worst |F|/(mu N) %.6g, |F|/B %.12g, bound "
      "quadrature %.3g, lipschitz %.4g, monotone drop %.3g mu N, wear imbalance %.3g; written to "
      "%s\n",
      count, static_cast<unsigned long long>(seed), failing, worst.force_ratio, worst.sliding_ratio,
      worst.quadrature, worst.lipschitz, worst.monotone_drop, worst.wear_imbalance, output.c_str());
  return failing == 0 ? 0 : 1;
}
