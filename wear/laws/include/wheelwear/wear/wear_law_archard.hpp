#pragma once
/// Archard's wear law with a wear map: depth per passage dz = k p ds / H, with the wear
/// coefficient k read from a map over the contact pressure ratio p/H and the sliding speed.
/// The default is the KTH map used by Jendel (Wear 253 (2002) 89-99), after Olofsson &
/// Telliskivi's pin-on-disc and full-scale tests.

#include <algorithm>
#include <iosfwd>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "wheelwear/wear/wear_law_state.hpp"

namespace wheelwear::wear {

/// One region of an Archard wear map: where p_over_h_lower <= p/H < p_over_h_upper and
/// speed_lower <= |s| V < speed_upper, the dimensionless wear coefficient is k.
struct ArchardRegime {
  std::string name;             ///< region name, e.g. "seizure"; non-empty, unique within a map
  double p_over_h_lower = 0.0;  ///< contact pressure over hardness [-], inclusive, finite, >= 0
  double p_over_h_upper = 0.0;  ///< [-], exclusive; may be +inf
  double speed_lower = 0.0;     ///< sliding speed [m/s], inclusive, finite, >= 0
  double speed_upper = 0.0;     ///< sliding speed [m/s], exclusive; may be +inf
  double k = 0.0;               ///< Archard wear coefficient [-], finite, >= 0

  bool operator==(const ArchardRegime&) const = default;
};

/// The KTH wear map as used by Jendel (2002) for wheel profile wear: k in 1e-4 units,
///   seizure          p > 0.8 H, any sliding speed              published 300-400, here 350
///   mild_low_speed   p < 0.8 H, sliding speed < 0.2 m/s        published 1-10,    here 5.5
///   severe           p < 0.8 H, 0.2 <= sliding speed < 0.7 m/s published 30-40,   here 35
///   mild_high_speed  p < 0.8 H, sliding speed >= 0.7 m/s       published 1-10,    here 5.5
/// The published map gives ranges; each default is its range's midpoint (our choice). Bounds
/// are inclusive below, exclusive above, in both axes: at p = 0.8 H exactly the cell seizes.
std::vector<ArchardRegime> kth_wear_map();

/// Header of the CSV format of an Archard map (data/wear/archard.csv is one; see its README).
inline constexpr std::string_view kArchardCsvHeader =
    "regime,p_over_H_lower,p_over_H_upper,sliding_speed_lower_m_per_s,"
    "sliding_speed_upper_m_per_s,k";

/// Archard's law per cell: dz = k p ds / H with ds = |s| dx, the distance the surface slides
/// while a point rolls through a cell of length dx (Archard 1953, worn volume = k N s / H, in
/// the local form per unit area used by Jendel 2002).
class ArchardLaw {
 public:
  /// Default hardness H [Pa] of the worn wheel steel: about 255 HB, the rim hardness of ER7
  /// (EN 13262 asks at least 245 HB) and R8T wheels, at 1 HB = 1 kgf/mm^2 = 9.80665 MPa.
  /// The map's seizure limit 0.8 H is then 2.0 GPa, above tread pressures and below the
  /// highest flange-root ones.
  static constexpr double kWheelSteelHardness = 2.5e9;

  /// A law from its map. Throws InputError unless the regions tile the quadrant p/H >= 0,
  /// speed >= 0 without gap or overlap, every k is finite and >= 0, and hardness > 0.
  /// @param map       #map >= 1 regions, in any order
  /// @param hardness  H [Pa] of the worn (wheel) steel, finite, > 0
  /// @param name      the law's name on the command line and in files
  explicit ArchardLaw(std::vector<ArchardRegime> map, double hardness = kWheelSteelHardness,
                      std::string name = "archard-table");

  /// The KTH map of kth_wear_map(), named "archard".
  static ArchardLaw kth(double hardness = kWheelSteelHardness);

  /// Reads a map in the format of kArchardCsvHeader: '#' comment lines and blank lines are
  /// skipped, the first other line is that header, then one region per line. Throws
  /// InputError "<source>:<line>: <problem>" on a bad header, a wrong field count, a field that
  /// is not a number, NaN, a negative k, an empty range, an overlap of two regions, or
  /// "<source>: ..." on a gap in the map or an empty file.
  static ArchardLaw read_csv(std::istream& in, std::string_view source,
                             double hardness = kWheelSteelHardness,
                             std::string name = "archard-table");
  /// read_csv() on the file at `path`; throws InputError when it cannot be opened.
  static ArchardLaw load_csv(const std::string& path, double hardness = kWheelSteelHardness,
                             std::string name = "archard-table");
  /// Writes the map in the format read_csv() reads (numbers round-trip exactly).
  void write_csv(std::ostream& out) const;

  /// The law's name ("archard" for the default).
  std::string_view name() const { return name_; }
  /// H [Pa].
  double hardness() const { return hardness_; }
  /// The regions, as given.
  std::span<const ArchardRegime> regimes() const { return regimes_; }
  /// Name of region `index` (as returned by regime()).
  std::string_view regime_name(int index) const { return regimes_.at(index).name; }

  /// Index of the region containing p/H and the sliding speed [m/s]; -1 for NaN or negatives.
  int regime_of(double p_over_h, double sliding_speed) const noexcept {
    if (!(p_over_h >= 0.0 && sliding_speed >= 0.0)) return -1;
    return grid_region_[grid_cell(p_over_h, sliding_speed)];
  }
  /// Index of the region the cell falls in (p/H and |s| V); -1 for an invalid state.
  int regime(const CellState& cell) const noexcept {
    return regime_of(cell.pressure * inverse_hardness_, cell.sliding_speed());
  }
  /// Wear coefficient k [-] of the cell's region; NaN for an invalid state.
  double coefficient(const CellState& cell) const noexcept {
    const int index = regime(cell);
    return index < 0 ? std::numeric_limits<double>::quiet_NaN() : regimes_[index].k;
  }
  /// Depth [m] a point of the wheel loses crossing the cell once: k p |s| dx / H.
  /// @param dx  cell length in the rolling direction [m], >= 0 (not checked)
  double depth_per_passage(const CellState& cell, double dx) const noexcept {
    return coefficient(cell) * (cell.pressure * inverse_hardness_) * cell.slip * dx;
  }
  /// depth_per_passage() of every cell of one strip (common dx) into `depth` (same size), the
  /// same numbers computed in blocks of cells with the map's bounds in the outer loops, so that
  /// the compiler can vectorise across cells.
  void depths_per_passage(std::span<const CellState> cells, double dx,
                          std::span<double> depth) const noexcept {
    double p[kBlock], slip[kBlock], v[kBlock];
    for (std::size_t start = 0; start < cells.size(); start += kBlock) {
      const std::size_t n = std::min(kBlock, cells.size() - start);
      const CellState* cell = cells.data() + start;
      for (std::size_t i = 0; i < n; ++i) {
        p[i] = cell[i].pressure;
        slip[i] = cell[i].slip;
        v[i] = cell[i].sliding_speed();
      }
      depths_block(p, slip, v, n, dx, depth.data() + start);
    }
  }
  /// The same for cells given as columns (pressure and slip are read, not the work).
  void depths_per_passage(const CellColumns& cells, double dx,
                          std::span<double> depth) const noexcept {
    double v[kBlock];
    for (std::size_t start = 0; start < cells.slip.size(); start += kBlock) {
      const std::size_t n = std::min(kBlock, cells.slip.size() - start);
      const double* slip = cells.slip.data() + start;
      for (std::size_t i = 0; i < n; ++i) v[i] = slip[i] * cells.speed;
      depths_block(cells.pressure.data() + start, slip, v, n, dx, depth.data() + start);
    }
  }

 private:
  static constexpr std::size_t kBlock = 64;  // cells per block of depths_block()

  // Depths of n <= kBlock cells of pressure p [Pa], slip and sliding speed v [m/s] into depth[]:
  // the grid index of grid_cell() counted in doubles (exact for small integers) so that every
  // loop works on one vector type and vectorises, then a select per grid cell rather than a
  // gather, which does not vectorise here.
  void depths_block(const double* __restrict pressure, const double* __restrict slip,
                    const double* __restrict v, std::size_t n, double dx,
                    double* __restrict depth) const noexcept {
    double p[kBlock], cell_index[kBlock], k[kBlock];
    for (std::size_t i = 0; i < n; ++i) {
      p[i] = pressure[i] * inverse_hardness_;
      // an invalid state (NaN, negative) starts far below every grid index and keeps k NaN
      cell_index[i] = (p[i] >= 0.0) & (v[i] >= 0.0) ? 0.0 : -1e9;
      k[i] = std::numeric_limits<double>::quiet_NaN();
    }
    const double speed_cells = speed_cells_;
    for (const double bound : p_bounds_) {
      for (std::size_t i = 0; i < n; ++i) cell_index[i] += p[i] >= bound ? speed_cells : 0.0;
    }
    for (const double bound : v_bounds_) {
      for (std::size_t i = 0; i < n; ++i) cell_index[i] += v[i] >= bound ? 1.0 : 0.0;
    }
    for (std::size_t c = 0; c < grid_k_.size(); ++c) {
      const double index = static_cast<double>(c), k_of_cell = grid_k_[c];
      for (std::size_t i = 0; i < n; ++i) k[i] = cell_index[i] == index ? k_of_cell : k[i];
    }
    for (std::size_t i = 0; i < n; ++i) depth[i] = k[i] * p[i] * slip[i] * dx;
  }

  // The regions tile the quadrant, so the distinct inner bounds of all regions cut it into a
  // grid of cells that each lie in exactly one region: a lookup is two counts and a read.
  int grid_cell(double p_over_h, double sliding_speed) const noexcept {
    int index = 0;
    for (const double bound : p_bounds_) index += (p_over_h >= bound) * speed_cells_;
    for (const double bound : v_bounds_) index += sliding_speed >= bound;
    return index;
  }
  std::vector<ArchardRegime> regimes_;
  std::vector<double> p_bounds_;  // distinct finite bounds > 0 of p/H, increasing
  std::vector<double> v_bounds_;  // distinct finite bounds > 0 of the sliding speed, increasing
  int speed_cells_ = 1;           // v_bounds_.size() + 1
  std::vector<int> grid_region_;  // region of each grid cell, row-major (p, then speed)
  std::vector<double> grid_k_;    // k of each grid cell
  double hardness_;
  double inverse_hardness_;
  std::string name_;
};

}  // namespace wheelwear::wear
