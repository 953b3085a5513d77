#include "wheelwear/profiles/surface_lookup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wheelwear::profiles {

namespace {

double cubic(const std::array<double, 4>& c, double u) {
  return c[0] + u * (c[1] + u * (c[2] + u * c[3]));
}

double cubic_slope(const std::array<double, 4>& c, double u) {
  return c[1] + u * (2.0 * c[2] + 3.0 * u * c[3]);
}

// Roots of y'(u) = c1 + 2 c2 u + 3 c3 u^2 strictly inside (0, h), ascending.
std::vector<double> turning_points(const std::array<double, 4>& c, double h) {
  std::vector<double> roots;
  const double a = 3.0 * c[3], b = 2.0 * c[2], k = c[1];
  const double scale = std::abs(a) * h * h + std::abs(b) * h + std::abs(k);
  if (scale == 0.0) return roots;
  if (std::abs(a) * h * h <= 1e-14 * scale) {
    if (b != 0.0) roots.push_back(-k / b);
  } else {
    const double disc = b * b - 4.0 * a * k;
    if (disc >= 0.0) {
      // Numerically stable pair (Numerical Recipes, section 5.6).
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      if (q != 0.0) roots.push_back(k / q);
      roots.push_back(q / a);
    }
  }
  std::vector<double> inside;
  for (double r : roots)
    if (r > 0.0 && r < h) inside.push_back(r);
  std::sort(inside.begin(), inside.end());
  return inside;
}

}  // namespace

SurfaceLookup::SurfaceLookup(const ArcLengthCurve& curve, Envelope envelope) : envelope_(envelope) {
  const auto& ys = curve.y_spline();
  const auto& zs = curve.z_spline();
  const double h = curve.knot_spacing();
  y_min_ = std::numeric_limits<double>::infinity();
  y_max_ = -y_min_;
  for (std::size_t i = 0; i < ys.segment_count(); ++i) {
    const auto& cy = ys.coefficients(i);
    const double width = ys.knots()[i + 1] - ys.knots()[i];
    std::vector<double> cuts = turning_points(cy, width);
    cuts.insert(cuts.begin(), 0.0);
    cuts.push_back(width);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      Piece piece;
      piece.u_lo = cuts[k];
      piece.u_hi = cuts[k + 1];
      piece.y_at_lo = cubic(cy, piece.u_lo);
      piece.y_at_hi = cubic(cy, piece.u_hi);
      piece.y_lo = std::min(piece.y_at_lo, piece.y_at_hi);
      piece.y_hi = std::max(piece.y_at_lo, piece.y_at_hi);
      // A piece with no lateral extent (an exactly vertical stretch) adds nothing to z(y): its
      // neighbours cover its y.
      if (piece.y_hi - piece.y_lo <= 1e-15 * h) continue;
      piece.s0 = ys.knots()[i];
      piece.cy = cy;
      piece.cz = zs.coefficients(i);
      y_min_ = std::min(y_min_, piece.y_lo);
      y_max_ = std::max(y_max_, piece.y_hi);
      pieces_.push_back(piece);
    }
  }
  if (pieces_.empty()) {
    y_min_ = y_max_ = 0.0;
    bucket_start_.assign(2, 0);
    return;
  }
  // About one piece per bucket: a query then tests one or two pieces, more only where the curve
  // is multi-valued in y.
  const std::size_t buckets = pieces_.size();
  inverse_bucket_width_ = y_max_ > y_min_ ? static_cast<double>(buckets) / (y_max_ - y_min_) : 0.0;
  auto bucket_of = [&](double y) {
    const double k = std::floor((y - y_min_) * inverse_bucket_width_);
    return static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(buckets - 1)));
  };
  bucket_start_.assign(buckets + 1, 0);
  for (const Piece& p : pieces_)
    for (std::size_t k = bucket_of(p.y_lo); k <= bucket_of(p.y_hi); ++k) ++bucket_start_[k + 1];
  for (std::size_t k = 0; k < buckets; ++k) bucket_start_[k + 1] += bucket_start_[k];
  bucket_pieces_.resize(bucket_start_.back());
  std::vector<std::uint32_t> fill(bucket_start_.begin(), bucket_start_.end() - 1);
  for (std::size_t j = 0; j < pieces_.size(); ++j)
    for (std::size_t k = bucket_of(pieces_[j].y_lo); k <= bucket_of(pieces_[j].y_hi); ++k)
      bucket_pieces_[fill[k]++] = static_cast<std::uint32_t>(j);
}

std::optional<SurfaceSample> SurfaceLookup::at(double y) const {
  if (pieces_.empty() || !(y >= y_min_ && y <= y_max_)) return std::nullopt;
  const std::size_t buckets = bucket_start_.size() - 1;
  const double kf = std::floor((y - y_min_) * inverse_bucket_width_);
  const auto k = static_cast<std::size_t>(std::clamp(kf, 0.0, static_cast<double>(buckets - 1)));
  std::optional<SurfaceSample> best;
  for (std::uint32_t idx = bucket_start_[k]; idx < bucket_start_[k + 1]; ++idx) {
    const Piece& p = pieces_[bucket_pieces_[idx]];
    if (y < p.y_lo || y > p.y_hi) continue;
    const bool increasing = p.y_at_hi > p.y_at_lo;
    double lo = p.u_lo, hi = p.u_hi;
    double u = p.u_lo + (p.u_hi - p.u_lo) * (y - p.y_at_lo) / (p.y_at_hi - p.y_at_lo);
    for (int iteration = 0; iteration < 60; ++iteration) {
      const double f = cubic(p.cy, u) - y;
      if ((f > 0.0) == increasing)
        hi = u;
      else
        lo = u;
      if (f == 0.0 || hi - lo <= 1e-15 * (p.u_hi - p.u_lo)) break;
      const double d = cubic_slope(p.cy, u);
      double next = d != 0.0 ? u - f / d : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - u) <= 1e-16 * (p.u_hi - p.u_lo)) break;
      u = next;
    }
    const double z = cubic(p.cz, u);
    const bool better = !best || (envelope_ == Envelope::max_z ? z > best->z : z < best->z);
    if (!better) continue;
    const double dy = cubic_slope(p.cy, u);
    const double dz = cubic_slope(p.cz, u);
    const double slope =
        dy != 0.0 ? dz / dy : std::copysign(std::numeric_limits<double>::infinity(), dz);
    best = SurfaceSample{z, slope, p.s0 + u};
  }
  return best;
}

}  // namespace wheelwear::profiles
