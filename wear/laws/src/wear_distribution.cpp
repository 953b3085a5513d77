#include "wheelwear/wear/wear_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::wear {

namespace {

// Sum of a strip's depths in four interleaved partial sums, which the compiler keeps in
// vector registers (a single running sum would wait on every addition).
double sum_of(const std::vector<double>& values) {
  double part[4] = {0.0, 0.0, 0.0, 0.0};
  const std::size_t n = values.size(), whole = n / 4 * 4;
  for (std::size_t i = 0; i < whole; i += 4) {
    for (int k = 0; k < 4; ++k) part[k] += values[i + k];
  }
  for (std::size_t i = whole; i < n; ++i) part[i - whole] += values[i];
  return (part[0] + part[1]) + (part[2] + part[3]);
}

// Depth per passage of each strip of the solution [m]: the law reads the strip's cells as
// columns of the fields, with one dispatch for the whole patch.
template <class PerStrip>
void strip_depths(const tangential::CellFields& cells, double speed, const WearLaw& law,
                  PerStrip&& per_strip) {
  require(speed > 0.0 && std::isfinite(speed), "V", speed,
          "the rolling speed must be positive (m/s)");
  thread_local std::vector<double> depth;
  const auto nx = static_cast<std::size_t>(cells.nx);
  depth.resize(nx);
  std::visit(
      [&](const auto& l) {
        for (int j = 0; j < cells.ny; ++j) {
          const std::size_t row = static_cast<std::size_t>(j) * nx;
          const CellColumns columns{{cells.pressure.data() + row, nx},
                                    {cells.work.data() + row, nx},
                                    {cells.slip_norm.data() + row, nx},
                                    speed};
          l.depths_per_passage(columns, cells.dx[j], depth);
          per_strip(j, cells.strip_y[j], sum_of(depth));
        }
      },
      law);
}

}  // namespace

WearDistribution WearDistribution::zeros(double s_first, double ds, std::size_t bins) {
  require(ds > 0.0 && std::isfinite(ds), "ds", ds, "the bin width must be positive (m)");
  require_finite("s_first", s_first);
  return WearDistribution{s_first, ds, std::vector<double>(bins, 0.0)};
}

double WearDistribution::area() const {
  double sum = 0.0;
  for (double d : depth) sum += d;
  return sum * ds;
}

void WearDistribution::add(const WearDistribution& other, double weight) {
  require(other.depth.size() == depth.size() && other.ds == ds && other.s_first == s_first,
          "wear grid", static_cast<double>(other.depth.size()),
          "distributions must share the same arc-length grid to be added");
  for (std::size_t k = 0; k < depth.size(); ++k) depth[k] += weight * other.depth[k];
}

WearSummary summarise(const WearDistribution& w) {
  WearSummary out;
  out.volume_per_metre = w.area();
  double moment = 0.0, sum = 0.0;
  std::size_t peak = 0;
  for (std::size_t k = 0; k < w.depth.size(); ++k) {
    moment += w.depth[k] * w.s(k);
    sum += w.depth[k];
    if (w.depth[k] > w.depth[peak]) peak = k;
  }
  if (sum <= 0.0) {
    // No wear: no position to report (NaN, written as null).
    out.peak_s = out.centroid_s = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  out.peak_depth = w.depth[peak];
  out.peak_s = w.s(peak);
  out.centroid_s = moment / sum;
  std::size_t lo = w.depth.size(), hi = 0;
  for (std::size_t k = 0; k < w.depth.size(); ++k) {
    if (w.depth[k] > 0.05 * out.peak_depth) {
      lo = std::min(lo, k);
      hi = std::max(hi, k);
    }
  }
  out.band_width = (static_cast<double>(hi - lo) + 1.0) * w.ds;
  return out;
}

double accumulate_wear(const tangential::CellFields& cells, double speed, const WearLaw& law,
                       const WheelPlacement& placement, double weight, WearDistribution& into) {
  require(placement.wheel_radius > 0.0, "wheel_radius", placement.wheel_radius,
          "the rolling radius must be positive (m)");
  const double per_metre = weight / (2.0 * std::numbers::pi * placement.wheel_radius);
  const double half = 0.5 * cells.dy;
  const double inv_ds = 1.0 / into.ds;
  const auto bins = static_cast<long>(into.depth.size());
  double outside = 0.0;
  strip_depths(cells, speed, law, [&](int, double y, double depth) {
    if (depth == 0.0) return;
    const double d = depth * per_metre;
    // The strip covers arc lengths [s_c - dy/2, s_c + dy/2] on the wheel, s_c = s_O - y
    // (+y points to the flange, the arc length grows towards the field side).
    const double s_lo = placement.s_at_O - y - half;
    const double s_hi = placement.s_at_O - y + half;
    const double u_lo = (s_lo - into.s_first) * inv_ds + 0.5;  // in bins from the grid's start
    const double u_hi = (s_hi - into.s_first) * inv_ds + 0.5;
    for (long k = static_cast<long>(std::floor(u_lo)); k <= static_cast<long>(std::floor(u_hi));
         ++k) {
      const double overlap = std::min(u_hi, static_cast<double>(k + 1)) -
                             std::max(u_lo, static_cast<double>(k));  // in bins
      if (overlap <= 0.0) continue;
      // depth d over a width overlap*ds of a bin of width ds adds d*overlap to its mean depth
      if (k >= 0 && k < bins) {
        into.depth[static_cast<std::size_t>(k)] += d * overlap;
      } else {
        outside += d * overlap * into.ds;
      }
    }
  });
  return outside;
}

double cell_wear_area(const tangential::CellFields& cells, double speed, const WearLaw& law,
                      double wheel_radius) {
  double area = 0.0;
  strip_depths(cells, speed, law, [&](int, double, double depth) { area += depth * cells.dy; });
  return area / (2.0 * std::numbers::pi * wheel_radius);
}

}  // namespace wheelwear::wear
