#pragma once
// The initial contact point O of a contact region whose gap has several minima of nearly the
// same depth (internal to contactgeom).
//
// O is the gap's minimum. Where a wide, nearly conformal patch (a worn, flat tread on its rail)
// has two minima far apart whose depths cross as the wheelset shifts, the lowest of them jumps
// across the patch, and with it everything measured at O: the rolling radius, the contact angle,
// the SDEC's shape number and the creep forces. A vehicle's balance has no solution across
// such a jump. So O is the weighted mean of the minima that lie within `depth` of the lowest:
// a minimum's weight falls smoothly from 1 (as deep as the lowest) to 0 (`depth` above it), and
// with its prominence (the rise from it to the lowest ridge towards a deeper minimum) below
// `prominence`, so a minimum that appears or vanishes on a slope enters with no weight. Where
// one minimum is within reach, O is that minimum, refined by the parabola through its sample
// and both neighbours: the single-basin result is unchanged.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "parabola_vertex.hpp"

namespace wheelwear::contactgeom::detail {

// How far the lowest gap may rise and still share O with a deeper minimum [m]: 4 um is 5-15 %
// of a tread contact's local approach, so two basins blend over 0.1-0.4 mm of lateral shift
// where their depths cross at 0.01-0.05 um per um.
constexpr double kMinimumBlendDepth = 4e-6;
// The prominence below which a minimum counts only in part [m]: a ripple of a smoothed profile.
constexpr double kMinimumProminence = 0.05e-6;
// Of a minimum's second difference, how far above it its lower neighbour still shares the
// refinement (refine_minimum): narrow, so that a basin's refined minimum depends on its own three
// samples but within a twentieth of their curvature of a tie.
constexpr double kTieBlend = 0.05;

struct BlendedMinimum {
  double index = 0.0;  // position in samples (fractional)
  double h = 0.0;      // the weighted minima's gap [m]
};

// The vertex of the parabola through samples k - 1, k, k + 1 of `h`, as a position in samples;
// none where a sample is missing or the parabola does not open upwards.
template <class Gap>
std::optional<ParabolaVertex> vertex_at(const Gap& h, std::ptrdiff_t k) {
  const double left = h(k - 1), middle = h(k), right = h(k + 1);
  if (!std::isfinite(left) || !std::isfinite(middle) || !std::isfinite(right)) return std::nullopt;
  auto vertex = parabola_vertex(left, middle, right);
  if (vertex) vertex->offset += static_cast<double>(k);
  return vertex;
}

// The minimum at sample p (p == q) or between two equal samples p, q = p + 1, refined by the
// parabola through its sample and both neighbours. Where its lower neighbour nearly ties with
// it, that parabola is blended with the one through the neighbour (half each at a tie, none
// once the neighbour lies kTieBlend of the three samples' second difference above): the refined
// minimum then moves continuously as the lowest sample passes to its neighbour, where either
// parabola alone jumps by the basin's asymmetry (on coarse strips across a steep flank, 1.7 um
// of a 180 um approach).
template <class Gap>
void refine_minimum(const Gap& h, std::ptrdiff_t p, std::ptrdiff_t q, double& index, double& gap) {
  const auto own = vertex_at(h, p);
  if (q == p + 1) {  // a tie: both parabolas, half each
    const auto other = vertex_at(h, q);
    if (own && other) {
      index = 0.5 * (own->offset + other->offset);
      gap = 0.5 * (own->h + other->h);
    }
    return;
  }
  if (!own) return;
  index = own->offset;
  gap = own->h;
  const double left = h(p - 1), right = h(p + 1), middle = h(p);
  const std::ptrdiff_t neighbour = right <= left ? p + 1 : p - 1;
  const double rise = std::min(left, right) - middle;
  const double scale = kTieBlend * (left - 2.0 * middle + right);
  const auto other = vertex_at(h, neighbour);
  // Its vertex lies between the two samples near a tie; beyond them (a flat gap past the
  // neighbour) it is no refinement of this minimum.
  const double lo = static_cast<double>(std::min(p, neighbour));
  if (!other || !(rise < scale) || !(other->offset >= lo && other->offset <= lo + 1.0)) return;
  const double t = rise / scale;
  const double w = 0.5 * (1.0 - t * t * (3.0 - 2.0 * t));
  index += w * (other->offset - index);
  gap += w * (other->h - gap);
}

// O of samples [first, last] of the gap `h(j)` (a callable; +inf for a sample that is missing
// or must not serve as a neighbour). The samples around the range may serve as neighbours.
template <class Gap>
BlendedMinimum blended_minimum(const Gap& h, std::ptrdiff_t first, std::ptrdiff_t last,
                               double depth = kMinimumBlendDepth,
                               double prominence = kMinimumProminence) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  struct Minimum {
    double index, h;  // refined by the parabola
    double sample;    // the sample's own gap: prominences compare samples, so that a minimum
                      // born between two equal samples starts with none
  };
  thread_local std::vector<Minimum> minima;
  thread_local std::vector<double> ridges;  // ridges[i]: highest gap between minima i and i + 1
  minima.clear();
  ridges.clear();
  double ridge = -inf;
  for (std::ptrdiff_t p = first; p <= last;) {
    std::ptrdiff_t q = p;
    const double hp = h(p);
    while (q + 1 <= last && h(q + 1) == hp) ++q;
    const double left = h(p - 1), right = h(q + 1);
    if (left > hp && right > hp) {
      Minimum m{0.5 * static_cast<double>(p + q), hp, hp};
      if (q <= p + 1) refine_minimum(h, p, q, m.index, m.h);
      if (!minima.empty()) ridges.push_back(ridge);
      minima.push_back(m);
      ridge = -inf;
    } else {
      ridge = std::max(ridge, hp);
    }
    p = q + 1;
  }
  if (minima.empty()) {  // a range without a sample lower than its neighbours: its lowest one
    std::ptrdiff_t k = first;
    for (std::ptrdiff_t j = first; j <= last; ++j)
      if (h(j) < h(k)) k = j;
    return {static_cast<double>(k), h(k)};
  }
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < minima.size(); ++i)
    if (minima[i].h < minima[lowest].h) lowest = i;
  if (minima.size() == 1) return {minima[0].index, minima[0].h};
  // Rise from minimum i to the lowest ridge on the way to a deeper minimum (inf: none).
  const auto prominence_of = [&](std::size_t i) {
    double rise = inf, r = -inf;
    for (std::size_t k = i; k-- > 0;) {
      r = std::max(r, ridges[k]);
      if (minima[k].sample < minima[i].sample) {
        rise = r - minima[i].sample;
        break;
      }
    }
    r = -inf;
    for (std::size_t k = i; k + 1 < minima.size(); ++k) {
      r = std::max(r, ridges[k]);
      if (minima[k + 1].sample < minima[i].sample) {
        rise = std::min(rise, r - minima[i].sample);
        break;
      }
    }
    return rise;
  };
  double weights = 0.0, index = 0.0, gap = 0.0;
  for (std::size_t i = 0; i < minima.size(); ++i) {
    const double t = std::clamp((minima[i].h - minima[lowest].h) / depth, 0.0, 1.0);
    double w = 1.0 - t * t * (3.0 - 2.0 * t);
    if (w > 0.0 && i != lowest) w *= std::clamp(prominence_of(i) / prominence, 0.0, 1.0);
    weights += w;
    index += w * minima[i].index;
    gap += w * minima[i].h;
  }
  return {index / weights, gap / weights};
}

}  // namespace wheelwear::contactgeom::detail
