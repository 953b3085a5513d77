#include "creep_table_reuse.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "table_hdf5.hpp"

namespace wheelwear::generators {
namespace {

// For each value of `now`, its index in `old` (equal within 1e-12, relative above 1), or -1.
std::vector<long> indices_in(const std::vector<double>& old, const std::vector<double>& now) {
  std::vector<long> out(now.size(), -1);
  for (std::size_t k = 0; k < now.size(); ++k)
    for (std::size_t m = 0; m < old.size(); ++m)
      if (std::abs(old[m] - now[k]) <= 1e-12 * std::max(1.0, std::abs(now[k])))
        out[k] = static_cast<long>(m);
  return out;
}

void read_nodes(hid_t group, Reused& out) {
  out.axes = read_axes(group);
  out.fx = read_doubles(group, "Fx_muN");
  out.fy = read_doubles(group, "Fy_muN");
  out.mz = read_doubles(group, "Mz_muNc");
  const Axes& a = out.axes;
  const std::size_t nodes =
      a.gs.size() * a.psis.size() * a.thetas.size() * a.betas.size() * a.rs.size();
  for (const auto* values : {&out.fx, &out.fy, &out.mz})
    if (values->size() != nodes) out.axes.gs.clear();  // not a whole table: reuse nothing
}

}  // namespace

Reused reusable(const std::string& path, const char* group_name, double nu, int n,
                double max_aspect, double spin_scale) {
  Reused out;
  const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (file.get() < 0) throw std::runtime_error("--reuse: " + path + " is not an HDF5 file");
  if (H5Lexists(file.get(), group_name, H5P_DEFAULT) <= 0) return out;
  const Handle group(H5Gopen2(file.get(), group_name, H5P_DEFAULT), H5Gclose);
  // A table written before the grid rule solved every node on n x n, which the rule gives
  // for a/b within [1/max_aspect, max_aspect] only.
  out.square_only = H5Aexists(group.get(), "max_element_aspect") <= 0;
  const double old_aspect = read_number(group.get(), "max_element_aspect", max_aspect);
  if (read_number(group.get(), "nu", -1.0) == nu && read_number(group.get(), "grid", 0) == n &&
      old_aspect == max_aspect && read_number(group.get(), "spin_scale", 1.0) == spin_scale)
    read_nodes(group.get(), out);
  return out;
}

std::size_t copy_reused(const Reused& old, const Axes& axes, double max_aspect,
                        std::vector<double>& fx, std::vector<double>& fy, std::vector<double>& mz,
                        std::vector<char>& reused) {
  const Axes& o = old.axes;
  const std::vector<long> og = indices_in(o.gs, axes.gs), op = indices_in(o.psis, axes.psis),
                          ot = indices_in(o.thetas, axes.thetas),
                          ob = indices_in(o.betas, axes.betas), orr = indices_in(o.rs, axes.rs);
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
        (((static_cast<std::size_t>(og[ig]) * o.psis.size() + op[ip]) * o.thetas.size() + ot[it]) *
             o.betas.size() +
         ob[ib]) *
            o.rs.size() +
        orr[ir];
    fx[i] = old.fx[from];
    fy[i] = old.fy[from];
    mz[i] = old.mz[from];
    reused[i] = 1;
    ++copied;
  }
  return copied;
}

}  // namespace wheelwear::generators
