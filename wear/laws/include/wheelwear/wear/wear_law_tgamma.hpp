#pragma once
/// Energy (T gamma) wear laws: a wear rate K [ug/(m mm^2)] that is a piecewise-linear function
/// of the local frictional work density T gamma / A [N/mm^2], turned into a depth through the
/// steel's density. The default is the USFD wear function for R8T wheel steel against UIC60
/// 900A rail (Lewis & Dwyer-Joyce 2004; as used by Braghin, Lewis, Dwyer-Joyce & Bruni, Wear 261
/// (2006) 1253-1264).

#include <algorithm>
#include <iosfwd>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "wheelwear/wear/wear_law_state.hpp"

namespace wheelwear::wear {

/// One regime of a T gamma wear law: on lower <= x < upper (x = T gamma / A [N/mm^2]) the wear
/// rate is K(x) = max(floor, slope x + intercept) [ug/(m mm^2)], mass lost per metre rolled per
/// mm^2 of contact. The floor is how a table asks for a clamp (the USFD fix at 77.2 N/mm^2).
struct TgammaRegime {
  std::string name;        ///< regime name, e.g. "mild"; non-empty, unique within a law
  double lower = 0.0;      ///< first x of the regime [N/mm^2], inclusive, finite, >= 0
  double upper = 0.0;      ///< end of the regime [N/mm^2], exclusive; +inf for the last
  double slope = 0.0;      ///< dK/dx [ug/(m mm^2) per N/mm^2]
  double intercept = 0.0;  ///< K of the linear part at x = 0 [ug/(m mm^2)]
  double floor = 0.0;      ///< lower bound of K on the regime [ug/(m mm^2)], >= 0

  bool operator==(const TgammaRegime&) const = default;
};

/// The USFD wear function, R8T wheel steel against UIC60 900A rail (Lewis & Dwyer-Joyce 2004,
/// twin-disc tests; the three regimes as quoted by Braghin et al. 2006):
///   mild          K = 5.3 x                          for x < 10.4 N/mm^2
///   severe        K = 55.0                           for 10.4 <= x < 77.2
///   catastrophic  K = max(55.0, 61.9 x - 4778.7)     for x >= 77.2
/// The published third branch starts at 61.9 * 77.2 - 4778.7 = -0.02, about 0, at 77.2: K would
/// drop from 55 to 0 and climb back to 55 only at x = 78.09. The floor of 55 (our choice) keeps K
/// continuous and non-decreasing there; above 78.09 it is the published line. At x = 77.2 exactly
/// the published text says "severe"; here the label is "catastrophic", K (55) is the same.
std::vector<TgammaRegime> usfd_regimes();

/// Header of the CSV format of a T gamma table (data/wear/usfd.csv is one; see its README).
inline constexpr std::string_view kTgammaCsvHeader =
    "regime,lower_N_per_mm2,upper_N_per_mm2,slope_ug_per_m_mm2_per_N_per_mm2,"
    "intercept_ug_per_m_mm2,floor_ug_per_m_mm2";

/// A T gamma wear law: depth per passage dz = K(T gamma / A) * dx / rho. K is mass lost per
/// metre rolled per mm^2 of contact (Braghin et al. 2006), and a point of the wheel crossing a
/// cell of length dx rolls dx through it.
class TgammaLaw {
 public:
  /// Density of carbon steel [kg/m^3], the default rho of the mass-to-depth conversion.
  static constexpr double kSteelDensity = 7850.0;

  /// A law from its regimes, in order of x. Throws InputError unless they tile [0, inf) without
  /// gap or overlap (first lower 0, each lower = previous upper, last upper inf), K(0) = 0 (no
  /// frictional work, no wear), every K >= 0 on its regime without relying on a zero floor, and
  /// density > 0.
  /// @param regimes  #regimes >= 1 regimes, in increasing x
  /// @param density  rho [kg/m^3] of the worn (wheel) steel, finite, > 0
  /// @param name     the law's name on the command line and in files
  explicit TgammaLaw(std::vector<TgammaRegime> regimes, double density = kSteelDensity,
                     std::string name = "tgamma-table");

  /// The USFD function of usfd_regimes(), named "usfd".
  static TgammaLaw usfd(double density = kSteelDensity);

  /// Reads a table in the format of kTgammaCsvHeader: '#' comment lines and blank lines are
  /// skipped, the first other line is that header, then one regime per line. Throws InputError
  /// "<source>:<line>: <problem>" on a bad header, a wrong field count, a field that is not a
  /// number, NaN, a gap or an overlap between regimes, a negative rate, an empty file.
  /// @param source  name used in error messages (the file path)
  static TgammaLaw read_csv(std::istream& in, std::string_view source,
                            double density = kSteelDensity, std::string name = "tgamma-table");
  /// read_csv() on the file at `path`; throws InputError when it cannot be opened.
  static TgammaLaw load_csv(const std::string& path, double density = kSteelDensity,
                            std::string name = "tgamma-table");
  /// Writes the table in the format read_csv() reads (numbers round-trip exactly).
  void write_csv(std::ostream& out) const;

  /// The law's name ("usfd" for the default).
  std::string_view name() const { return name_; }
  /// rho [kg/m^3].
  double density() const { return density_; }
  /// The regimes, as given.
  std::span<const TgammaRegime> regimes() const { return regimes_; }
  /// Name of regime `index` (as returned by regime()).
  std::string_view regime_name(int index) const { return regimes_.at(index).name; }

  /// Index of the regime containing x = T gamma / A [N/mm^2]; -1 for NaN or x < 0.
  int regime_of(double x_N_per_mm2) const noexcept {
    if (!(x_N_per_mm2 >= 0.0)) return -1;
    int index = 0;  // upper bounds are increasing: count those at or below x
    for (std::size_t j = 0; j + 1 < rows_.size(); ++j) index += x_N_per_mm2 >= rows_[j].upper;
    return index;
  }
  /// Index of the regime the cell falls in; -1 for an invalid state.
  int regime(const CellState& cell) const noexcept {
    return regime_of(cell.work_density() * kPaToNPerMm2);
  }
  /// Wear rate K [ug/(m mm^2)] at x = T gamma / A [N/mm^2]; NaN for NaN or x < 0.
  double wear_rate(double x_N_per_mm2) const noexcept {
    const int index = regime_of(x_N_per_mm2);
    if (index < 0) return std::numeric_limits<double>::quiet_NaN();
    return rate(rows_[index], x_N_per_mm2);
  }
  /// Depth [m] a point of the wheel loses crossing the cell once: K(|tau||s|) * dx / rho, with
  /// |tau||s| converted from N/m^2 to N/mm^2 and K from ug/(m mm^2) to kg/(m m^2).
  /// @param dx  cell length in the rolling direction [m], >= 0 (not checked)
  double depth_per_passage(const CellState& cell, double dx) const noexcept {
    return wear_rate(cell.work_density() * kPaToNPerMm2) * dx * rate_to_depth_;
  }
  /// depth_per_passage() of every cell of one strip (common dx) into `depth` (same size), the
  /// same numbers computed in blocks of cells with the regimes in the outer loop, so that the
  /// compiler can vectorise across cells.
  void depths_per_passage(std::span<const CellState> cells, double dx,
                          std::span<double> depth) const noexcept {
    constexpr std::size_t kBlock = 64;
    double work[kBlock];
    for (std::size_t start = 0; start < cells.size(); start += kBlock) {
      const std::size_t n = std::min(kBlock, cells.size() - start);
      const CellState* cell = cells.data() + start;
      for (std::size_t i = 0; i < n; ++i) work[i] = cell[i].work_density();
      depths_from_work(work, n, dx, depth.data() + start);
    }
  }
  /// The same for cells given as columns (only their work densities are read).
  void depths_per_passage(const CellColumns& cells, double dx,
                          std::span<double> depth) const noexcept {
    depths_from_work(cells.work.data(), cells.work.size(), dx, depth.data());
  }

 private:
  static constexpr double kPaToNPerMm2 = 1e-6;  // 1 N/m^2 = 1e-6 N/mm^2
  // The numbers of a regime that the per-cell path reads, stored without the name.
  struct Row {
    double upper, slope, intercept, floor;
  };
  // K = max(floor, slope x + intercept) of one regime (no NaN can reach it from wear_rate()).
  static double rate(const Row& row, double x) noexcept {
    const double line = row.slope * x + row.intercept;
    return line > row.floor ? line : row.floor;
  }
  // Depths of n cells of work densities work[] [N/m^2] into depth[], with the regimes in the
  // outer loop so that the loops over cells vectorise.
  void depths_from_work(const double* __restrict work, std::size_t n, double dx,
                        double* __restrict depth) const noexcept {
    const Row first = rows_[0];  // copies: stores to depth[] cannot alias them
    for (std::size_t i = 0; i < n; ++i) depth[i] = rate(first, work[i] * kPaToNPerMm2);
    for (std::size_t j = 1; j < rows_.size(); ++j) {  // regime j starts where j-1 ends
      const Row row = rows_[j];
      const double lower = rows_[j - 1].upper;
      for (std::size_t i = 0; i < n; ++i) {
        const double x = work[i] * kPaToNPerMm2;
        depth[i] = x >= lower ? rate(row, x) : depth[i];
      }
    }
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    const double scale = dx * rate_to_depth_;
    for (std::size_t i = 0; i < n; ++i) depth[i] = (work[i] >= 0.0 ? depth[i] : nan) * scale;
  }
  std::vector<TgammaRegime> regimes_;
  std::vector<Row> rows_;
  double density_;
  double rate_to_depth_;  // 1e-3 / rho: ug/(m mm^2) -> kg/(m m^2) is 1e-9 / 1e-6 = 1e-3
  std::string name_;
};

}  // namespace wheelwear::wear
