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
//   [--beta ...] [--r 0,0.25,...,20] [--spin-scale 3] [--max-aspect 5] [--reuse OLD.h5,...]
//   [--into T.h5]
//   or: wheelwear_creep_table_generator --add-sliding TABLE.h5 [--threads 2]
// --add-sliding writes (or rewrites) the full-sliding limits into an existing table in place,
// its forces untouched (how the shipped table, solved before the limits were stored, got them).
// --reuse OLD.h5[,OLDER.h5...] takes every node the files hold (the same nu, grid rule and spin
// scale, and each of the node's axis values among the file's) from the first that holds it
// instead of solving it again: to add nodes along any axis (a/b, psi, theta, beta, r) to a
// table, also one nu at a time (--nu 0.25 into one file, then both nu reusing it and the old
// table).
// --beta LIST gives the beta nodes themselves (radians, increasing, within -pi/2 ... pi/2; one
// node alone for a file to --reuse), where --beta-count spaces them uniformly.
// --into TABLE.h5 writes the groups of --nu into a copy of TABLE.h5, replacing its groups of the
// same nu and keeping the others (the groups may differ in their a/b, beta and r nodes): a table
// refined at one nu first.
// The defaults are the node set of both groups of the first shipped table: 2 x 1 003 200 nodes
// (898 320 solves per nu), about 90 min on two cores: 35 min for a/b 0.2 ... 5 and 37 min for
// 6 ... 10 with r up to 6, 10 min for r 7 ... 12 and 5 min for 14 ... 20 (solves near full
// sliding take fewer sweeps), 35 MB. The nodes are where interpolating
// (creep_table_interpolation.cpp) needs them to stay within 1 % of mu N of fresh solves
// (tests/tangential/creep_table_test.cpp; but for corners near full sliding, docs/validation.md):
// the forces turn fastest with theta where the patch begins to slide fully, and with a/b below
// 0.3 and above 3 (with nodes at 5, 7 and 10 alone the worst of the 190 of 1000 test points
// beyond a/b = 5 reached 0.98 %). A finer solver grid (--n 40) or more nodes cost in proportion
// to their elements and sweeps (see the printed count).
// The shipped table's nu = 0.25 group adds the flank's patches: a/b 12, 14.5, 17.5, 21 and 25
// (72 x 30 ... 150 x 30 elements, 1.8 ... 6.4 times as long a solve as at 8.5), beta at +-85
// degrees (on slender patches with spin the forces turn fast as beta nears +-90 degrees) and
// r 25, 32, 40 and 50 (the flank's spin), each node a file of its own over the other axes of
// the merged group (--nu 0.25 --g 12; --g ...,25 --beta 1.4835298641951802; --g ...,25
// --beta ... --r 0,25), merged with --reuse data/creep_table.h5,g12.h5,... --into
// data/creep_table.h5 (docs/developing.md gives the times).

#include <hdf5.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "creep_table_nodes.hpp"
#include "creep_table_reuse.hpp"
#include "creep_table_sliding.hpp"
#include "table_hdf5.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"
#include "wheelwear/tangential/kalker_coefficients.hpp"

namespace {

using namespace wheelwear;
using namespace wheelwear::generators;

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

struct Options {
  int n = 30;
  unsigned threads = 2;
  std::string out_path = "data/creep_table.h5";
  std::string into;  // the table whose other groups the new file keeps (--into)
  std::vector<double> nus = {0.25, 0.28};
  std::vector<double> gs = {0.2, 0.25, 0.3, 0.4, 0.5, 0.7, 1.0, 1.4,
                            2.0, 3.0,  4.0, 5.0, 6.0, 7.0, 8.5, 10.0};
  double max_aspect = 5.0;
  std::vector<std::string> reuse_paths;
  std::vector<double> psis = {0.0, 0.2, 0.4, 0.6, 0.8};
  int theta_count = 33, beta_count = 19;
  std::vector<double> betas;  // --beta: the beta nodes themselves, instead of beta_count uniform
  std::vector<double> rs = {0.0, 0.25, 0.5, 0.75, 1.0, 1.5,  2.0,  2.5,  3.0,  3.5,
                            4.0, 5.0,  6.0, 7.0,  8.0, 10.0, 12.0, 14.0, 17.0, 20.0};
  double spin_scale = 3.0;
  std::string add_sliding_to;
};

// Reads the options into `o`; false (having said why) where one is unknown.
bool parse_options(int argc, char** argv, Options& o) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--n") {
      o.n = std::stoi(value);
    } else if (key == "--threads") {
      o.threads = static_cast<unsigned>(std::max(1, std::stoi(value)));
    } else if (key == "--out") {
      o.out_path = value;
    } else if (key == "--into") {
      o.into = value;
    } else if (key == "--nu") {
      o.nus = parse_list(value);
    } else if (key == "--g") {
      o.gs = parse_list(value);
    } else if (key == "--psi") {
      o.psis = parse_list(value);
    } else if (key == "--theta-count") {
      o.theta_count = std::stoi(value);
    } else if (key == "--beta-count") {
      o.beta_count = std::stoi(value);
    } else if (key == "--beta") {
      o.betas = parse_list(value);
    } else if (key == "--r") {
      o.rs = parse_list(value);
    } else if (key == "--spin-scale") {
      o.spin_scale = std::stod(value);
    } else if (key == "--max-aspect") {
      o.max_aspect = std::stod(value);
    } else if (key == "--add-sliding") {
      o.add_sliding_to = value;
    } else if (key == "--reuse") {
      std::stringstream list(value);
      for (std::string path; std::getline(list, path, ',');) o.reuse_paths.push_back(path);
    } else {
      std::cerr << "unknown option " << key
                << "; options: --n --threads --out --into --nu --g --psi --theta-count "
                   "--beta-count --beta --r --spin-scale --max-aspect --reuse --add-sliding\n";
      return false;
    }
  }
  return true;
}

// Empty when the options describe a table that can be made, else why not.
std::string invalid(const Options& o) {
  if (!(std::isfinite(o.max_aspect) && o.max_aspect >= 1.0))
    return "need a finite --max-aspect >= 1";
  for (const std::string& path : o.reuse_paths)
    if (!std::filesystem::exists(path)) return "--reuse " + path + ": no such file";
  if (!o.into.empty() && !std::filesystem::exists(o.into))
    return "--into " + o.into + ": no such file";
  const double half_pi = std::numbers::pi / 2 + 1e-12;
  for (std::size_t i = 0; i < o.betas.size(); ++i)
    if (!(std::abs(o.betas[i]) <= half_pi) || (i > 0 && !(o.betas[i] > o.betas[i - 1])))
      return "--beta: the nodes must increase within -pi/2 ... pi/2 (radians)";
  if (o.n < 8 || o.theta_count < 3 || o.beta_count < 3 || o.rs.empty() || o.rs[0] != 0.0 ||
      o.psis.empty() || o.psis[0] != 0.0)
    return "need --n >= 8, --theta-count >= 3, --beta-count >= 3, --r and --psi starting at 0";
  return {};
}

std::string description(const Options& o) {
  std::ostringstream text;
  text << "Book of creep-force tables: Fx/(mu N), Fy/(mu N) and Mz/(mu N c) (c = sqrt(ab), about "
          "O) on the body-1 (wheel) side, Kalker's convention, from Kalker's exact theory of "
          "steady rolling (wheelwear wear/exact, exact_sdec) on SDEC patches with the prescribed "
          "pressure of Liu, Fu & Bruni 2022, Eq. 4, "
       << o.n << " elements across the patch, elements at most " << o.max_aspect
       << " times as long as wide (aspect_sdec_grid; n x n up to a/b = " << o.max_aspect
       << ") over [-1.02a, 1.02a] x [y0 - 1.02b, y0 + 1.02b], stopping tolerance 1e-6. "
          "Axes: a_over_b (interpolate in log), psi >= 0 (psi < 0: mirror y -> -y, vy, phi and "
          "Fy change sign), normalised creepages xi = G c^2 C11 vx/(mu N), eta = G c^2 C22 "
          "vy/(mu N), chi = s G c^3 C23 phi/(mu N) (s: the group's spin_scale), c = sqrt(ab), "
          "C's of the group (Kalker's at a_over_b and nu), as r and direction: chi = r "
          "cos(theta), xi = r sin(theta) cos(beta), eta = r sin(theta) sin(beta), xi >= 0 "
          "(reversing all creepages reverses the forces). Values "
          "[a_over_b][psi][theta][beta][r]; the groups (one per nu) may differ in their a_over_b "
          "nodes. Generated by generators/creep_table_generator.cpp (target "
          "wheelwear_creep_table_generator).";
  return text.str();
}

// One nu's group: its normalisation and forces at every node.
struct Group {
  Normalisation k;
  std::vector<double> fx, fy, mz;
  int unconverged = 0;
  double seconds = 0.0;  // this run's solves; reused nodes are not counted
};

// Copies the nodes the --reuse tables hold into `g`; returns which they are.
std::vector<char> reuse_nodes(const Options& o, const Axes& axes, const char* name, double nu,
                              Group& g) {
  std::vector<char> reused(g.fx.size(), 0);
  for (const std::string& path : o.reuse_paths) {
    const Reused old = reusable(path, name, nu, o.n, o.max_aspect, o.spin_scale);
    const std::size_t copied = copy_reused(old, axes, o.max_aspect, g.fx, g.fy, g.mz, reused);
    std::cout << name << ": " << copied << " of " << reused.size() << " nodes reused from " << path
              << std::endl;
  }
  return reused;
}

// Solves every node of `axes` at `nu` that no --reuse table holds.
Group solve_group(const Options& o, const Axes& axes, const char* name, double nu) {
  const std::size_t n_r = axes.rs.size(), n_b = axes.betas.size(), n_t = axes.thetas.size(),
                    n_p = axes.psis.size();
  const std::size_t total = axes.gs.size() * n_p * n_t * n_b * n_r;
  Group g;
  g.k.spin_scale = o.spin_scale;
  for (const double ab : axes.gs) {
    const tangential::KalkerCoefficients kc = tangential::kalker_coefficients(ab, nu);
    g.k.c11.push_back(kc.c11);
    g.k.c22.push_back(kc.c22);
    g.k.c23.push_back(kc.c23);
  }
  g.fx.assign(total, 0.0);
  g.fy.assign(total, 0.0);
  g.mz.assign(total, 0.0);
  const std::vector<char> reused = reuse_nodes(o, axes, name, nu, g);
  std::atomic<int> unconverged{0};
  const auto start = std::chrono::steady_clock::now();
  const tangential::Material material{kNodeShear, nu};
  const double mu_n = kNodeLoad.mu * kNodeLoad.N;
  parallel_for(total, o.threads, [&](std::size_t i) {
    const std::size_t ir = i % n_r, ib = i / n_r % n_b, it = i / (n_r * n_b) % n_t,
                      ip = i / (n_r * n_b * n_t) % n_p, ig = i / (n_r * n_b * n_t * n_p);
    if (axes.rs[ir] == 0.0 || reused[i]) return;
    // The poles (theta = 0, pi) are one direction for every beta: solve it once.
    const bool pole = it == 0 || it + 1 == n_t;
    if (pole && ib != 0) return;
    const NodeProblem p =
        node_problem(axes, g.k, ig, ip, axes.rs[ir], axes.thetas[it], axes.betas[ib]);
    const auto s = tangential::exact_sdec(p.patch, p.creepages, kNodeLoad, material,
                                          tangential::aspect_sdec_grid(p.patch, o.n, o.max_aspect));
    if (s.status != tangential::ExactStatus::converged) ++unconverged;
    g.fx[i] = s.forces.Fx / mu_n;
    g.fy[i] = s.forces.Fy / mu_n;
    g.mz[i] = *s.forces.Mz / (mu_n * p.patch.c());
  });
  // Copy each pole's solution to every beta.
  for (std::size_t i = 0; i < total; ++i) {
    const std::size_t ib = i / n_r % n_b, it = i / (n_r * n_b) % n_t;
    if ((it == 0 || it + 1 == n_t) && ib != 0) {
      g.fx[i] = g.fx[i - ib * n_r];
      g.fy[i] = g.fy[i - ib * n_r];
      g.mz[i] = g.mz[i - ib * n_r];
    }
  }
  g.unconverged = unconverged;
  g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return g;
}

void write_group(hid_t file, const char* name, double nu, const Options& o, const Axes& axes,
                 const Group& g) {
  if (H5Lexists(file, name, H5P_DEFAULT) > 0)  // --into a table that holds this nu: replace it
    checked(H5Ldelete(file, name, H5P_DEFAULT), std::string("remove the old group ") + name);
  const Handle group(checked(H5Gcreate2(file, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                             std::string("create the group ") + name),
                     H5Gclose);
  const hid_t id = group.get();
  const std::vector<double>& gs = axes.gs;
  write_attribute(id, "nu", nu);
  write_attribute(id, "grid", static_cast<double>(o.n));
  write_attribute(id, "max_element_aspect", o.max_aspect);
  write_attribute(id, "spin_scale", o.spin_scale);
  write_attribute(id, "generation_seconds", g.seconds);  // this run's solves, reused not counted
  write(id, "a_over_b", gs, {gs.size()}, "1", "ellipticity a/b of the SDEC patch");
  write(id, "psi", axes.psis, {axes.psis.size()}, "1", "shape number psi >= 0");
  write(id, "theta", axes.thetas, {axes.thetas.size()}, "rad",
        "polar angle of (xi, eta, chi) from chi");
  write(id, "beta", axes.betas, {axes.betas.size()}, "rad", "azimuth in the (xi, eta) plane");
  write(id, "r", axes.rs, {axes.rs.size()}, "1", "magnitude of the normalised creepage");
  write(id, "C11", g.k.c11, {gs.size()}, "1", "normalisation: Kalker's C11 at a_over_b, nu");
  write(id, "C22", g.k.c22, {gs.size()}, "1", "normalisation: Kalker's C22 at a_over_b, nu");
  write(id, "C23", g.k.c23, {gs.size()}, "1", "normalisation: Kalker's C23 at a_over_b, nu");
  const std::vector<hsize_t> dims = {gs.size(), axes.psis.size(), axes.thetas.size(),
                                     axes.betas.size(), axes.rs.size()};
  write(id, "Fx_muN", g.fx, dims, "1", "Fx/(mu N) [a_over_b][psi][theta][beta][r]");
  write(id, "Fy_muN", g.fy, dims, "1", "Fy/(mu N) [a_over_b][psi][theta][beta][r]");
  write(id, "Mz_muNc", g.mz, dims, "1",
        "Mz/(mu N c), spin moment about O, c = sqrt(ab) [a_over_b][psi][theta][beta][r]");
  write_sliding(id, sliding_limits(axes, g.k, o.n, o.max_aspect, o.threads), axes);
}

// Writes every group of the options into `partial_path` (a copy of --into, or a new file).
double write_table(const Options& o, const std::string& partial_path) {
  if (!o.into.empty())
    std::filesystem::copy_file(o.into, partial_path,
                               std::filesystem::copy_options::overwrite_existing);
  Handle file(o.into.empty()
                  ? H5Fcreate(partial_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)
                  : H5Fopen(partial_path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT),
              H5Fclose);
  checked(file.get(), "create " + partial_path);
  if (H5Aexists(file.get(), "description") > 0)
    checked(H5Adelete(file.get(), "description"), "replace the description");
  write_attribute(file.get(), "description", description(o));
  const double pi = std::numbers::pi;
  const Axes axes{o.gs, o.psis, uniform(0.0, pi, o.theta_count),
                  o.betas.empty() ? uniform(-pi / 2, pi / 2, o.beta_count) : o.betas, o.rs};
  double seconds = 0;
  for (const double nu : o.nus) {
    char name[32];
    std::snprintf(name, sizeof name, "nu_%.2f", nu);
    const Group g = solve_group(o, axes, name, nu);
    write_group(file.get(), name, nu, o, axes, g);
    seconds += g.seconds;
    std::cout << name << ": " << g.fx.size() << " nodes on grids of " << o.n
              << " elements across in " << g.seconds << " s (" << o.threads << " threads), "
              << g.unconverged << " not converged" << std::endl;
  }
  file.close("close " + partial_path);
  return seconds;
}

// The generator's work. Written beside the output and renamed over it when complete: a failed
// or interrupted run leaves the table it would replace (which --reuse or --into may be reading)
// as it was.
int generate(int argc, char** argv) {
  Options o;
  if (!parse_options(argc, argv, o)) return 2;
  if (!o.add_sliding_to.empty()) return add_sliding(o.add_sliding_to, o.threads);
  if (const std::string why = invalid(o); !why.empty()) {
    std::cerr << why << '\n';
    return 2;
  }
  const std::string partial_path = o.out_path + ".partial";
  double seconds = 0;
  try {
    seconds = write_table(o, partial_path);
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(partial_path, ignored);
    std::cerr << e.what() << "; " << o.out_path << " is unchanged\n";
    return 1;
  }
  std::error_code error;
  std::filesystem::rename(partial_path, o.out_path, error);
  if (error) {
    std::cerr << "cannot rename " << partial_path << " to " << o.out_path << ": " << error.message()
              << '\n';
    return 1;
  }
  std::cout << "-> " << o.out_path << " in " << seconds << " s\n";
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
