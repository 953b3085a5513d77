#include "wheelwear/contactgeom/kik_piotrowski.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "blended_minimum.hpp"
#include "hertz_penetration.hpp"
#include "kik_piotrowski_eval.hpp"
#include "strip_kernel.hpp"
#include "wheelwear/core/input_error.hpp"

// Why the formulas reduce to Hertz for a circle (cross-check (a) in the header):
// for h = (x^2 + s^2)/(2R), A = 1/(2R), the virtual patch is the circle of radius a with
// a^2 = 2 R eps delta, x_l(s)^2 = a^2 - s^2. Then I2 = int pi/2 (a^2 - s^2) ds = 2 pi a^3 / 3 and
// I1 = int_0^(2 pi) int_0^a sqrt(a^2 - r^2) dr dphi = pi^2 a^2 / 2, so N = pi E* delta I2/I1 =
// 4/3 E* a delta and p_O = N a / I2 = 3N/(2 pi a^2). With eps = 1/2, a^2 = R delta: Hertz's
// circular contact exactly. With eps = 0.55 the KP circle is 1.1^(1/3) = 3.2 % wider than
// Hertz's at the same load, with 1.1^(-2/3) = 6.2 % lower p_O and 1.1^(-1/3) = 3.1 % less
// approach.

namespace wheelwear::contactgeom {
namespace {

constexpr double kPi = std::numbers::pi;

using detail::RunIntegrals;

// One run of consecutive strips with h < delta, and its initial contact point O.
struct Run {
  std::size_t first = 0;  // first strip of the run
  std::size_t last = 0;   // last strip of the run (inclusive)
  double s_O = 0.0;       // lateral position of the gap minimum [m]
  double h_O = 0.0;       // gap at O [m]
  double a_O = 0.0;       // A(s_O) [1/m]
};

// Locates O in [first, last]: the strip with the smallest h, refined by the parabola through it
// and its two neighbours (the way CONTACT's reference data locate s_icp), which keeps s_O and
// h_O continuous as the true minimum moves between strips; where several neighbouring strips
// share the smallest h exactly (a flat gap), the middle of that flat part; where the gap has
// minima of nearly the same depth far apart, their weighted mean (blended_minimum.hpp), so that
// O does not jump across a wide patch.
Run locate_minimum(const GapStrips& g, std::size_t first, std::size_t last) {
  const auto gap = [&g](std::ptrdiff_t j) {
    return j < 0 || j >= static_cast<std::ptrdiff_t>(g.size())
               ? std::numeric_limits<double>::infinity()
               : g.h[static_cast<std::size_t>(j)];
  };
  const detail::BlendedMinimum m = detail::blended_minimum(gap, static_cast<std::ptrdiff_t>(first),
                                                           static_cast<std::ptrdiff_t>(last));
  // A(s) at O, linear between the strips around it.
  const double floor = std::floor(m.index);
  const auto j = static_cast<std::size_t>(floor);
  const double t = m.index - floor;
  const double a_O = t > 0.0 && j + 1 < g.size() ? g.ax[j] + t * (g.ax[j + 1] - g.ax[j]) : g.ax[j];
  return {first, last, g.s_first + m.index * g.ds, m.h, a_O};
}

// Visits every run of consecutive strips with h < delta, in increasing s.
template <class Visit>
void for_each_run(const GapStrips& g, double delta, Visit&& visit) {
  const std::size_t n = g.size();
  std::size_t j = 0;
  while (j < n) {
    if (!(g.h[j] < delta)) {
      ++j;
      continue;
    }
    const std::size_t first = j;
    while (j + 1 < n && g.h[j + 1] < delta) ++j;
    visit(locate_minimum(g, first, j));
    ++j;
  }
}

// The virtual penetration of one run: the lateral level eps_s delta_k (strips whose gap
// h - h_O lies below it touch) and the stretch eps_x / eps_s of the strips' squared length,
// exactly 1 with a fixed eps (KpPenetration).
struct Levels {
  double lateral = 0.0;  // [m]
  double stretch = 1.0;  // [-]
  // x_l^2 of a strip whose gap lies `rise` above h_O [m^2]; <= 0 out of contact.
  double xl2(double rise, double a) const { return stretch * (lateral - rise) / a; }
  // How much x_l^2 a strip out of contact lacks [m^2]: > 0, also for a strip just at the level,
  // so that measure_patch always knows where the edge lies (0 there means "not known").
  double opening(double rise, double a) const {
    return std::max(-xl2(rise, a), std::numeric_limits<double>::min());
  }
};

// The rise of the gap above h_O at strip j of `run`, where strips beyond the run count as
// lying at the rigid approach (their gap is at least that, or they have none): the same rise
// whichever window of strips the run was cut from, and continuous as a strip joins the run.
double rise_at(const GapStrips& g, const Run& run, double approach, std::ptrdiff_t j) {
  const bool inside =
      j >= static_cast<std::ptrdiff_t>(run.first) && j <= static_cast<std::ptrdiff_t>(run.last);
  return inside ? g.h[static_cast<std::size_t>(j)] - run.h_O : approach;
}

// Integral over s of the positive part of g, linear from g0 to g1 over a length `step`.
double positive_integral(double g0, double g1, double step) {
  if (g0 >= 0.0 && g1 >= 0.0) return 0.5 * (g0 + g1) * step;
  if (g0 <= 0.0 && g1 <= 0.0) return 0.0;
  const double up = std::max(g0, g1);
  return 0.5 * up * up / std::abs(g1 - g0) * step;
}

// Integral over s of the interpenetration g = level - (h - h_O) > 0 of the whole run (all its
// pieces), the gap taken linear between the strip centres and O (where g = level, also when O
// lies between two pieces) and out to one strip beyond the run at the rigid approach (rise_at):
// positive for every level > 0, and continuous in the level and the gap however few strips the
// run spans.
double interpenetration_integral(const GapStrips& g, const Run& run, double approach,
                                 double level) {
  const auto first = static_cast<std::ptrdiff_t>(run.first) - 1;
  const auto last = static_cast<std::ptrdiff_t>(run.last) + 1;
  const auto s_of = [&](std::ptrdiff_t j) { return g.s_first + static_cast<double>(j) * g.ds; };
  double area = 0.0;
  double s0 = s_of(first), g0 = level - rise_at(g, run, approach, first);
  bool passed_O = !(run.s_O > s0);
  for (std::ptrdiff_t j = first + 1; j <= last; ++j) {
    const double s1 = s_of(j);
    if (!passed_O && run.s_O <= s1) {
      area += positive_integral(g0, level, run.s_O - s0);
      s0 = run.s_O;
      g0 = level;
      passed_O = true;
    }
    const double g1 = level - rise_at(g, run, approach, j);
    area += positive_integral(g0, g1, s1 - s0);
    s0 = s1;
    g0 = g1;
  }
  return area;
}

// Secant lateral curvature of the run's interpenetration at `level` above h_O:
// B = 16 L^3 / (9 (int g ds)^2), B itself for a parabola h - h_O = B (s - s_O)^2.
double secant_curvature(const GapStrips& g, const Run& run, double approach, double level) {
  const double area = interpenetration_integral(g, run, approach, level);
  const double root = 4.0 * level * std::sqrt(level) / (3.0 * area);  // no under- or overflow
  return area > 0.0 ? root * root : 0.0;
}

Levels levels_of(const GapStrips& g, const Run& run, double approach, const KpOptions& options) {
  if (options.penetration == KpPenetration::fixed) return {options.epsilon * approach, 1.0};
  // A fixed number of steps keeps the levels continuous in the gap and the approach.
  constexpr int kSteps = 3;
  double eps_s = 0.5;
  for (int k = 0; k < kSteps; ++k) {
    const double b = secant_curvature(g, run, approach, eps_s * approach);
    eps_s = 1.0 - detail::hertz_penetration_x(b / run.a_O);
  }
  return {eps_s * approach, (1.0 - eps_s) / eps_s};
}

// Integrals of one run at the virtual penetration `levels`.
RunIntegrals integrate_run(const GapStrips& g, const Run& run, const Levels& levels) {
  const double half = 0.5 * g.ds;
  RunIntegrals r;
  r.first_contact = run.last + 1;
  double sum_xl2 = 0.0;
  for (std::size_t j = run.first; j <= run.last; ++j) {
    const double xl2 = levels.xl2(g.h[j] - run.h_O, g.ax[j]);
    if (!(xl2 > 0.0)) continue;
    const double xl = std::sqrt(xl2);
    sum_xl2 += xl2;
    r.max_xl = std::max(r.max_xl, xl);
    const double y = g.s(j) - run.s_O;
    r.i1 += detail::strip_kernel(xl, y - half, y + half);
    r.first_contact = std::min(r.first_contact, j);
    r.last_contact = j;
  }
  r.i2 = 0.5 * kPi * g.ds * sum_xl2;
  return r;
}

// KP load N_k = pi E* delta_k I2 / I1 [N]; 0 when no strip is in contact.
double run_load(const RunIntegrals& r, double approach, double E_star) {
  if (!(r.i2 > 0.0) || !(r.i1 > 0.0)) return 0.0;
  return kPi * E_star * approach * r.i2 / r.i1;
}

// Writes the patch of one run from its integrals.
void write_patch(const GapStrips& g, const Run& run, double approach, const Levels& levels,
                 const RunIntegrals& r, double load, KpPatch& patch) {
  // p(x, s) = p_O sqrt(x_l^2 - x^2)/x_l(s_O) with p_O = N x_l(s_O)/I2, so the pressure at the
  // centre of strip j is N x_l,j / I2.
  const double p_per_xl = load / r.i2;
  patch.strips.clear();
  for (std::size_t j = r.first_contact; j <= r.last_contact; ++j) {
    const double xl2 = levels.xl2(g.h[j] - run.h_O, g.ax[j]);
    const double xl = xl2 > 0.0 ? std::sqrt(xl2) : 0.0;
    const double opening = xl2 > 0.0 ? 0.0 : levels.opening(g.h[j] - run.h_O, g.ax[j]);
    patch.strips.push_back({g.s(j), xl, p_per_xl * xl, opening});
  }
  // The strips beyond either end, out of contact: how much x_lead^2 they lack (beyond the run
  // at the rigid approach, rise_at; the end strip's A where there is no strip).
  const auto opening_at = [&](std::ptrdiff_t j, std::size_t nearest) {
    const bool exists = j >= 0 && j < static_cast<std::ptrdiff_t>(g.size());
    const double a = exists ? g.ax[static_cast<std::size_t>(j)] : g.ax[nearest];
    return levels.opening(rise_at(g, run, approach, j), a);
  };
  patch.opening_before =
      opening_at(static_cast<std::ptrdiff_t>(r.first_contact) - 1, r.first_contact);
  patch.opening_after = opening_at(static_cast<std::ptrdiff_t>(r.last_contact) + 1, r.last_contact);
  patch.ds = g.ds;
  patch.s_O = run.s_O;
  patch.h_O = run.h_O;
  patch.approach = approach;
  patch.virtual_penetration = levels.lateral;
  patch.stretch = levels.stretch;
  patch.x_lead_O = std::sqrt(levels.stretch * levels.lateral / run.a_O);
  patch.normal_force = load;
  patch.p_O = p_per_xl * patch.x_lead_O;
  // O usually lies between strip centres, and the pressure peaks there.
  patch.pmax = p_per_xl * std::max(r.max_xl, patch.x_lead_O);
}

}  // namespace

namespace detail {

double total_load(const GapStrips& g, double delta, const KpOptions& options, double E_star,
                  EvaluationCache& cache) {
  double load = 0.0;
  cache.delta = delta;
  cache.count = 0;
  cache.complete = true;
  for_each_run(g, delta, [&](const Run& run) {
    const double approach = delta - run.h_O;
    const RunIntegrals r = approach > 0.0
                               ? integrate_run(g, run, levels_of(g, run, approach, options))
                               : RunIntegrals{};
    if (cache.count < cache.runs.size()) {
      cache.runs[cache.count++] = r;
    } else {
      cache.complete = false;
    }
    load += run_load(r, approach, E_star);
  });
  return load;
}

void fill_result(const GapStrips& g, double delta, const KpOptions& options, double E_star,
                 const EvaluationCache& cache, KpResult& result) {
  const bool cached = cache.complete && cache.delta == delta;
  std::size_t used = 0;
  std::size_t k = 0;
  result.normal_force = 0.0;
  result.pmax = 0.0;
  result.approach = delta;
  for_each_run(g, delta, [&](const Run& run) {
    const double approach = delta - run.h_O;
    const Levels levels = approach > 0.0 ? levels_of(g, run, approach, options) : Levels{};
    RunIntegrals r;
    if (cached && k < cache.count) {
      r = cache.runs[k];
    } else if (approach > 0.0) {
      r = integrate_run(g, run, levels);
    }
    ++k;
    const double load = run_load(r, approach, E_star);
    if (!(load > 0.0)) return;
    if (used == result.patches.size()) result.patches.emplace_back();
    write_patch(g, run, approach, levels, r, load, result.patches[used]);
    result.pmax = std::max(result.pmax, result.patches[used].pmax);
    result.normal_force += load;
    ++used;
  });
  result.patches.resize(used);
}

LowestStrip lowest_strip(const GapStrips& g) {
  LowestStrip m{g.size(), std::numeric_limits<double>::infinity()};
  for (std::size_t j = 0; j < g.size(); ++j) {
    if (g.h[j] < m.h) m = {j, g.h[j]};
  }
  return m;
}

void check_modulus(double E_star) {
  require_finite("E_star", E_star);
  require(E_star > 0.0, "E_star", E_star, "the combined modulus must be positive (Pa)");
}

void set_no_contact(KpResult& result, double delta, std::string message) {
  result.status = KpStatus::no_contact;
  result.message = std::move(message);
  result.approach = delta;
  result.normal_force = 0.0;
  result.pmax = 0.0;
  result.patches.clear();
}

}  // namespace detail

void GapStrips::validate() const {
  require_finite("ds", ds);
  require_finite("s_first", s_first);
  require(ds > 0.0, "ds", ds, "the strip width must be positive (m)");
  require(!h.empty(), "h.size", 0.0, "at least one strip is needed");
  if (ax.size() != h.size()) {
    // The message is built only on failure: validate() runs on every solve.
    require(false, "ax.size", static_cast<double>(ax.size()),
            "needs one longitudinal coefficient per strip (h.size() = " + std::to_string(h.size()) +
                ")");
  }
  for (std::size_t j = 0; j < h.size(); ++j) {
    if (std::isnan(h[j]) || h[j] == -std::numeric_limits<double>::infinity()) {
      require(false, "h[" + std::to_string(j) + "]", h[j],
              "the gap must be a number or +inf (no potential contact)");
    }
    if (!(std::isfinite(ax[j]) && ax[j] > 0.0)) {
      require(false, "ax[" + std::to_string(j) + "]", ax[j],
              "the longitudinal gap coefficient must be finite and positive (1/m)");
    }
  }
}

void KpOptions::validate() const {
  require_finite("epsilon", epsilon);
  require(epsilon > 0.0 && epsilon <= 1.0, "epsilon", epsilon,
          "the virtual penetration factor must lie in (0, 1]");
  require_finite("load_tolerance", load_tolerance);
  require(load_tolerance > 0.0 && load_tolerance <= 1e-2, "load_tolerance", load_tolerance,
          "the relative tolerance on the normal force must lie in (0, 0.01]");
  require(max_evaluations >= 3, "max_evaluations", max_evaluations, "must be at least 3");
}

double KpStrip::pressure(double x) const {
  if (!(x_lead > 0.0)) return 0.0;
  const double r = x / x_lead;
  const double t = 1.0 - r * r;
  return t > 0.0 ? p_peak * std::sqrt(t) : 0.0;
}

double KpStrip::line_load() const {
  return 0.5 * kPi * p_peak * x_lead;
}

void solve_kp_approach(const GapStrips& gap, double E_star, double delta, const KpOptions& options,
                       KpResult& result) {
  gap.validate();
  options.validate();
  detail::check_modulus(E_star);
  require_finite("delta", delta);
  result.evaluations = 0;
  const detail::LowestStrip m = detail::lowest_strip(gap);
  if (m.index == gap.size()) {
    detail::set_no_contact(result, delta, "no strip has a finite gap: no potential contact");
    return;
  }
  if (!(delta > m.h)) {
    detail::set_no_contact(result, delta, "the approach does not reach the gap minimum");
    return;
  }
  detail::fill_result(gap, delta, options, E_star, detail::EvaluationCache{}, result);
  result.evaluations = 1;
  if (result.patches.empty()) {
    detail::set_no_contact(result, delta,
                           "the virtual penetration is too small to reach any strip centre");
    return;
  }
  result.status = KpStatus::converged;
  result.message.clear();
}

KpResult solve_kp_approach(const GapStrips& gap, double E_star, double delta,
                           const KpOptions& options) {
  KpResult result;
  solve_kp_approach(gap, E_star, delta, options, result);
  return result;
}

}  // namespace wheelwear::contactgeom
