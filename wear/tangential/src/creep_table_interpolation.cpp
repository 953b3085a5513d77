#include "creep_table_interpolation.hpp"

#include <algorithm>
#include <cmath>

namespace wheelwear::tangential::detail {

namespace {

// Four-node (or fewer, on short axes) Lagrange stencil of q on increasing nodes x[0..n-1].
struct Stencil {
  int start = 0, count = 0;
  std::array<double, 4> w{};
};

Stencil stencil(const double* x, int n, double q) {
  Stencil s;
  s.count = std::min(n, 4);
  int k = 0;
  while (k + 2 < n && q > x[k + 1]) ++k;
  s.start = std::clamp(k - 1, 0, n - s.count);
  for (int j = 0; j < s.count; ++j) {
    double w = 1.0;
    for (int m = 0; m < s.count; ++m) {
      if (m != j) w *= (q - x[s.start + m]) / (x[s.start + j] - x[s.start + m]);
    }
    s.w[static_cast<std::size_t>(j)] = w;
  }
  return s;
}

// The block's normalisation coefficients at a/b, by the same four-node stencils in log(a/b) as
// the forces: a linear interpolation would kink the normalised forces at every node of a/b.
struct Normalisation {
  double c11, c22, c23;
};

Normalisation normalisation(const CreepTableBlock& b, double g) {
  const Stencil s = stencil(b.log_a_over_b.data(), b.n_g, std::log(g));
  Normalisation n{0.0, 0.0, 0.0};
  for (int i = 0; i < s.count; ++i) {
    n.c11 += s.w[i] * b.c11[s.start + i];
    n.c22 += s.w[i] * b.c22[s.start + i];
    n.c23 += s.w[i] * b.c23[s.start + i];
  }
  return n;
}

struct Normalised {
  double xi, eta, chi;
  double r() const { return std::sqrt(xi * xi + eta * eta + chi * chi); }
};

Normalised normalise(const CreepTableBlock& b, const contactgeom::Sdec& sdec, const Creepages& v,
                     const ContactLoad& load, const Material& material) {
  const Normalisation n = normalisation(b, sdec.ellipticity());
  const double c = sdec.c(), mu_n = load.mu * load.N, gc2 = material.G * c * c;
  return {gc2 * n.c11 * v.vx / mu_n, gc2 * n.c22 * v.vy / mu_n,
          b.spin_scale * gc2 * c * n.c23 * v.phi / mu_n};
}

// The forces and the full-sliding limit interpolated in one block (the limit zero where it has
// none).
Interpolated evaluate(const CreepTableBlock& b, const contactgeom::Sdec& sdec, const Creepages& v,
                      const ContactLoad& load, const Material& material) {
  Normalised n = normalise(b, sdec, v, load, material);
  double psi = sdec.psi, sign_x = 1.0, sign_y = 1.0;
  if (psi < 0) {  // mirror y -> -y: eta, chi, Fy and Mz change sign
    psi = -psi;
    n.eta = -n.eta;
    n.chi = -n.chi;
    sign_y = -sign_y;
  }
  if (n.xi < 0) {  // reversed creepages reverse the forces and the moment
    n = {-n.xi, -n.eta, -n.chi};
    sign_x = -sign_x;
    sign_y = -sign_y;
  }
  const double r = n.r();
  if (r == 0.0) return {};
  const double theta = std::acos(std::clamp(n.chi / r, -1.0, 1.0));
  const double beta = std::atan2(n.eta, n.xi);  // xi >= 0: in [-pi/2, pi/2]
  const Stencil sg = stencil(b.log_a_over_b.data(), b.n_g, std::log(sdec.ellipticity()));
  const Stencil sp = stencil(b.psi.data(), b.n_psi, psi);
  const Stencil st = stencil(b.theta.data(), b.n_theta, theta);
  const Stencil sb = stencil(b.beta.data(), b.n_beta, beta);
  const Stencil sr = stencil(b.r.data(), b.n_r, r);
  double fx = 0.0, fy = 0.0, mz = 0.0;
  for (int ig = 0; ig < sg.count; ++ig) {
    for (int ip = 0; ip < sp.count; ++ip) {
      const double wgp = sg.w[ig] * sp.w[ip];
      for (int it = 0; it < st.count; ++it) {
        for (int ib = 0; ib < sb.count; ++ib) {
          const double w4 = wgp * st.w[it] * sb.w[ib];
          const std::size_t base =
              ((((static_cast<std::size_t>(sg.start + ig) * b.n_psi + sp.start + ip) * b.n_theta +
                 st.start + it) *
                    b.n_beta +
                sb.start + ib) *
               b.n_r) +
              sr.start;
          // The r-stencil's weighted sum first: one weight per node of the other four axes.
          const float* node = b.values.data() + 3 * base;
          double sx = 0.0, sy = 0.0, sm = 0.0;
          for (int ir = 0; ir < sr.count; ++ir) {
            sx += sr.w[ir] * node[3 * ir];
            sy += sr.w[ir] * node[3 * ir + 1];
            sm += sr.w[ir] * node[3 * ir + 2];
          }
          fx += w4 * sx;
          fy += w4 * sy;
          mz += w4 * sm;
        }
      }
    }
  }
  Interpolated out;
  out.f = {sign_x * fx, sign_y * fy, sign_y * mz};
  if (b.sliding.empty()) return out;
  // The full-sliding limit from the direction nodes, with the same stencils.
  double lx = 0.0, ly = 0.0, lm = 0.0;
  for (int ig = 0; ig < sg.count; ++ig) {
    for (int ip = 0; ip < sp.count; ++ip) {
      const double wgp = sg.w[ig] * sp.w[ip];
      for (int it = 0; it < st.count; ++it) {
        const std::size_t row =
            ((static_cast<std::size_t>(sg.start + ig) * b.n_psi + sp.start + ip) * b.n_theta +
             st.start + it) *
                b.n_beta +
            sb.start;
        const float* limit = b.sliding.data() + 3 * row;
        for (int ib = 0; ib < sb.count; ++ib) {
          const double w4 = wgp * st.w[it] * sb.w[ib];
          lx += w4 * limit[3 * ib];
          ly += w4 * limit[3 * ib + 1];
          lm += w4 * limit[3 * ib + 2];
        }
      }
    }
  }
  out.sliding = {sign_x * lx, sign_y * ly, sign_y * lm};
  return out;
}

}  // namespace

double magnitude(const NuBlocks& nb, const contactgeom::Sdec& sdec, const Creepages& v,
                 const ContactLoad& load, const Material& material) {
  double r = normalise(*nb.lower, sdec, v, load, material).r();
  if (nb.upper) r = std::max(r, normalise(*nb.upper, sdec, v, load, material).r());
  return r;
}

Interpolated interpolate(const NuBlocks& nb, const contactgeom::Sdec& sdec, const Creepages& v,
                         const ContactLoad& load, const Material& material) {
  Interpolated f = evaluate(*nb.lower, sdec, v, load, material);
  if (nb.upper && nb.t > 0.0) {
    const Interpolated u = evaluate(*nb.upper, sdec, v, load, material);
    for (std::size_t k = 0; k < 3; ++k) {
      f.f[k] = (1 - nb.t) * f.f[k] + nb.t * u.f[k];
      f.sliding[k] = (1 - nb.t) * f.sliding[k] + nb.t * u.sliding[k];
    }
  }
  return f;
}

bool has_sliding(const NuBlocks& nb) {
  return !nb.lower->sliding.empty();  // the loader refuses tables with them in some groups only
}

}  // namespace wheelwear::tangential::detail
