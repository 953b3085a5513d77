#include "strip_plane.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <utility>

namespace wheelwear::contactgeom::detail {

double StripPlane::sample_at(double s) const {
  const double k = std::clamp((s - s_first) / ds, 0.0, static_cast<double>(sample.size() - 1));
  const auto i = static_cast<std::size_t>(k);
  if (i + 1 >= sample.size()) return sample.back();
  return sample[i] + (k - static_cast<double>(i)) * (sample[i + 1] - sample[i]);
}

double StripPlane::y_at(const GapSamples& g, double s) const {
  if (!weighted) return y_O - s * cos;
  const double j = sample_at(s);
  const auto i = static_cast<std::size_t>(j);
  return g.y[i] + (j - static_cast<double>(i)) * g.dy;
}

namespace {

// Beyond a cut the gap rises to the rigid approach over one sample, linearly in the cut's
// position: a sample half a sample or more beyond it lies as a sample beyond the run does, and
// the patch's loads and edges follow the cut's position continuously.
double gap_in_run(const GapSamples& g, const Run& run, std::size_t j, double approach) {
  const double beyond =
      std::max(run.cut_before - static_cast<double>(j), static_cast<double>(j) - run.cut_after);
  return g.h[j] + std::clamp(beyond + 0.5, 0.0, 1.0) * std::max(0.0, approach - g.h[j]);
}

// How many samples either way strips_of() looks for the wheel's points about a rail point: the
// wheel lies (approach - gap) sin(delta) along t from the rail, under a sample where they touch.
constexpr std::size_t kWheelSearch = 8;
// Samples the weighted plane's strips reach beyond their run's ends (strips_of).
constexpr std::size_t kBeyondRun = 4;
// The least factor of the wheel's sag along the plane's normal, of cos(delta): it falls with the
// wheel's slope against the plane only far from the contact, where the strips never touch.
constexpr double kLeastSag = 0.05;

// `run` widened by up to `samples` samples at either end, within its window.
Run widened(const GapSamples& g, const Run& run, std::size_t samples) {
  Run wider = run;
  const int window = g.window[run.first];
  for (std::size_t k = 0; k < samples; ++k) {
    if (wider.first > 0 && g.window[wider.first - 1] == window) --wider.first;
    if (wider.last + 1 < g.h.size() && g.window[wider.last + 1] == window) ++wider.last;
  }
  return wider;
}

// Kik & Piotrowski's reduction: the plane at the run's gap minimum, each sample a strip, its
// gap the vertical one times the plane's cosine, s = -(y - y_O) / cos.
void strips_in_plane_at_O(const WheelRailGap& geometry, const GapSamples& g, const Run& run,
                          double approach, RunStrips& out, StripBuffers& b) {
  const std::size_t n = run.last - run.first + 1;
  const double c = out.plane.cos;
  b.h.resize(n);
  b.ax.resize(n);
  b.sample.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = run.last - k;
    b.h[k] = gap_in_run(g, run, j, approach) * c;
    b.ax[k] = c / (2.0 * geometry.rolling_radius(g.z_wheel[j]));
    b.sample[k] = static_cast<double>(j);
  }
  out.strips.ds = g.dy / c;
  out.strips.s_first = -(g.y[run.last] - run.y_O) / c;
}

// Each sample's place t along the weighted plane (towards the gauge side) and its gap and A
// along the plane's normal, into b.t, b.hs, b.axs, from the run's last sample on (increasing
// s). The rail's and the wheel's points are turned into the plane as CONTACT turns its
// profiles (z, and n, point down into the rail), the wheel moved down by the approach; the
// wheel's points reach kWheelSearch samples beyond the run (within its window), so that the
// run's end samples find theirs as the inner ones do.
void turned_gap(const WheelRailGap& geometry, const GapSamples& g, SampleDirections& directions,
                const Run& run, double approach, const StripPlane& plane, StripBuffers& b) {
  const std::size_t n = run.last - run.first + 1;
  const double c = plane.cos, sn = std::sin(plane.angle);
  b.t.resize(n);
  b.hs.resize(n);
  b.axs.resize(n);
  const std::size_t j_O =
      std::clamp(static_cast<std::size_t>(std::llround((run.y_O - g.y[run.first]) / g.dy)),
                 run.first, run.last);
  const double y_ref = g.y[j_O], z_ref = directions.rail_z(geometry, g, j_O);
  const Run reach = widened(g, run, kWheelSearch);
  const std::size_t j_top = reach.last, m = reach.last - reach.first + 1, above = j_top - run.last;
  b.tw.resize(m);
  b.nw.resize(m);
  const auto turned = [&](std::size_t j, double z) {
    const double y = g.y[j] - y_ref;
    return std::pair{-y * c + z * sn, y * sn + z * c};
  };
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t j = j_top - i;
    const double z_r = directions.rail_z(geometry, g, j) - z_ref;
    std::tie(b.tw[i], b.nw[i]) = turned(j, z_r - gap_in_run(g, run, j, approach) + approach);
    if (j >= run.first && j <= run.last)
      std::tie(b.t[run.last - j], b.hs[run.last - j]) = turned(j, z_r);  // hs: the rail's n
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = run.last - k;
    // The wheel's n at the rail point's t, between the wheel points about it, searched
    // outwards from the wheel's point at the same sample (the wheel lies within a few samples
    // along t of the rail where they interpenetrate); else, far from the contact, to first
    // order in the slope gamma - delta of the surfaces against the plane.
    const std::size_t at = k + above;
    double h = 0.0, slope = 0.0;
    bool found = false;
    for (std::size_t d = 0; d <= kWheelSearch && !found; ++d) {
      for (const std::size_t i : {at + d, at >= d + 1 ? at - d - 1 : m}) {
        if (i + 1 >= m || !(b.tw[i] <= b.t[k] && b.t[k] <= b.tw[i + 1] && b.tw[i + 1] > b.tw[i]))
          continue;
        slope = (b.nw[i + 1] - b.nw[i]) / (b.tw[i + 1] - b.tw[i]);
        h = b.hs[k] - (b.nw[i] + (b.t[k] - b.tw[i]) * slope) + approach * c;
        found = true;
        break;
      }
    }
    if (!found) {
      const double gamma = directions.angle(geometry, g, j);
      const double f = std::cos(gamma) / std::cos(gamma - plane.angle);
      h = gap_in_run(g, run, j, approach) * f + approach * (c - f);
      slope = std::tan(gamma - plane.angle);
    }
    b.hs[k] = h;
    // The wheel's sag x^2 / (2 R), vertical, seen along the normal at fixed t.
    const double sag = std::max(c - sn * slope, kLeastSag * c);
    b.axs[k] = sag / (2.0 * geometry.rolling_radius(g.z_wheel[j]));
  }
}

// The strips of turned_gap()'s samples: s = 0 at the run's gap minimum, strips every g.dy / c
// from there (the spacing of O's plane where the rail's slope is the same throughout), so that
// a run and any longer one holding it (the fast path's window) have the same strips where they
// overlap; each strip's gap and A linear between the samples about it.
void resampled(const GapSamples& g, const Run& run, RunStrips& out, StripBuffers& b) {
  const std::size_t n = run.last - run.first + 1;
  const double k_O = (g.y[run.last] - run.y_O) / g.dy;
  const std::size_t k0 = n > 1 ? std::min(static_cast<std::size_t>(std::max(k_O, 0.0)), n - 2) : 0;
  const double t_O =
      n > 1 ? b.t[k0] + (k_O - static_cast<double>(k0)) * (b.t[k0 + 1] - b.t[k0]) : 0.0;
  const double ds = g.dy / out.plane.cos;
  const auto m_first = static_cast<long long>(std::ceil((b.t[0] - t_O) / ds - 1e-9));
  const auto m_last = static_cast<long long>(std::floor((b.t[n - 1] - t_O) / ds + 1e-9));
  const std::size_t strips = m_last >= m_first ? static_cast<std::size_t>(m_last - m_first + 1) : 0;
  b.h.resize(strips);
  b.ax.resize(strips);
  b.sample.resize(strips);
  std::size_t k = 0;
  for (std::size_t i = 0; i < strips; ++i) {
    const double t = t_O + static_cast<double>(m_first + static_cast<long long>(i)) * ds;
    while (k + 2 < n && b.t[k + 1] < t) ++k;
    const std::size_t k1 = std::min(k + 1, n - 1);
    const double u = k1 > k ? std::clamp((t - b.t[k]) / (b.t[k1] - b.t[k]), 0.0, 1.0) : 0.0;
    b.h[i] = b.hs[k] + u * (b.hs[k1] - b.hs[k]);
    b.ax[i] = b.axs[k] + u * (b.axs[k1] - b.axs[k]);
    b.sample[i] = static_cast<double>(run.last) - (static_cast<double>(k) + u);
  }
  out.strips.ds = ds;
  out.strips.s_first = static_cast<double>(m_first) * ds;
}

}  // namespace

double weighted_plane_angle(const WheelRailGap& geometry, const GapSamples& g,
                            SampleDirections& directions, const Run& run, double approach,
                            double fallback) {
  double weight = 0.0, moment = 0.0;
  for (std::size_t j = run.first; j <= run.last; ++j) {
    const double penetration = approach - gap_in_run(g, run, j, approach);
    if (!(penetration > 0.0)) continue;
    const double w = penetration * penetration * std::sqrt(penetration);
    weight += w;
    moment += w * directions.angle(geometry, g, j);
  }
  return weight > 0.0 ? moment / weight : fallback;
}

RunStrips strips_of(const WheelRailGap& geometry, const GapSamples& g, SampleDirections& directions,
                    const Run& run, double approach, bool weighted, StripBuffers& b) {
  RunStrips out;
  StripPlane& plane = out.plane;
  plane.weighted = weighted;
  plane.y_O = run.y_O;
  const double angle_O = geometry.contact_angle(run.y_O);
  plane.weighted_angle = weighted_plane_angle(geometry, g, directions, run, approach, angle_O);
  plane.angle = weighted ? plane.weighted_angle : angle_O;
  plane.cos = std::cos(plane.angle);
  if (weighted) {
    // The run's ends are where the vertical gap meets the approach; the gap along the plane's
    // normal may still be below it there, so the strips reach kBeyondRun samples further (within
    // the window): a strip that appeared only as the run grew would make the load jump.
    const Run wider = widened(g, run, kBeyondRun);
    turned_gap(geometry, g, directions, wider, approach, plane, b);
    resampled(g, wider, out, b);
  } else {
    strips_in_plane_at_O(geometry, g, run, approach, out, b);
  }
  out.strips.h = b.h;
  out.strips.ax = b.ax;
  plane.sample = b.sample;
  plane.s_first = out.strips.s_first;
  plane.ds = out.strips.ds;
  return out;
}

}  // namespace wheelwear::contactgeom::detail
