// Generates the book of creep-force tables (data/creep_table.h5), in the spirit of Kalker's
// book of tables (Kalker 1996) and of Piotrowski, Liu & Bruni's KBTNH (2017): total creep
// forces of Kalker's exact theory (wear/exact, exact_sdec, the SDEC pressure of Liu, Fu &
// Bruni 2022, Eq. 4) over the SDEC parameters and normalised creepages, for a fixed nu.
//
// Parametrisation (the forces divided by mu N depend only on these, by the similarity of the
// exact theory):
//   a/b (interpolated in log a/b), psi >= 0 (psi < 0 is the mirror image y -> -y:
//   vy, phi, Fy change sign), and the normalised creepages
//     xi = G c^2 C11 vx / (mu N),  eta = G c^2 C22 vy / (mu N),  chi = s G c^3 C23 phi / (mu N)
//   with c = sqrt(ab) and Kalker's C11, C22, C23 of the ellipse a/b at nu (so that the linear
//   forces are about -xi and -(eta + chi/s)) and the spin scale s (default 3: spin saturates
//   the patch at about a third of the normalised creepage translation needs, so without it the
//   forces change steeply with direction near chi = 0), written as r (magnitude) and the
//   direction chi = r cos(theta), xi = r sin(theta) cos(beta), eta = r sin(theta) sin(beta), with
//   xi >= 0 (beta in [-pi/2, pi/2]): reversing all creepages reverses the forces.
// Stored: Fx/(mu N), Fy/(mu N) and the spin moment about O, Mz/(mu N c),
// [g][psi][theta][beta][r], r = 0 included (zero forces). Mz changes sign with Fy under both
// symmetries. Per direction node [g][psi][theta][beta] also the full-sliding limit of the three
// (full_sliding_sdec on the node's grid; Fx_sliding_muN ...), which the interpolation uses near
// full sliding (creep_table.cpp): no iteration, under a second for the whole table.
//
// Grid: n elements across the patch, elements at most --max-aspect (5) times as long as wide
// (aspect_sdec_grid): n x n up to a/b = 5, as the table was first made; beyond, elements no
// longer than at a/b = 5 (42 x 30 at a/b = 7, 60 x 30 at 10), where an n x n grid would lose
// accuracy along the long axis as the patch grows slender.
//
// Usage: wheelwear_creep_table_generator [--n 30] [--threads 2] [--out data/creep_table.h5]
//   [--nu 0.25,0.28] [--g 0.2,0.25,...] [--psi 0,0.2,...] [--theta-count 33] [--beta-count 19]
//   [--r 0,0.25,...,20] [--spin-scale 3] [--max-aspect 5] [--reuse OLD.h5,...]
//   or: wheelwear_creep_table_generator --add-sliding TABLE.h5 [--threads 2]
// --add-sliding writes (or rewrites) the full-sliding limits into an existing table in place,
// its forces untouched (how the shipped table, solved before the limits were stored, got them).
// --reuse OLD.h5[,OLDER.h5...] takes every node the files hold (the same nu, grid rule and spin
// scale, and each of the node's axis values among the file's) from the first that holds it
// instead of solving it again: to add nodes along any axis (a/b, psi, theta, beta, r) to a
// table, also one nu at a time (--nu 0.25 into one file, then both nu reusing it and the old
// table).
// The defaults are the shipped table: 2 x 1 003 200 nodes (898 320 solves per nu), about 90 min on
// two cores: 35 min for a/b 0.2 ... 5 and 37 min for 6 ... 10 with r up to 6, 10 min for r 7 ...
// 12 and 5 min for 14 ... 20 (solves near full sliding take fewer sweeps), 35 MB. The nodes are
// where interpolating (creep_table_interpolation.cpp) needs them to stay within 1 % of mu N of
// fresh solves (tests/tangential/creep_table_test.cpp; but for a corner of wide patches near full
// sliding, docs/validation.md): the forces turn fastest with theta where the patch begins to slide
// fully, and with a/b below 0.3 and above 3 (with nodes at 5, 7 and 10 alone the worst of the 190
// of 1000 test points beyond a/b = 5 reached 0.98 %). A finer solver grid (--n 40) or more nodes
// cost in proportion to their elements and sweeps (see the printed count): nodes at a/b
// 12, 14.5, 17.5, 21 and 25 (72 x 30 ... 150 x 30 elements) take 1.8 ... 6.4 times as long a solve
// as those at 8.5 (105 ... 187 sweeps against 85, on a sample of 96 creepages at r up to 5), about
// 111 min per nu on two cores where 6 and 8.5 took 8.6 min.

#include <hdf5.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "table_hdf5.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/kalker_coefficients.hpp"

namespace {

using namespace wheelwear;
using generators::checked;
using generators::Handle;
using generators::read_doubles;
using generators::read_number;
using generators::write;
using generators::write_attribute;

std::vector<double> parse_list(const std::string& text) {
  std::vector<double> out;
  std::stringstream in(text);
  std::string cell;
  while (std::getline(in, cell, ',')) out.push_back(std::stod(cell));
  return out;
}

std::vector<double> uniform(double lo, double hi, int count) {
  std::vector<double> out;
  for (int i = 0; i < count; ++i) out.push_back(lo + (hi - lo) * i / (count - 1));
  return out;
}

// The solved nodes of one nu block of an earlier table, to reuse where they are nodes of the new
// one too (same nu, grid rule and spin scale; each axis value of the node among the old axis's).
struct Reused {
  std::vector<double> gs, psis, thetas, betas, rs, fx, fy, mz;
  bool square_only = false;  // written before the grid rule: n x n nodes only
};

Reused reusable(const std::string& path, const char* group_name, double nu, int n,
                double max_aspect, double spin_scale) {
  Reused out;
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("--reuse: " + path + " is not an HDF5 file");
  if (H5Lexists(file, group_name, H5P_DEFAULT) > 0) {
    const hid_t group = H5Gopen2(file, group_name, H5P_DEFAULT);
    // A table written before the grid rule solved every node on n x n, which the rule gives
    // for a/b within [1/max_aspect, max_aspect] only.
    out.square_only = H5Aexists(group, "max_element_aspect") <= 0;
    const double old_aspect = read_number(group, "max_element_aspect", max_aspect);
    if (read_number(group, "nu", -1.0) == nu && read_number(group, "grid", 0) == n &&
        old_aspect == max_aspect && read_number(group, "spin_scale", 1.0) == spin_scale) {
      out.gs = read_doubles(group, "a_over_b");
      out.psis = read_doubles(group, "psi");
      out.thetas = read_doubles(group, "theta");
      out.betas = read_doubles(group, "beta");
      out.rs = read_doubles(group, "r");
      out.fx = read_doubles(group, "Fx_muN");
      out.fy = read_doubles(group, "Fy_muN");
      out.mz = read_doubles(group, "Mz_muNc");
      const std::size_t nodes =
          out.gs.size() * out.psis.size() * out.thetas.size() * out.betas.size() * out.rs.size();
      for (const auto* values : {&out.fx, &out.fy, &out.mz})
        if (values->size() != nodes) out.gs.clear();  // not a whole table: reuse nothing
    }
    H5Gclose(group);
  }
  H5Fclose(file);
  return out;
}

// For each value of `now`, its index in `old` (equal within 1e-12, relative above 1), or -1.
std::vector<long> indices_in(const std::vector<double>& old, const std::vector<double>& now) {
  std::vector<long> out(now.size(), -1);
  for (std::size_t k = 0; k < now.size(); ++k)
    for (std::size_t m = 0; m < old.size(); ++m)
      if (std::abs(old[m] - now[k]) <= 1e-12 * std::max(1.0, std::abs(now[k])))
        out[k] = static_cast<long>(m);
  return out;
}

// The axes of the table being made.
struct Axes {
  std::vector<double> gs, psis, thetas, betas, rs;
};

// Copies into (fx, fy, mz) every node of `axes` that `old` holds and `reused` does not mark
// yet, and marks it; returns how many.
std::size_t copy_reused(const Reused& old, const Axes& axes, double max_aspect,
                        std::vector<double>& fx, std::vector<double>& fy, std::vector<double>& mz,
                        std::vector<char>& reused) {
  const std::vector<long> og = indices_in(old.gs, axes.gs), op = indices_in(old.psis, axes.psis),
                          ot = indices_in(old.thetas, axes.thetas),
                          ob = indices_in(old.betas, axes.betas), orr = indices_in(old.rs, axes.rs);
  const std::size_t n_r = axes.rs.size(), n_b = axes.betas.size(), n_t = axes.thetas.size(),
                    n_p = axes.psis.size();
  std::size_t copied = 0;
  for (std::size_t i = 0; i < reused.size(); ++i) {
    const std::size_t ir = i % n_r, ib = i / n_r % n_b, it = i / (n_r * n_b) % n_t,
                      ip = i / (n_r * n_b * n_t) % n_p, ig = i / (n_r * n_b * n_t * n_p);
    if (reused[i] || og[ig] < 0 || op[ip] < 0 || ot[it] < 0 || ob[ib] < 0 || orr[ir] < 0) continue;
    const double g = axes.gs[ig];
    if (old.square_only && !(g <= max_aspect && g >= 1.0 / max_aspect)) continue;
    const std::size_t from =
        (((static_cast<std::size_t>(og[ig]) * old.psis.size() + op[ip]) * old.thetas.size() +
          ot[it]) *
             old.betas.size() +
         ob[ib]) *
            old.rs.size() +
        orr[ir];
    fx[i] = old.fx[from];
    fy[i] = old.fy[from];
    mz[i] = old.mz[from];
    reused[i] = 1;
    ++copied;
  }
  return copied;
}

// Calls body(i) for i = 0 ... total - 1 on `threads` threads, each taking the next index; the
// first exception a call throws stops the others' taking and is rethrown after the join.
template <class Body>
void parallel_for(std::size_t total, unsigned threads, const Body& body) {
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> failed(threads);
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) {
    pool.emplace_back([&, t] {
      try {
        for (std::size_t i = next++; i < total; i = next++) body(i);
      } catch (...) {
        failed[t] = std::current_exception();
        next = total;
      }
    });
  }
  for (auto& t : pool) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

// Every node is solved at this load and shear modulus: the normalised forces do not depend on
// them (the similarity of the exact theory).
const tangential::ContactLoad kNodeLoad{1e4, 0.3};
constexpr double kNodeShear = 80e9;

// What maps a group's normalised creepages onto physical ones: Kalker's C11, C22, C23 at each
// of its a/b nodes and its spin scale.
struct Normalisation {
  std::vector<double> c11, c22, c23;
  double spin_scale = 1.0;
};

// The patch of node (ig, ip) (a = 5 mm) and the creepages of the normalised creepage
// (r, theta, beta) on it.
struct NodeProblem {
  contactgeom::Sdec patch;
  tangential::Creepages creepages;
};

NodeProblem node_problem(const Axes& axes, const Normalisation& k, std::size_t ig, std::size_t ip,
                         double r, double theta, double beta) {
  const double a = 5e-3, b = a / axes.gs[ig], c = std::sqrt(a * b);
  const double mu_n = kNodeLoad.mu * kNodeLoad.N, gc2 = kNodeShear * c * c;
  const double xi = r * std::sin(theta) * std::cos(beta);
  const double eta = r * std::sin(theta) * std::sin(beta);
  const double chi = r * std::cos(theta);
  return {{a, b, axes.psis[ip]},
          {xi * mu_n / (gc2 * k.c11[ig]), eta * mu_n / (gc2 * k.c22[ig]),
           chi * mu_n / (k.spin_scale * gc2 * c * k.c23[ig])}};
}

// The full-sliding limit (full_sliding_sdec) at every direction node [g][psi][theta][beta] of a
// group, normalised as its forces: the table's interpolation takes it out of its error near
// full sliding (creep_table.cpp). No iteration: a second on two threads for the whole table.
struct Sliding {
  std::vector<double> fx, fy, mz;
};

Sliding sliding_limits(const Axes& axes, const Normalisation& k, int n, double max_aspect,
                       unsigned threads) {
  const std::size_t n_b = axes.betas.size(), n_t = axes.thetas.size(), n_p = axes.psis.size();
  const std::size_t total = axes.gs.size() * n_p * n_t * n_b;
  Sliding out{std::vector<double>(total), std::vector<double>(total), std::vector<double>(total)};
  const double mu_n = kNodeLoad.mu * kNodeLoad.N;
  parallel_for(total, threads, [&](std::size_t i) {
    const std::size_t ib = i % n_b, it = i / n_b % n_t, ip = i / (n_b * n_t) % n_p,
                      ig = i / (n_b * n_t * n_p);
    // A unit normalised creepage: S depends on its direction alone.
    const NodeProblem p = node_problem(axes, k, ig, ip, 1.0, axes.thetas[it], axes.betas[ib]);
    const tangential::CreepForces s = tangential::full_sliding_sdec(
        p.patch, p.creepages, kNodeLoad, tangential::aspect_sdec_grid(p.patch, n, max_aspect));
    out.fx[i] = s.Fx / mu_n;
    out.fy[i] = s.Fy / mu_n;
    out.mz[i] = *s.Mz / (mu_n * p.patch.c());
  });
  return out;
}

void write_sliding(hid_t group, const Sliding& s, const Axes& axes) {
  const std::vector<hsize_t> dims = {axes.gs.size(), axes.psis.size(), axes.thetas.size(),
                                     axes.betas.size()};
  write(group, "Fx_sliding_muN", s.fx, dims, "1",
        "full-sliding limit of Fx/(mu N) in the node's direction (full_sliding_sdec) "
        "[a_over_b][psi][theta][beta]");
  write(group, "Fy_sliding_muN", s.fy, dims, "1",
        "full-sliding limit of Fy/(mu N) in the node's direction [a_over_b][psi][theta][beta]");
  write(group, "Mz_sliding_muNc", s.mz, dims, "1",
        "full-sliding limit of Mz/(mu N c) in the node's direction [a_over_b][psi][theta][beta]");
}

// --add-sliding: writes (or rewrites) the full-sliding limits into every group of an existing
// table, leaving its forces as they are. Through a copy, which the library must read back as a
// table before it is renamed over the file: any failure leaves the file as it was.
void add_sliding_to_copy(const std::string& copy, unsigned threads) {
  Handle file(H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
  if (file.get() < 0) throw std::runtime_error("it is not an HDF5 file");
  H5G_info_t info;
  checked(H5Gget_info(file.get(), &info), "list the file's groups");
  int groups = 0;
  for (hsize_t link = 0; link < info.nlinks; ++link) {
    char name[64] = {};
    checked(H5Lget_name_by_idx(file.get(), ".", H5_INDEX_NAME, H5_ITER_INC, link, name, sizeof name,
                               H5P_DEFAULT),
            "list the file's groups");
    if (std::string(name).rfind("nu_", 0) != 0) continue;
    const Handle group(
        checked(H5Gopen2(file.get(), name, H5P_DEFAULT), "open " + std::string(name)), H5Gclose);
    const Axes axes{read_doubles(group.get(), "a_over_b"), read_doubles(group.get(), "psi"),
                    read_doubles(group.get(), "theta"), read_doubles(group.get(), "beta"),
                    read_doubles(group.get(), "r")};
    const Normalisation k{read_doubles(group.get(), "C11"), read_doubles(group.get(), "C22"),
                          read_doubles(group.get(), "C23"),
                          read_number(group.get(), "spin_scale", 1.0)};
    const std::size_t n_g = axes.gs.size();
    if (n_g == 0 || axes.psis.empty() || axes.thetas.empty() || axes.betas.empty() ||
        k.c11.size() != n_g || k.c22.size() != n_g || k.c23.size() != n_g)
      throw std::runtime_error("group " + std::string(name) +
                               " lacks the axes or C11, C22, C23 of a creep table");
    const int n = static_cast<int>(read_number(group.get(), "grid", 30));
    const double aspect = read_number(group.get(), "max_element_aspect", 1e9);
    const Sliding limits = sliding_limits(axes, k, n, aspect, threads);
    for (const char* set : {"Fx_sliding_muN", "Fy_sliding_muN", "Mz_sliding_muNc"})
      if (H5Lexists(group.get(), set, H5P_DEFAULT) > 0)
        checked(H5Ldelete(group.get(), set, H5P_DEFAULT), std::string("remove the old ") + set);
    write_sliding(group.get(), limits, axes);
    ++groups;
  }
  file.close("close the table");
  if (groups == 0) throw std::runtime_error("it holds no group nu_* of a creep table");
  tangential::load_creep_table(copy);  // read back as the library reads it, or say why not
}

int add_sliding(const std::string& path, unsigned threads) {
  const std::string partial_path = path + ".sliding.partial";
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // the messages below say what failed
  try {
    std::filesystem::copy_file(path, partial_path,
                               std::filesystem::copy_options::overwrite_existing);
    add_sliding_to_copy(partial_path, threads);
    std::filesystem::rename(partial_path, path);
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(partial_path, ignored);
    std::cerr << "--add-sliding " << path << ": " << e.what() << "; the file is unchanged\n";
    return 1;
  }
  std::cout << "full-sliding limits written into every group of " << path << '\n';
  return 0;
}

// The generator's work; throws where writing the table failed (the table it would replace, which
// --reuse may be reading, stays as it was: the new one is renamed over it only when complete).
int generate(int argc, char** argv) {
  int n = 30;
  unsigned threads = 2;
  std::string out_path = "data/creep_table.h5";
  std::vector<double> nus = {0.25, 0.28};
  std::vector<double> gs = {0.2, 0.25, 0.3, 0.4, 0.5, 0.7, 1.0, 1.4,
                            2.0, 3.0,  4.0, 5.0, 6.0, 7.0, 8.5, 10.0};
  double max_aspect = 5.0;
  std::vector<std::string> reuse_paths;
  std::vector<double> psis = {0.0, 0.2, 0.4, 0.6, 0.8};
  int theta_count = 33, beta_count = 19;
  std::vector<double> rs = {0.0, 0.25, 0.5, 0.75, 1.0, 1.5,  2.0,  2.5,  3.0,  3.5,
                            4.0, 5.0,  6.0, 7.0,  8.0, 10.0, 12.0, 14.0, 17.0, 20.0};
  double spin_scale = 3.0;
  std::string add_sliding_to;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--n") {
      n = std::stoi(value);
    } else if (key == "--threads") {
      threads = static_cast<unsigned>(std::max(1, std::stoi(value)));
    } else if (key == "--out") {
      out_path = value;
    } else if (key == "--nu") {
      nus = parse_list(value);
    } else if (key == "--g") {
      gs = parse_list(value);
    } else if (key == "--psi") {
      psis = parse_list(value);
    } else if (key == "--theta-count") {
      theta_count = std::stoi(value);
    } else if (key == "--beta-count") {
      beta_count = std::stoi(value);
    } else if (key == "--r") {
      rs = parse_list(value);
    } else if (key == "--spin-scale") {
      spin_scale = std::stod(value);
    } else if (key == "--max-aspect") {
      max_aspect = std::stod(value);
    } else if (key == "--add-sliding") {
      add_sliding_to = value;
    } else if (key == "--reuse") {
      std::stringstream list(value);
      for (std::string path; std::getline(list, path, ',');) reuse_paths.push_back(path);
    } else {
      std::cerr << "unknown option " << key
                << "; options: --n --threads --out --nu --g --psi --theta-count --beta-count "
                   "--r --spin-scale --max-aspect --reuse --add-sliding\n";
      return 2;
    }
  }
  if (!add_sliding_to.empty()) return add_sliding(add_sliding_to, threads);
  if (!(std::isfinite(max_aspect) && max_aspect >= 1.0)) {
    std::cerr << "need a finite --max-aspect >= 1\n";
    return 2;
  }
  for (const std::string& path : reuse_paths) {
    if (!std::filesystem::exists(path)) {
      std::cerr << "--reuse " << path << ": no such file\n";
      return 2;
    }
  }
  if (n < 8 || theta_count < 3 || beta_count < 3 || rs.empty() || rs[0] != 0.0 || psis.empty() ||
      psis[0] != 0.0) {
    std::cerr << "need --n >= 8, --theta-count >= 3, --beta-count >= 3, --r and --psi "
                 "starting at 0\n";
    return 2;
  }
  const double pi = std::numbers::pi;
  const std::vector<double> thetas = uniform(0.0, pi, theta_count);
  const std::vector<double> betas = uniform(-pi / 2, pi / 2, beta_count);
  const std::size_t per_g = psis.size() * thetas.size() * betas.size() * rs.size();
  const std::size_t total = gs.size() * per_g;
  const Axes axes{gs, psis, thetas, betas, rs};

  // Written beside the output and renamed over it when complete: a failed or interrupted run
  // leaves the table it would replace (which --reuse may be reading) as it was.
  const std::string partial_path = out_path + ".partial";
  const hid_t file = H5Fcreate(partial_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) {
    std::cerr << "cannot create " << partial_path << '\n';
    return 1;
  }
  std::ostringstream description;
  description
      << "Book of creep-force tables: Fx/(mu N), Fy/(mu N) and Mz/(mu N c) (c = sqrt(ab), about O) "
         "on the body-1 (wheel) side, Kalker's convention, from Kalker's exact theory of steady "
         "rolling (wheelwear wear/exact, "
         "exact_sdec) on SDEC patches with the prescribed pressure of Liu, Fu & Bruni 2022, "
         "Eq. 4, "
      << n << " elements across the patch, elements at most " << max_aspect
      << " times as long as wide (aspect_sdec_grid; n x n up to a/b = " << max_aspect
      << ") over [-1.02a, 1.02a] x [y0 - 1.02b, y0 + 1.02b], stopping tolerance 1e-6. "
         "Axes: a_over_b (interpolate in log), psi >= 0 (psi < 0: mirror y -> -y, vy, phi and "
         "Fy change sign), normalised creepages xi = G c^2 C11 vx/(mu N), eta = G c^2 C22 "
         "vy/(mu N), chi = s G c^3 C23 phi/(mu N) (s: the group's spin_scale), c = sqrt(ab), "
         "C's of the group (Kalker's at a_over_b and nu), as r and direction: chi = r cos(theta), "
         "xi = r sin(theta) "
         "cos(beta), eta = r sin(theta) sin(beta), xi >= 0 (reversing all creepages reverses "
         "the forces). Values [a_over_b][psi][theta][beta][r]. Generated by "
         "generators/creep_table_generator.cpp (target wheelwear_creep_table_generator).";
  write_attribute(file, "description", description.str());
  double seconds_total = 0;
  for (const double nu : nus) {
    char name[32];
    std::snprintf(name, sizeof name, "nu_%.2f", nu);
    Normalisation k;
    k.spin_scale = spin_scale;
    for (const double g : gs) {
      const tangential::KalkerCoefficients kc = tangential::kalker_coefficients(g, nu);
      k.c11.push_back(kc.c11);
      k.c22.push_back(kc.c22);
      k.c23.push_back(kc.c23);
    }
    std::vector<double> fx(total, 0.0), fy(total, 0.0), mz(total, 0.0);
    // Nodes earlier tables hold (--reuse) are copied, not solved: from the first that has it.
    std::vector<char> reused(total, 0);
    for (const std::string& path : reuse_paths) {
      Reused old;
      try {
        old = reusable(path, name, nu, n, max_aspect, spin_scale);
      } catch (const std::exception& e) {
        std::cerr << e.what() << '\n';
        H5Fclose(file);
        std::filesystem::remove(partial_path);
        return 1;
      }
      const auto copied = copy_reused(old, axes, max_aspect, fx, fy, mz, reused);
      std::cout << name << ": " << copied << " of " << total << " nodes reused from " << path
                << std::endl;
    }
    std::atomic<int> unconverged{0};
    const auto start = std::chrono::steady_clock::now();
    const tangential::Material material{kNodeShear, nu};
    const double mu_n = kNodeLoad.mu * kNodeLoad.N;
    parallel_for(total, threads, [&](std::size_t i) {
      std::size_t rest = i;
      const std::size_t ir = rest % rs.size();
      rest /= rs.size();
      const std::size_t ib = rest % betas.size();
      rest /= betas.size();
      const std::size_t it = rest % thetas.size();
      rest /= thetas.size();
      const std::size_t ip = rest % psis.size();
      const std::size_t ig = rest / psis.size();
      if (rs[ir] == 0.0 || reused[i]) return;
      // The poles (theta = 0, pi) are one direction for every beta: solve it once.
      const bool pole = it == 0 || it + 1 == thetas.size();
      if (pole && ib != 0) return;
      const NodeProblem p = node_problem(axes, k, ig, ip, rs[ir], thetas[it], betas[ib]);
      const auto s = tangential::exact_sdec(p.patch, p.creepages, kNodeLoad, material,
                                            tangential::aspect_sdec_grid(p.patch, n, max_aspect));
      if (s.status != tangential::ExactStatus::converged) ++unconverged;
      fx[i] = s.forces.Fx / mu_n;
      fy[i] = s.forces.Fy / mu_n;
      mz[i] = *s.forces.Mz / (mu_n * p.patch.c());
    });
    // Copy each pole's solution to every beta.
    for (std::size_t i = 0; i < total; ++i) {
      std::size_t rest = i / rs.size();
      const std::size_t ib = rest % betas.size();
      const std::size_t it = (rest / betas.size()) % thetas.size();
      if ((it == 0 || it + 1 == thetas.size()) && ib != 0) {
        fx[i] = fx[i - ib * rs.size()];
        fy[i] = fy[i - ib * rs.size()];
        mz[i] = mz[i - ib * rs.size()];
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    seconds_total += seconds;
    const hid_t group = H5Gcreate2(file, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    write_attribute(group, "nu", nu);
    write_attribute(group, "grid", static_cast<double>(n));
    write_attribute(group, "max_element_aspect", max_aspect);
    write_attribute(group, "spin_scale", spin_scale);
    write_attribute(group, "generation_seconds", seconds);  // this run's solves, reused not counted
    write(group, "a_over_b", gs, {gs.size()}, "1", "ellipticity a/b of the SDEC patch");
    write(group, "psi", psis, {psis.size()}, "1", "shape number psi >= 0");
    write(group, "theta", thetas, {thetas.size()}, "rad", "polar angle of (xi, eta, chi) from chi");
    write(group, "beta", betas, {betas.size()}, "rad", "azimuth in the (xi, eta) plane");
    write(group, "r", rs, {rs.size()}, "1", "magnitude of the normalised creepage");
    write(group, "C11", k.c11, {gs.size()}, "1", "normalisation: Kalker's C11 at a_over_b, nu");
    write(group, "C22", k.c22, {gs.size()}, "1", "normalisation: Kalker's C22 at a_over_b, nu");
    write(group, "C23", k.c23, {gs.size()}, "1", "normalisation: Kalker's C23 at a_over_b, nu");
    const std::vector<hsize_t> dims = {gs.size(), psis.size(), thetas.size(), betas.size(),
                                       rs.size()};
    write(group, "Fx_muN", fx, dims, "1", "Fx/(mu N) [a_over_b][psi][theta][beta][r]");
    write(group, "Fy_muN", fy, dims, "1", "Fy/(mu N) [a_over_b][psi][theta][beta][r]");
    write(group, "Mz_muNc", mz, dims, "1",
          "Mz/(mu N c), spin moment about O, c = sqrt(ab) [a_over_b][psi][theta][beta][r]");
    write_sliding(group, sliding_limits(axes, k, n, max_aspect, threads), axes);
    H5Gclose(group);
    std::cout << name << ": " << total << " nodes on grids of " << n << " elements across in "
              << seconds << " s (" << threads << " threads), " << unconverged << " not converged"
              << std::endl;
  }
  H5Fclose(file);
  std::error_code error;
  std::filesystem::rename(partial_path, out_path, error);
  if (error) {
    std::cerr << "cannot rename " << partial_path << " to " << out_path << ": " << error.message()
              << '\n';
    return 1;
  }
  std::cout << "-> " << out_path << " in " << seconds_total << " s\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return generate(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
}
