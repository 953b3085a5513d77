#include "wheelwear/wear/wear_law_archard.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <ostream>
#include <utility>

#include "wear_law_csv.hpp"
#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::wear {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

using core::format_number;

[[noreturn]] void fail(const detail::RowNaming& naming, std::size_t row, const std::string& what) {
  throw InputError(naming.at(row) + ": " + what);
}

void check_range(const detail::RowNaming& naming, std::size_t row, std::string_view quantity,
                 double lower, double upper) {
  if (!(std::isfinite(lower) && lower >= 0.0)) {
    fail(naming, row,
         std::string(quantity) + " lower bound " + format_number(lower) +
             ": must be finite and >= 0");
  }
  if (!(upper > lower)) {
    fail(naming, row,
         "empty " + std::string(quantity) + " range: upper bound " + format_number(upper) +
             " is not above lower bound " + format_number(lower));
  }
}

// "[a, b)" for messages.
std::string interval(double lower, double upper) {
  std::string text("[");  // appended piece by piece: GCC 12 warns falsely on "[" + string&&
  text.append(format_number(lower)).append(", ").append(format_number(upper)).append(")");
  return text;
}

// The sorted distinct bounds of one axis, with 0 and inf added so that the cells between
// consecutive bounds cover the whole half-line.
std::vector<double> breakpoints(const std::vector<ArchardRegime>& map, bool pressure_axis) {
  std::vector<double> points{0.0, kInfinity};
  for (const ArchardRegime& r : map) {
    points.push_back(pressure_axis ? r.p_over_h_lower : r.speed_lower);
    points.push_back(pressure_axis ? r.p_over_h_upper : r.speed_upper);
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

// A point strictly inside [lower, upper), for the coverage test.
double inside(double lower, double upper) {
  return std::isinf(upper) ? lower + 1.0 : 0.5 * (lower + upper);
}

// Every cell of the grid the bounds of all regions make must lie in exactly one region.
void check_tiling(const std::vector<ArchardRegime>& map, const detail::RowNaming& naming) {
  const std::vector<double> p = breakpoints(map, true);
  const std::vector<double> v = breakpoints(map, false);
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    for (std::size_t j = 0; j + 1 < v.size(); ++j) {
      const double p_probe = inside(p[i], p[i + 1]);
      const double v_probe = inside(v[j], v[j + 1]);
      const std::string cell = "p/H in " + interval(p[i], p[i + 1]) + " and sliding speed in " +
                               interval(v[j], v[j + 1]) + " m/s";
      std::size_t first = map.size();
      for (std::size_t r = 0; r < map.size(); ++r) {
        const ArchardRegime& region = map[r];
        const bool covers = p_probe >= region.p_over_h_lower && p_probe < region.p_over_h_upper &&
                            v_probe >= region.speed_lower && v_probe < region.speed_upper;
        if (!covers) continue;
        if (first == map.size()) {
          first = r;
        } else {
          fail(naming, r,
               "overlap: region '" + region.name + "' and region '" + map[first].name + "' (" +
                   naming.other(first) + ") both cover " + cell);
        }
      }
      if (first == map.size()) {
        throw InputError(naming.source + ": gap in the wear map: no region covers " + cell);
      }
    }
  }
}

void validate(const std::vector<ArchardRegime>& map, const detail::RowNaming& naming) {
  if (map.empty())
    throw InputError(naming.source + ": an Archard wear map needs at least one region");
  for (std::size_t i = 0; i < map.size(); ++i) {
    const ArchardRegime& r = map[i];
    detail::check_row_name(r.name, naming, i);
    for (std::size_t j = 0; j < i; ++j) {
      if (map[j].name == r.name) {
        fail(naming, i, "region name '" + r.name + "' repeats that of " + naming.other(j));
      }
    }
    check_range(naming, i, "p/H", r.p_over_h_lower, r.p_over_h_upper);
    check_range(naming, i, "sliding speed", r.speed_lower, r.speed_upper);
    if (!(std::isfinite(r.k) && r.k >= 0.0)) {
      fail(naming, i,
           "negative wear coefficient: k = " + format_number(r.k) + " must be finite and >= 0");
    }
  }
  check_tiling(map, naming);
}

}  // namespace

std::vector<ArchardRegime> kth_wear_map() {
  // Jendel (2002), after Olofsson & Telliskivi: k = 300-400e-4 where p > 0.8 H; otherwise
  // 1-10e-4 below 0.2 m/s, 30-40e-4 from 0.2 to 0.7 m/s, 1-10e-4 above 0.7 m/s. Each default k
  // is the midpoint of its range.
  return {
      {"seizure", 0.8, kInfinity, 0.0, kInfinity, 350e-4},
      {"mild_low_speed", 0.0, 0.8, 0.0, 0.2, 5.5e-4},
      {"severe", 0.0, 0.8, 0.2, 0.7, 35e-4},
      {"mild_high_speed", 0.0, 0.8, 0.7, kInfinity, 5.5e-4},
  };
}

ArchardLaw::ArchardLaw(std::vector<ArchardRegime> map, double hardness, std::string name)
    : regimes_(std::move(map)), hardness_(hardness), name_(std::move(name)) {
  require_finite("hardness", hardness);
  require(hardness > 0.0, "hardness", hardness, "must be > 0 Pa");
  validate(regimes_, {"Archard law '" + name_ + "'", {}});
  // The grid of the per-cell lookup: the inner bounds of both axes, and each cell's region.
  for (const ArchardRegime& r : regimes_) {
    for (const double bound : {r.p_over_h_lower, r.p_over_h_upper}) {
      if (bound > 0.0 && std::isfinite(bound)) p_bounds_.push_back(bound);
    }
    for (const double bound : {r.speed_lower, r.speed_upper}) {
      if (bound > 0.0 && std::isfinite(bound)) v_bounds_.push_back(bound);
    }
  }
  for (std::vector<double>* bounds : {&p_bounds_, &v_bounds_}) {
    std::sort(bounds->begin(), bounds->end());
    bounds->erase(std::unique(bounds->begin(), bounds->end()), bounds->end());
  }
  speed_cells_ = static_cast<int>(v_bounds_.size()) + 1;
  for (std::size_t i = 0; i <= p_bounds_.size(); ++i) {
    for (std::size_t j = 0; j <= v_bounds_.size(); ++j) {
      const double p = i == 0 ? 0.0 : p_bounds_[i - 1];  // each cell's lower corner
      const double v = j == 0 ? 0.0 : v_bounds_[j - 1];
      int region = -1;
      for (std::size_t r = 0; r < regimes_.size(); ++r) {
        const ArchardRegime& m = regimes_[r];
        if (p >= m.p_over_h_lower && p < m.p_over_h_upper && v >= m.speed_lower &&
            v < m.speed_upper) {
          region = static_cast<int>(r);
        }
      }
      grid_region_.push_back(region);  // >= 0: validate() proved the tiling
      grid_k_.push_back(regimes_[region].k);
    }
  }
  inverse_hardness_ = 1.0 / hardness_;
}

ArchardLaw ArchardLaw::kth(double hardness) {
  return ArchardLaw(kth_wear_map(), hardness, "archard");
}

ArchardLaw ArchardLaw::read_csv(std::istream& in, std::string_view source, double hardness,
                                std::string name) {
  const std::vector<detail::TableLine> lines = detail::read_table(in, source, kArchardCsvHeader);
  std::vector<ArchardRegime> map;
  detail::RowNaming naming{std::string(source), {}};
  for (const detail::TableLine& line : lines) {
    const auto number = [&](std::size_t column, bool allow_infinity) {
      return detail::table_number(line, column, kArchardCsvHeader, source, allow_infinity);
    };
    map.push_back({line.fields[0], number(1, false), number(2, true), number(3, false),
                   number(4, true), number(5, false)});
    naming.lines.push_back(line.number);
  }
  validate(map, naming);  // with the file's line numbers; the constructor checks again
  return ArchardLaw(std::move(map), hardness, std::move(name));
}

ArchardLaw ArchardLaw::load_csv(const std::string& path, double hardness, std::string name) {
  std::ifstream in(path);
  if (!in) detail::table_error(path, 0, "cannot open the file");
  return read_csv(in, path, hardness, std::move(name));
}

void ArchardLaw::write_csv(std::ostream& out) const {
  out << kArchardCsvHeader << '\n';
  for (const ArchardRegime& r : regimes_) {
    detail::write_table_line(
        out, r.name, {r.p_over_h_lower, r.p_over_h_upper, r.speed_lower, r.speed_upper, r.k});
  }
}

}  // namespace wheelwear::wear
