// Generates the SDEC coefficients K13, B11, B22, B23 of Liu, Fu & Bruni 2022 (Table 1) for
// several Poisson's ratios with Kalker's exact theory (wear/exact), fitted as CONTACT's
// reference data and the paper's Table 1 were: at each a/b the no-slip coefficients
// C11s = -Fx/(G c^2 vx), C22s = -Fy/(G c^2 vy), C23s = -Fy/(G c^3 phi), C13s = -Fx/(G c^3 phi)
// (Eq. 9, creepages at O) are computed for psi = 0, 0.2, 0.4, 0.6, 0.8 on an n x n grid over
// the patch (CONTACT's margin 1.02), then K13 by least squares of C13s = -K13 psi and each B
// by least squares of Cs(psi) - Cs(0) = B psi^2 over psi = 0.2 ... 0.8 (negative psi give the
// same equations by symmetry).
//
// Writes the CSV (default data/sdec_coefficients.csv) and the C++ table compiled into the
// library (default wear/src/sdec_coefficients_table.inc). Usage:
//   wheelwear_sdec_table_generator [--n 40] [--threads 2] [--csv FILE] [--cpp FILE]
// Rows: a/b = 0.1 ... 1.0 and b/a = 0.9 ... 0.1 (Table 1's rows); nu = 0, 0.25, 0.28, 0.3, 0.5.

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "wheelwear/wear/exact/steady_rolling.hpp"

namespace {

using namespace wheelwear;

constexpr std::array<double, 5> kNu = {0.0, 0.25, 0.28, 0.3, 0.5};
constexpr std::array<double, 4> kPsi = {0.2, 0.4, 0.6, 0.8};

struct Row {
  double nu = 0, a_over_b = 0;
  std::string label;
  double k13 = 0, b11 = 0, b22 = 0, b23 = 0;
  double c11 = 0, c22 = 0, c23 = 0;  // the grid's own psi = 0 coefficients (for the record)
};

struct Linear {
  double c11, c22, c23, c13;
};

Linear sdec_linear(double a_over_b, double psi, double nu, int n) {
  const double a = 4.25e-3, b = a / a_over_b, c = std::sqrt(a * b), creep = 1e-6;
  const wear::Material material{80e9, nu};
  const wear::ContactLoad load{1e4, 1e6};  // friction large enough that nothing slips
  wear::ExactOptions options;
  options.nx = options.ny = n;
  const contactgeom::Sdec patch{a, b, psi};
  const auto fx = wear::exact_sdec(patch, {creep, 0, 0}, load, material, options);
  const auto fy = wear::exact_sdec(patch, {0, creep, 0}, load, material, options);
  const auto fs = wear::exact_sdec(patch, {0, 0, creep / c}, load, material, options);
  for (const auto* s : {&fx, &fy, &fs}) {
    if (s->status != wear::ExactStatus::converged || s->slip_elements != 0) {
      std::cerr << "not converged or slipping at a/b " << a_over_b << " psi " << psi << ": "
                << s->message << '\n';
      std::exit(1);
    }
  }
  const double gc2 = material.G * c * c * creep;
  return {-fx.forces.Fx / gc2, -fy.forces.Fy / gc2, -fs.forces.Fy / gc2, -fs.forces.Fx / gc2};
}

void fit(Row& row, int n) {
  const Linear base = sdec_linear(row.a_over_b, 0.0, row.nu, n);
  double k13 = 0, b11 = 0, b22 = 0, b23 = 0, s2 = 0, s4 = 0;
  for (const double psi : kPsi) {
    const Linear l = sdec_linear(row.a_over_b, psi, row.nu, n);
    k13 -= l.c13 * psi;
    b11 += (l.c11 - base.c11) * psi * psi;
    b22 += (l.c22 - base.c22) * psi * psi;
    b23 += (l.c23 - base.c23) * psi * psi;
    s2 += psi * psi;
    s4 += psi * psi * psi * psi;
  }
  row.k13 = k13 / s2;
  row.b11 = b11 / s4;
  row.b22 = b22 / s4;
  row.b23 = b23 / s4;
  row.c11 = base.c11;
  row.c22 = base.c22;
  row.c23 = base.c23;
}

std::string fixed(double v, int digits) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 40;
  unsigned threads = 2;
  std::string csv_path = "data/sdec_coefficients.csv";
  std::string cpp_path = "wear/src/sdec_coefficients_table.inc";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--n") {
      n = std::atoi(argv[i + 1]);
    } else if (key == "--threads") {
      threads = static_cast<unsigned>(std::max(1, std::atoi(argv[i + 1])));
    } else if (key == "--csv") {
      csv_path = argv[i + 1];
    } else if (key == "--cpp") {
      cpp_path = argv[i + 1];
    } else {
      std::cerr << "unknown option " << key << "; options: --n --threads --csv --cpp\n";
      return 2;
    }
  }
  if (n < 8) {
    std::cerr << "--n " << n << ": the grid needs at least 8 x 8 elements\n";
    return 2;
  }
  std::vector<Row> rows;
  for (const double nu : kNu) {
    for (int k = 1; k <= 10; ++k) rows.push_back({nu, k / 10.0, fixed(k / 10.0, 1)});
    for (int k = 9; k >= 1; --k) rows.push_back({nu, 10.0 / k, "1/" + fixed(k / 10.0, 1)});
  }
  const auto start = std::chrono::steady_clock::now();
  std::atomic<std::size_t> next{0};
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) {
    pool.emplace_back([&] {
      for (std::size_t i = next++; i < rows.size(); i = next++) fit(rows[i], n);
    });
  }
  for (auto& t : pool) t.join();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string how =
      "Kalker's exact theory (wheelwear wear/exact, exact_sdec) on SDEC patches with the "
      "prescribed pressure of Eq. 4, no slip (creepage 1e-6, mu = 1e6), " +
      std::to_string(n) + " x " + std::to_string(n) +
      " elements over [-1.02a, 1.02a] x [y0 - 1.02b, y0 + 1.02b]; K13 by least squares of "
      "C13s = -K13 psi, B11, B22, B23 by least squares of Cs(psi) - Cs(0) = B psi^2 over "
      "psi = 0.2, 0.4, 0.6, 0.8 (Liu, Fu & Bruni 2022, Eq. 9 and 12; Table 1's fit)";
  std::ofstream csv(csv_path);
  csv << "# SDEC coefficients K13, B11, B22, B23 (Liu, Fu & Bruni 2022, Table 1) for several\n"
      << "# Poisson's ratios, generated by bench/sdec_table_generator.cpp\n"
      << "# (target wheelwear_sdec_table_generator; rerun it to regenerate).\n"
      << "# Method: " << how << ".\n"
      << "# C11_grid, C22_grid, C23_grid: the grid's own coefficients of the ellipse (psi = 0),\n"
      << "# for reference; the library keeps Kalker's C11, C22, C23 (Kalker 1990, Table E.3).\n"
      << "# Rows a/b = 0.1 ... 1.0 and b/a = 0.9 ... 0.1 (g_label 1/0.9 ... 1/0.1) per nu.\n"
      << "nu,g_label,a_over_b,K13,B11,B22,B23,C11_grid,C22_grid,C23_grid\n";
  for (const Row& r : rows) {
    csv << fixed(r.nu, 2) << ',' << r.label << ',' << std::setprecision(6) << r.a_over_b << ','
        << fixed(r.k13, 4) << ',' << fixed(r.b11, 4) << ',' << fixed(r.b22, 4) << ','
        << fixed(r.b23, 4) << ',' << fixed(r.c11, 4) << ',' << fixed(r.c22, 4) << ','
        << fixed(r.c23, 4) << '\n';
  }
  std::ofstream cpp(cpp_path);
  cpp << "// Generated by bench/sdec_table_generator.cpp (--n " << n << "): the values of\n"
      << "// data/sdec_coefficients.csv. Rows per nu: a/b = 0.1 ... 1.0, then b/a = 0.9 ... 0.1.\n"
      << "// Do not edit: rerun the generator.\n"
      << "// clang-format off\n"
      << "constexpr int kGeneratedGrid = " << n << ";\n"
      << "constexpr std::array<double, " << kNu.size() << "> kGeneratedNu = {";
  for (std::size_t i = 0; i < kNu.size(); ++i) cpp << (i ? ", " : "") << fixed(kNu[i], 2);
  cpp << "};\n"
      << "constexpr std::array<std::array<SdecExtra, 19>, " << kNu.size()
      << "> kGeneratedRows = {{\n";
  for (std::size_t v = 0; v < kNu.size(); ++v) {
    cpp << "  {{  // nu = " << fixed(kNu[v], 2) << '\n';
    for (std::size_t k = 0; k < 19; ++k) {
      const Row& r = rows[v * 19 + k];
      cpp << "    {" << fixed(r.k13, 4) << ", " << fixed(r.b11, 4) << ", " << fixed(r.b22, 4)
          << ", " << fixed(r.b23, 4) << "},  // a/b = " << r.label << '\n';
    }
    cpp << "  }},\n";
  }
  cpp << "}};\n// clang-format on\n";
  std::cout << rows.size() << " rows on " << n << " x " << n << " grids in " << seconds << " s ("
            << threads << " threads) -> " << csv_path << ", " << cpp_path << '\n';
  return csv && cpp ? 0 : 1;
}
