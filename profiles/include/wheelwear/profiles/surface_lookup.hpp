#pragma once
/// Fast z(y) queries on a parametric profile curve: the surface the mating body sees.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "wheelwear/profiles/curve.hpp"

namespace wheelwear::profiles {

/// One point of the surface z(y).
struct SurfaceSample {
  double z = 0.0;      ///< height [m]
  double dz_dy = 0.0;  ///< slope [-]; +-infinity on a vertical tangent
  double s = 0.0;      ///< arc length of the point on the curve [m]
};

/// The single-valued envelope z(y) of a curve that may be vertical or overhang (the S1002 flange
/// back): where several branches share a y, the one facing the mating body wins (largest z for a
/// wheel, smallest z for a rail, z pointing down). The curve is split into pieces monotonic in y;
/// a uniform bucket grid over y maps a query to its candidate pieces in O(1), and a safeguarded
/// Newton iteration solves y(u) = y on each to round-off.
class SurfaceLookup {
 public:
  /// Which branch wins where the curve is multi-valued in y.
  enum class Envelope { max_z, min_z };

  /// An empty lookup: at() returns nullopt everywhere.
  SurfaceLookup() = default;
  /// Index over `curve`; the lookup keeps its own copy of the coefficients.
  SurfaceLookup(const ArcLengthCurve& curve, Envelope envelope);

  /// z(y), or nullopt outside [y_min(), y_max()].
  std::optional<SurfaceSample> at(double y) const;
  /// Smallest lateral coordinate covered [m].
  double y_min() const { return y_min_; }
  /// Largest lateral coordinate covered [m].
  double y_max() const { return y_max_; }
  /// Number of y-monotonic pieces (diagnostics and tests).
  std::size_t piece_count() const { return pieces_.size(); }

 private:
  struct Piece {
    double y_lo, y_hi;        // y range [m]
    double u_lo, u_hi;        // local parameter range within the knot interval [m]
    double y_at_lo, y_at_hi;  // y at u_lo and u_hi [m]
    double s0;                // arc length at the start of the knot interval [m]
    std::array<double, 4> cy, cz;
  };
  std::vector<Piece> pieces_;
  std::vector<std::uint32_t> bucket_start_;
  std::vector<std::uint32_t> bucket_pieces_;
  double y_min_ = 0.0, y_max_ = 0.0, inverse_bucket_width_ = 0.0;
  Envelope envelope_ = Envelope::max_z;
};

}  // namespace wheelwear::profiles
