#include "wear_increment.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace wheelwear::pipeline::detail {

wear::WearDistribution smoothed(const wear::WearDistribution& rate, double length) {
  if (length <= 0.0) return rate;
  const auto reach = static_cast<long>(std::ceil(4.0 * length / rate.ds));
  std::vector<double> kernel(static_cast<std::size_t>(2 * reach + 1));
  for (long k = -reach; k <= reach; ++k) {
    const double u = static_cast<double>(k) * rate.ds / length;
    kernel[static_cast<std::size_t>(k + reach)] = std::exp(-0.5 * u * u);
  }
  wear::WearDistribution out = rate;
  std::fill(out.depth.begin(), out.depth.end(), 0.0);
  const auto n = static_cast<long>(rate.depth.size());
  for (long i = 0; i < n; ++i) {
    const double d = rate.depth[static_cast<std::size_t>(i)];
    if (d == 0.0) continue;
    const long lo = std::max(0L, i - reach), hi = std::min(n - 1, i + reach);
    double total = 0.0;
    for (long j = lo; j <= hi; ++j) total += kernel[static_cast<std::size_t>(j - i + reach)];
    for (long j = lo; j <= hi; ++j)
      out.depth[static_cast<std::size_t>(j)] +=
          d * kernel[static_cast<std::size_t>(j - i + reach)] / total;
  }
  return out;
}

profiles::WearDepth depth_on_y(const profiles::Profile& profile, const wear::WearDistribution& rate,
                               double distance) {
  profiles::WearDepth depth;
  for (std::size_t k = 0; k < rate.depth.size(); ++k) {
    const double y = profile.position(rate.s(k)).x();
    if (!depth.y.empty() && !(y > depth.y.back())) continue;
    depth.y.push_back(y);
    depth.depth.push_back(rate.depth[k] * distance);
  }
  return depth;
}

}  // namespace wheelwear::pipeline::detail
