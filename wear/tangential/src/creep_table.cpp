#include "wheelwear/tangential/creep_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "creep_table_data.hpp"
#include "creep_table_interpolation.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/tangential/exact/steady_rolling.hpp"

namespace wheelwear::tangential {

namespace {

using detail::CreepTableBlock;
using detail::CreepTableData;
using detail::has_sliding;
using detail::interpolate;
using detail::Interpolated;
using detail::magnitude;
using detail::NuBlocks;

constexpr double kSlack = 1e-12;  // relative slack on the range's ends (rounding of inputs)
// Beyond r_max the table extrapolates towards full sliding (towards_full_sliding) where the
// patch at r_max is within this fraction of mu N of it. Set when r_max was 6: over 1000 points
// beyond it the answers stayed within 0.34 % of mu N of fresh exact solves, where 0.05 let Mz
// reach 1.3 % of mu N c and 0.1 let F reach 3 %; beyond r_max = 20, 0.49 % of mu N in F and
// 0.65 % of mu N c in Mz (studies/table_interpolation_study.cpp).
constexpr double kFullSlidingMargin = 0.04;

double r_max(const CreepTableBlock& b) {
  return b.r[b.n_r - 1];
}
double psi_max(const CreepTableBlock& b) {
  return b.psi[b.n_psi - 1];
}

std::string range_text(double lo, double hi) {
  std::ostringstream text;
  text << lo << " ... " << hi;
  return text.str();
}

// The advice of the error creep_table_forces throws (not of the reason creep_table_outside gives
// best, which has already moved on).
const std::string kFallback = "; use --method best (or fastsim-sdec) there";

// Throws InputError naming the first invalid input.
void validate(const contactgeom::Sdec& sdec, const Creepages& v, const ContactLoad& load,
              const Material& material) {
  sdec.validate();
  load.validate();
  material.validate();
  v.validate();
}

// The groups `nu` lies between and its weight between them (nu inside the table's range). A
// group of zero weight (nu on the other's own value) is left out: the groups may differ in their
// a/b, direction and r nodes, and only those that count must cover the patch.
NuBlocks nu_blocks(const CreepTableData& table, double nu) {
  const int count = static_cast<int>(table.blocks.size());
  const CreepTableBlock* blocks = table.blocks.data();
  NuBlocks nb;
  nb.lower = &blocks[0];
  for (int i = 0; i + 1 < count; ++i) {
    if (nu >= blocks[i].nu - 1e-12) {
      nb.lower = &blocks[i];
      nb.upper = &blocks[i + 1];
      nb.t = std::clamp((nu - blocks[i].nu) / (blocks[i + 1].nu - blocks[i].nu), 0.0, 1.0);
    }
  }
  if (nb.upper && nb.t >= 1.0) nb = {nb.upper, nullptr, 0.0};
  if (nb.upper && nb.t <= 0.0) nb.upper = nullptr;
  return nb;
}

// The largest normalised creepage every group of `nb` tabulates.
double r_max(const NuBlocks& nb) {
  return nb.upper ? std::min(r_max(*nb.lower), r_max(*nb.upper)) : r_max(*nb.lower);
}

// The a/b range every group of `nb` covers.
std::pair<double, double> a_over_b_range(const NuBlocks& nb) {
  double lo = nb.lower->a_over_b.front(), hi = nb.lower->a_over_b.back();
  if (nb.upper) {
    lo = std::max(lo, nb.upper->a_over_b.front());
    hi = std::min(hi, nb.upper->a_over_b.back());
  }
  return {lo, hi};
}

// Empty message when the table covers the patch's shape and material (nu, a/b, psi), else the
// reason; `out` receives the blocks for nu. The inputs are valid.
std::string check_shape(const CreepTableData& table, const contactgeom::Sdec& sdec,
                        const Material& material, NuBlocks* out) {
  const double nu_lo = table.blocks.front().nu, nu_hi = table.blocks.back().nu;
  std::ostringstream why;
  if (material.nu < nu_lo - 1e-12 || material.nu > nu_hi + 1e-12) {
    why << "nu = " << material.nu << ": the creep table covers nu = " << range_text(nu_lo, nu_hi);
    return why.str();
  }
  const NuBlocks nb = nu_blocks(table, material.nu);
  const double g = sdec.ellipticity();
  const auto [g_lo, g_hi] = a_over_b_range(nb);
  if (g < g_lo * (1 - kSlack) || g > g_hi * (1 + kSlack)) {
    why << "a/b = " << g << ": the creep table covers a/b = " << range_text(g_lo, g_hi)
        << " at nu = " << material.nu;
    return why.str();
  }
  if (std::abs(sdec.psi) > psi_max(*nb.lower) + kSlack) {
    why << "psi = " << sdec.psi << ": the creep table covers |psi| <= " << psi_max(*nb.lower);
    return why.str();
  }
  if (out) *out = nb;
  return {};
}

bool has_moment(const CreepTableData& table) {
  for (const CreepTableBlock& b : table.blocks)
    if (!b.has_mz) return false;
  return !table.blocks.empty();
}

const CreepTableData& data(const CreepTable& table) {
  return detail::CreepTableAccess::data(table);
}

SdecGridOptions table_grid(const CreepTableRange& range, const contactgeom::Sdec& sdec) {
  if (range.max_element_aspect >= 1.0)
    return aspect_sdec_grid(sdec, range.grid, range.max_element_aspect);
  SdecGridOptions grid;
  grid.nx = grid.ny = range.grid;
  return grid;
}

// The full-sliding limit S of the creepages' direction (every element sliding against its rigid
// slip, full_sliding_sdec) on the table's grid, normalised as the table's forces: computed once,
// when first asked for. S depends on the direction alone, not on the creepages' magnitude.
class SlidingLimit {
 public:
  SlidingLimit(const CreepTableData& table, const CreepTableRange& range,
               const contactgeom::Sdec& sdec, const Creepages& v, const ContactLoad& load)
      : table_(table), range_(range), sdec_(sdec), v_(v), load_(load) {}

  const std::array<double, 3>& value() {
    if (!value_) {
      const CreepForces s = full_sliding_sdec(sdec_, v_, load_, table_grid(range_, sdec_));
      const double mu_n = load_.mu * load_.N;
      value_ = {s.Fx / mu_n, s.Fy / mu_n,
                has_moment(table_) ? s.Mz.value_or(0.0) / (mu_n * sdec_.c()) : 0.0};
    }
    return *value_;
  }

 private:
  const CreepTableData& table_;
  const CreepTableRange& range_;
  const contactgeom::Sdec& sdec_;
  const Creepages& v_;
  const ContactLoad& load_;
  std::optional<std::array<double, 3>> value_;
};

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Near full sliding the forces turn with the creepages' direction faster than the table's
// direction nodes resolve: on wide patches the spin's pole, where the rigid slip vanishes,
// crosses the patch. S turns the same way there, and is cheap. So the table answers
// F_interp + rho (S - S_interp), S_interp being S interpolated from the direction nodes as F is:
// the interpolation's error of S taken out. rho fades in with the saturation |F|/|S| (of the
// normalised Fx, Fy, Mz together: under spin the moment saturates where the force stays small)
// from kSlidingFrom to kSlidingFull: small creepages, smooth in direction and far from S, keep
// the plain interpolation and skip S's cost. Over 1000 points inside the table it took the
// worst Mz of wide patches (a/b 0.2-1) from 3.8 % to 0.5 % of mu N c and the mean error by a
// third (studies/table_interpolation_study.cpp). Above a/b 5, S at the creepages is summed on a
// grid whose element count steps with a/b (table_grid), where S_interp is smooth: the answer
// steps with it, by the grid's error of S (the generator's grid: well below the table's error).
constexpr double kSlidingFrom = 0.5, kSlidingFull = 0.9;

std::array<double, 3> interpolate_near_sliding(const NuBlocks& nb, const contactgeom::Sdec& sdec,
                                               const Creepages& v, const ContactLoad& load,
                                               const Material& material, SlidingLimit& limit) {
  const Interpolated in = interpolate(nb, sdec, v, load, material);
  const auto norm = [](const std::array<double, 3>& a) {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  };
  const double bound = norm(in.sliding);
  if (!has_sliding(nb) || !(bound > 0.0)) return in.f;  // (no creepage: no limit)
  const double saturation = norm(in.f) / bound;
  const double rho = smoothstep((saturation - kSlidingFrom) / (kSlidingFull - kSlidingFrom));
  if (rho == 0.0) return in.f;
  const std::array<double, 3>& s = limit.value();
  std::array<double, 3> f = in.f;
  for (std::size_t k = 0; k < 3; ++k) f[k] += rho * (s[k] - in.sliding[k]);
  return f;
}

// Beyond r_max, towards full sliding. The exact theory's forces approach their full-sliding
// limit S as 1/r: the elastic part of the slip is bounded by the tractions while the rigid slip
// grows with r. S depends on the direction of the creepages alone, so
// F(r) = S + (F_table(r_max) - S) r_max / r in the same direction, on the table's grid.
// `deficit` is how far the patch at r_max is from full sliding, |F_table - S| / (mu N) (and
// |Mz_table - S_Mz| / (mu N c)): where spin dominates, the patch is far from it at r_max and
// the 1/r term alone does not hold.
struct TowardsSliding {
  std::array<double, 3> f{};
  double deficit = 0.0;
};

TowardsSliding towards_full_sliding(double r_top, const NuBlocks& nb, const contactgeom::Sdec& sdec,
                                    const Creepages& v, const ContactLoad& load,
                                    const Material& material, double r, SlidingLimit& limit) {
  const double k = r_top / r;
  const Creepages at_max{v.vx * k, v.vy * k, v.phi * k};
  const std::array<double, 3> tabled =
      interpolate_near_sliding(nb, sdec, at_max, load, material, limit);
  const std::array<double, 3>& s = limit.value();
  const std::array<double, 3> d = {tabled[0] - s[0], tabled[1] - s[1], tabled[2] - s[2]};
  TowardsSliding out;
  out.deficit = std::max(std::hypot(d[0], d[1]), std::abs(d[2]));
  out.f = {s[0] + k * d[0], s[1] + k * d[1], s[2] + k * d[2]};
  return out;
}

// Where the table answers: inside its creepages by interpolation, beyond them towards full
// sliding where the patch is within kFullSlidingMargin of it at r_max; else why it does not.
struct Answer {
  std::string why;  // empty when the table answers
  std::array<double, 3> f{};
};

Answer answer(const CreepTable& table, const contactgeom::Sdec& sdec, const Creepages& v,
              const ContactLoad& load, const Material& material) {
  validate(sdec, v, load, material);
  const CreepTableData& d = data(table);
  NuBlocks nb;
  Answer out;
  out.why = check_shape(d, sdec, material, &nb);
  if (!out.why.empty()) return out;
  const CreepTableRange range = table.range();
  SlidingLimit limit(d, range, sdec, v, load);
  const double r = magnitude(nb, sdec, v, load, material);
  const double r_top = r_max(nb);
  if (r <= r_top * (1 + kSlack)) {
    out.f = interpolate_near_sliding(nb, sdec, v, load, material, limit);
    return out;
  }
  const TowardsSliding beyond = towards_full_sliding(r_top, nb, sdec, v, load, material, r, limit);
  if (beyond.deficit <= range.full_sliding_margin) {
    out.f = beyond.f;
    return out;
  }
  std::ostringstream why;
  why << "normalised creepage |(xi, eta, chi)| = " << r
      << " (xi = G c^2 C11 vx/(mu N), eta = G c^2 C22 vy/(mu N), chi = " << range.spin_scale
      << " G c^3 C23 phi/(mu N)): the creep table covers up to " << r_top
      << ", and beyond only patches within " << range.full_sliding_margin
      << " of mu N of full sliding there (this one: " << beyond.deficit << ")";
  out.why = why.str();
  return out;
}

// Forces [N] and moment [N m] from the normalised answer.
CreepForces to_forces(const CreepTable& table, const std::array<double, 3>& f,
                      const contactgeom::Sdec& sdec, const ContactLoad& load) {
  const double mu_n = load.mu * load.N;
  CreepForces forces;
  forces.Fx = f[0] * mu_n;
  forces.Fy = f[1] * mu_n;
  if (has_moment(data(table))) forces.Mz = f[2] * mu_n * sdec.c();
  return forces;
}

}  // namespace

CreepTableRange CreepTable::range() const {
  CreepTableRange range;
  const std::vector<CreepTableBlock>& blocks = data_->blocks;
  const CreepTableBlock& first = blocks.front();
  range.nu_min = first.nu;
  range.nu_max = blocks.back().nu;
  range.a_over_b_min = first.a_over_b.front();
  range.a_over_b_max = first.a_over_b.back();
  range.r_max = r_max(first);
  for (const CreepTableBlock& b : blocks) {
    range.a_over_b_min = std::max(range.a_over_b_min, b.a_over_b.front());
    range.a_over_b_max = std::min(range.a_over_b_max, b.a_over_b.back());
    range.r_max = std::min(range.r_max, r_max(b));
  }
  range.psi_max = psi_max(first);
  range.grid = first.grid;
  range.spin_scale = first.spin_scale;
  range.max_element_aspect = first.max_element_aspect;
  range.full_sliding_margin = kFullSlidingMargin;
  return range;
}

CreepTableRange CreepTable::range(double nu) const {
  CreepTableRange out = range();
  if (!std::isfinite(nu)) throw InputError("creep table range: nu = " + std::to_string(nu));
  const NuBlocks nb = nu_blocks(*data_, std::clamp(nu, out.nu_min, out.nu_max));
  const auto [lo, hi] = a_over_b_range(nb);
  out.a_over_b_min = lo;
  out.a_over_b_max = hi;
  out.r_max = r_max(nb);
  return out;
}

CreepTableRange creep_table_range() {
  return creep_table().range();
}

CreepTableRange creep_table_range(double nu) {
  return creep_table().range(nu);
}

SdecGridOptions creep_table_grid(const contactgeom::Sdec& sdec) {
  return table_grid(creep_table_range(), sdec);
}

double creep_table_magnitude(const contactgeom::Sdec& sdec, const Creepages& creepages,
                             const ContactLoad& load, const Material& material) {
  validate(sdec, creepages, load, material);
  NuBlocks nb;
  const std::string why = check_shape(data(creep_table()), sdec, material, &nb);
  if (!why.empty()) throw InputError(why + kFallback);
  return magnitude(nb, sdec, creepages, load, material);
}

CreepTableLookup creep_table_lookup(const contactgeom::Sdec& sdec, const Creepages& creepages,
                                    const ContactLoad& load, const Material& material) {
  const CreepTable& table = creep_table();
  Answer a = answer(table, sdec, creepages, load, material);
  CreepTableLookup out;
  if (a.why.empty())
    out.forces = to_forces(table, a.f, sdec, load);
  else
    out.outside = std::move(a.why);
  return out;
}

std::optional<std::string> creep_table_outside(const contactgeom::Sdec& sdec,
                                               const Creepages& creepages, const ContactLoad& load,
                                               const Material& material) {
  return creep_table_lookup(sdec, creepages, load, material).outside;
}

bool creep_table_covers(const contactgeom::Sdec& sdec, const Creepages& creepages,
                        const ContactLoad& load, const Material& material) {
  return !creep_table_outside(sdec, creepages, load, material);
}

CreepForces creep_table_forces(const CreepTable& table, const contactgeom::Sdec& sdec,
                               const Creepages& creepages, const ContactLoad& load,
                               const Material& material) {
  const Answer a = answer(table, sdec, creepages, load, material);
  if (!a.why.empty()) throw InputError(a.why + kFallback);
  return to_forces(table, a.f, sdec, load);
}

CreepForces creep_table_forces(const contactgeom::Sdec& sdec, const Creepages& creepages,
                               const ContactLoad& load, const Material& material) {
  return creep_table_forces(creep_table(), sdec, creepages, load, material);
}

std::string creep_table_provenance() {
  return creep_table().provenance();
}

}  // namespace wheelwear::tangential
