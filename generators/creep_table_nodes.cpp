#include "creep_table_nodes.hpp"

#include <cmath>

#include "table_hdf5.hpp"

namespace wheelwear::generators {

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

Axes read_axes(hid_t group) {
  return {read_doubles(group, "a_over_b"), read_doubles(group, "psi"), read_doubles(group, "theta"),
          read_doubles(group, "beta"), read_doubles(group, "r")};
}

}  // namespace wheelwear::generators
