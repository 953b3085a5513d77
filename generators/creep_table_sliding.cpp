#include "creep_table_sliding.hpp"

#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "table_hdf5.hpp"
#include "wheelwear/tangential/creep_table.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"

namespace wheelwear::generators {
namespace {

// The names of the file's groups nu_*, one per nu.
std::vector<std::string> nu_groups(hid_t file) {
  H5G_info_t info;
  checked(H5Gget_info(file, &info), "list the file's groups");
  std::vector<std::string> out;
  for (hsize_t link = 0; link < info.nlinks; ++link) {
    char name[64] = {};
    checked(H5Lget_name_by_idx(file, ".", H5_INDEX_NAME, H5_ITER_INC, link, name, sizeof name,
                               H5P_DEFAULT),
            "list the file's groups");
    if (std::string(name).rfind("nu_", 0) == 0) out.push_back(name);
  }
  return out;
}

void rewrite_sliding(hid_t group, const std::string& name, unsigned threads) {
  const Axes axes = read_axes(group);
  const Normalisation k{read_doubles(group, "C11"), read_doubles(group, "C22"),
                        read_doubles(group, "C23"), read_number(group, "spin_scale", 1.0)};
  const std::size_t n_g = axes.gs.size();
  if (n_g == 0 || axes.psis.empty() || axes.thetas.empty() || axes.betas.empty() ||
      k.c11.size() != n_g || k.c22.size() != n_g || k.c23.size() != n_g)
    throw std::runtime_error("group " + name + " lacks the axes or C11, C22, C23 of a creep table");
  const int n = static_cast<int>(read_number(group, "grid", 30));
  const double aspect = read_number(group, "max_element_aspect", 1e9);
  const Sliding limits = sliding_limits(axes, k, n, aspect, threads);
  for (const char* set : {"Fx_sliding_muN", "Fy_sliding_muN", "Mz_sliding_muNc"})
    if (H5Lexists(group, set, H5P_DEFAULT) > 0)
      checked(H5Ldelete(group, set, H5P_DEFAULT), std::string("remove the old ") + set);
  write_sliding(group, limits, axes);
}

void add_sliding_to_copy(const std::string& copy, unsigned threads) {
  Handle file(H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
  if (file.get() < 0) throw std::runtime_error("it is not an HDF5 file");
  const std::vector<std::string> groups = nu_groups(file.get());
  for (const std::string& name : groups) {
    const Handle group(checked(H5Gopen2(file.get(), name.c_str(), H5P_DEFAULT), "open " + name),
                       H5Gclose);
    rewrite_sliding(group.get(), name, threads);
  }
  file.close("close the table");
  if (groups.empty()) throw std::runtime_error("it holds no group nu_* of a creep table");
  tangential::load_creep_table(copy);  // read back as the library reads it, or say why not
}

}  // namespace

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

}  // namespace wheelwear::generators
