// The book of creep-force tables against fresh exact solves on its own grid (creep_table_grid),
// so that the difference is the table's own error:
//   - interpolation: POINTS points spread over the range it covers at every nu, the sequence
//     tests/tangential/creep_table_test.cpp draws its first 100 from, by band of a/b; and
//     where one nu's group reaches more slender patches than the others (a/b 10 ... 25 at
//     nu 0.25), POINTS more there, at that nu;
//   - beyond its creepages: POINTS points with r log-uniform in r_max ... 40, of
//     which the table answers those near full sliding (creep_table_forces): how many, and
//     their error.
// Writes per set the points drawn and answered, the worst and mean error in F (of mu N) and
// in Mz (of mu N c) and the worst point (bench/results/table_interpolation.csv).
//
// Usage: wheelwear_table_interpolation_study [POINTS (1000)] [THREADS (2)] [OUTPUT.csv]

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "support/creep_table_points.hpp"

namespace {

using wheelwear::testing::creep_table::Point;
using wheelwear::testing::creep_table::TableError;

struct Band {
  const char* name;
  double lo, hi;  // a/b in [lo, hi)
  bool beyond;    // the points beyond r_max
};

// The table's regions: wide patches, round ones, the slender ones (nodes 6 ... 10) and the
// flank's (nodes 12 ... 25); and beyond r_max.
constexpr Band kBands[] = {{"a/b 0.2-1", 0.0, 1.0, false},
                           {"a/b 1-5", 1.0, 5.0, false},
                           {"a/b 5-10", 5.0, 10.0, false},
                           {"a/b 10-25", 10.0, 1e9, false},
                           {"beyond r_max", 0.0, 1e9, true}};
constexpr double kBeyondTop = 40.0;  // r of the farthest points beyond r_max

std::string describe(const Point& p) {
  char text[200];
  std::snprintf(text, sizeof text, "a/b %.4g psi %.3f nu %.4f vx %.3e vy %.3e phi %.3e",
                p.sdec.ellipticity(), p.sdec.psi, p.material.nu, p.creepages.vx, p.creepages.vy,
                p.creepages.phi);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::stoi(argv[1]) : 1000;
  const unsigned threads = argc > 2 ? static_cast<unsigned>(std::max(1, std::stoi(argv[2]))) : 2;
  const std::string out_path =
      argc > 3 ? argv[3] : std::string(WHEELWEAR_RESULTS) + "/table_interpolation.csv";
  if (count < 1) {
    std::cerr << "POINTS must be at least 1\n";
    return 2;
  }

  // Inside: the test's sequence. Beyond: a sequence of its own, the points the table answers.
  wheelwear::testing::creep_table::PointSequence sequence, beyond_sequence(54321);
  std::vector<Point> points;
  std::vector<char> beyond;
  for (int i = 0; i < count; ++i) {
    points.push_back(sequence.next());
    beyond.push_back(0);
  }
  // Slender: a sequence of its own over the a/b a group reaches beyond the others' (the flank's
  // patches, tabulated at one nu first), at that group's nu.
  namespace tangential = wheelwear::tangential;
  const tangential::CreepTableRange common = tangential::creep_table_range();
  for (const double nu : {common.nu_min, common.nu_max}) {
    const tangential::CreepTableRange at_nu = tangential::creep_table_range(nu);
    if (at_nu.a_over_b_max <= common.a_over_b_max) continue;
    wheelwear::testing::creep_table::PointSequence slender(777);
    for (int i = 0; i < count; ++i) {
      points.push_back(
          slender.next({common.a_over_b_max, at_nu.a_over_b_max, nu, nu, at_nu.r_max}));
      beyond.push_back(0);
    }
  }
  const double r_top = std::max(kBeyondTop, 2 * wheelwear::tangential::creep_table_range().r_max);
  int drawn_beyond = 0;
  for (int i = 0; i < count; ++i) {
    const Point p = beyond_sequence.next_beyond(r_top);
    const auto& load = wheelwear::testing::creep_table::kLoad;
    // Drawn with Kalker's C's: the table's own magnitude decides whether a point lies beyond.
    if (wheelwear::tangential::creep_table_magnitude(p.sdec, p.creepages, load, p.material) <=
        wheelwear::tangential::creep_table_range().r_max)
      continue;
    ++drawn_beyond;
    if (!wheelwear::tangential::creep_table_covers(p.sdec, p.creepages, load, p.material)) continue;
    points.push_back(p);
    beyond.push_back(1);
  }
  std::vector<TableError> errors(points.size());
  std::atomic<std::size_t> next{0};
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (std::size_t i = next++; i < points.size(); i = next++)
        errors[i] = wheelwear::testing::creep_table::table_error(points[i]);
    });
  for (auto& t : pool) t.join();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::ofstream out(out_path);
  out << "set,points_drawn,points_answered,unconverged,worst_F_muN,mean_F_muN,worst_Mz_muNc,"
         "mean_Mz_muNc,worst_point,seconds\n";
  int unconverged_total = 0;
  for (const Band& band : kBands) {
    int n = 0, unconverged = 0;
    double worst = 0, sum = 0, worst_moment = 0, sum_moment = 0;
    std::string worst_point;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double g = points[i].sdec.ellipticity();
      if ((beyond[i] != 0) != band.beyond || g < band.lo || g >= band.hi) continue;
      const TableError& e = errors[i];
      if (e.status != wheelwear::tangential::ExactStatus::converged) {
        ++unconverged;
        continue;
      }
      ++n;
      sum += e.force;
      sum_moment += e.moment;
      if (e.force > worst) {
        worst = e.force;
        worst_point = describe(points[i]);
      }
      worst_moment = std::max(worst_moment, e.moment);
    }
    unconverged_total += unconverged;
    const int drawn = band.beyond ? drawn_beyond : n + unconverged;
    out << band.name << ',' << drawn << ',' << n << ',' << unconverged << ',' << worst << ','
        << (n ? sum / n : 0.0) << ',' << worst_moment << ',' << (n ? sum_moment / n : 0.0) << ','
        << worst_point << ',' << seconds << '\n';
    std::printf(
        "%-13s %4d of %4d points: F worst %.4f mean %.4f of mu N; Mz worst %.4f mean %.4f of "
        "mu N c; worst at %s\n",
        band.name, n, drawn, worst, n ? sum / n : 0.0, worst_moment, n ? sum_moment / n : 0.0,
        worst_point.c_str());
  }
  std::printf("%zu points in %.0f s on %u threads (%d exact solves not converged) -> %s\n",
              points.size(), seconds, threads, unconverged_total, out_path.c_str());
  return unconverged_total == 0 ? 0 : 1;
}
