#include "wheelwear/tangential/exact/normal_contact.hpp"

#include <cmath>
#include <cstddef>

#include "influence_operator.hpp"
#include "wheelwear/core/input_error.hpp"

namespace wheelwear::tangential {

NormalSolution exact_normal(const ElementGrid& grid, const std::vector<double>& h,
                            double normal_force, const Material& material,
                            const ExactSolverOptions& options) {
  grid.validate();
  material.validate();
  options.validate();
  const auto n = static_cast<std::size_t>(grid.size());
  require(h.size() == n, "h.size()", static_cast<double>(h.size()),
          "needs one undeformed distance per grid element (nx*ny)");
  for (const double v : h) require_finite("h", v);
  require_finite("normal_force", normal_force);
  require(normal_force > 0.0, "normal_force", normal_force, "must be positive (newtons)");

  NormalSolution solution;
  solution.grid = grid;
  const double da = grid.area();
  const detail::InfluenceOperator op(grid, material, false, true);

  // Polonsky & Keer (1999): conjugate gradients on the gap within the current contact set,
  // with the mean gap there as the approach, elements with negative gap outside the set
  // re-entered (and the conjugation restarted), and the total force imposed by scaling.
  auto& p = solution.pn;
  p.assign(n, normal_force / (static_cast<double>(n) * da));
  std::vector<double> u(n), r(n), t(n, 0.0), q(n), p_old(n);
  double g_old = 1.0;
  bool conjugate = false;
  solution.status = ExactStatus::not_converged;
  for (int it = 1; it <= options.max_iterations; ++it) {
    solution.iterations = it;
    op.normal(p.data(), u.data());
    double mean = 0.0;
    std::size_t count = 0;
    for (std::size_t e = 0; e < n; ++e) {
      r[e] = h[e] + u[e];
      if (p[e] > 0.0) {
        mean += r[e];
        ++count;
      }
    }
    mean /= static_cast<double>(count);
    solution.approach = mean;
    double g = 0.0;
    for (std::size_t e = 0; e < n; ++e) {
      r[e] -= mean;
      if (p[e] > 0.0) g += r[e] * r[e];
    }
    for (std::size_t e = 0; e < n; ++e)
      t[e] = p[e] > 0.0 ? r[e] + (conjugate ? g / g_old : 0.0) * t[e] : 0.0;
    g_old = g;
    op.normal(t.data(), q.data());
    double q_mean = 0.0;
    for (std::size_t e = 0; e < n; ++e)
      if (p[e] > 0.0) q_mean += q[e];
    q_mean /= static_cast<double>(count);
    double rt = 0.0, qt = 0.0;
    for (std::size_t e = 0; e < n; ++e)
      if (p[e] > 0.0) {
        rt += r[e] * t[e];
        qt += (q[e] - q_mean) * t[e];
      }
    const double tau = qt > 0.0 ? rt / qt : 0.0;
    p_old = p;
    bool overlap = false;
    for (std::size_t e = 0; e < n; ++e) {
      if (p_old[e] > 0.0) p[e] = std::max(0.0, p[e] - tau * t[e]);
    }
    for (std::size_t e = 0; e < n; ++e)
      if (p[e] == 0.0 && r[e] < 0.0) {
        p[e] = -tau * r[e];
        overlap = true;
      }
    conjugate = !overlap;
    double total = 0.0;
    for (const double v : p) total += v * da;
    if (!(total > 0.0)) {
      solution.status = ExactStatus::no_contact;
      solution.message = "the pressure vanished on every element";
      return solution;
    }
    double change = 0.0;
    for (std::size_t e = 0; e < n; ++e) {
      p[e] *= normal_force / total;
      change += std::abs(p[e] - p_old[e]) * da;
    }
    if (change <= options.normal_tolerance * normal_force) {
      solution.status = ExactStatus::converged;
      break;
    }
  }
  solution.normal_force = 0.0;
  for (const double v : p) solution.normal_force += v * da;
  if (solution.status == ExactStatus::not_converged) solution.message = "max_iterations reached";
  return solution;
}

}  // namespace wheelwear::tangential
