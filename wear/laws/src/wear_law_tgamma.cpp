#include "wheelwear/wear/wear_law_tgamma.hpp"

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

// Throws InputError("<row>: <problem>") naming the row the way `naming` does.
[[noreturn]] void fail(const detail::RowNaming& naming, std::size_t row, const std::string& what) {
  throw InputError(naming.at(row) + ": " + what);
}

// The linear part slope x + intercept of a regime must not go negative on [lower, upper)
// unless the regime asks for a clamp with a positive floor: a zero floor must not hide a
// negative rate. Returns an x of the range where it is negative (an end of the range, as the
// part is linear), NaN when there is none.
double negative_rate_at(const TgammaRegime& r) {
  if (r.floor > 0.0) return std::numeric_limits<double>::quiet_NaN();
  if (r.slope * r.lower + r.intercept < 0.0) return r.lower;
  if (std::isinf(r.upper))
    return r.slope < 0.0 ? kInfinity : std::numeric_limits<double>::quiet_NaN();
  if (r.slope * r.upper + r.intercept < 0.0) return r.upper;
  return std::numeric_limits<double>::quiet_NaN();
}

void validate(const std::vector<TgammaRegime>& regimes, const detail::RowNaming& naming) {
  if (regimes.empty())
    throw InputError(naming.source + ": a T gamma law needs at least one regime");
  for (std::size_t i = 0; i < regimes.size(); ++i) {
    const TgammaRegime& r = regimes[i];
    detail::check_row_name(r.name, naming, i);
    for (std::size_t j = 0; j < i; ++j) {
      if (regimes[j].name == r.name) {
        fail(naming, i, "regime name '" + r.name + "' repeats that of " + naming.other(j));
      }
    }
    if (!(std::isfinite(r.lower) && r.lower >= 0.0)) {
      fail(naming, i, "lower = " + format_number(r.lower) + " N/mm^2: must be finite and >= 0");
    }
    if (!(r.upper > r.lower)) {
      fail(naming, i,
           "empty regime: upper = " + format_number(r.upper) +
               " N/mm^2 is not above lower = " + format_number(r.lower));
    }
    if (!std::isfinite(r.slope) || !std::isfinite(r.intercept)) {
      fail(naming, i, "slope and intercept must be finite");
    }
    if (!(std::isfinite(r.floor) && r.floor >= 0.0)) {
      fail(naming, i,
           "negative wear rate: floor = " + format_number(r.floor) +
               " ug/(m mm^2) must be finite and >= 0");
    }
    const double x = negative_rate_at(r);
    if (!std::isnan(x)) {
      const std::string value = std::isinf(x) ? "-inf" : format_number(r.slope * x + r.intercept);
      fail(naming, i,
           "negative wear rate: slope*x + intercept = " + value +
               " ug/(m mm^2) at x = " + format_number(x) +
               " N/mm^2 (set a positive floor to ask for max(floor, slope*x + intercept))");
    }
    if (i == 0 && r.lower != 0.0) {
      fail(naming, i, "the first regime must start at 0 N/mm^2, not at " + format_number(r.lower));
    }
    if (i > 0 && r.lower != regimes[i - 1].upper) {
      const bool gap = r.lower > regimes[i - 1].upper;
      fail(naming, i,
           std::string(gap ? "gap" : "overlap") + " between regimes: this one starts at " +
               format_number(r.lower) + " N/mm^2, the one before (" + naming.other(i - 1) +
               ") ends at " + format_number(regimes[i - 1].upper));
    }
  }
  const std::size_t last = regimes.size() - 1;
  if (!std::isinf(regimes[last].upper)) {
    fail(naming, last,
         "the last regime must end at inf (T gamma / A has no upper limit), not at " +
             format_number(regimes[last].upper) + " N/mm^2");
  }
  const TgammaRegime& first = regimes.front();
  const double rate_at_zero = std::fmax(first.floor, first.intercept);
  if (rate_at_zero != 0.0) {
    fail(naming, 0,
         "wear rate at T gamma / A = 0 is " + format_number(rate_at_zero) +
             " ug/(m mm^2): it must be 0 (no frictional work, no wear)");
  }
}

}  // namespace

std::vector<TgammaRegime> usfd_regimes() {
  // Lewis & Dwyer-Joyce (2004), R8T against UIC60 900A, as quoted by Braghin et al. (2006):
  // K = 5.3 x (x < 10.4), 55.0 (10.4 <= x <= 77.2), 61.9 x - 4778.7 (x > 77.2). The floor 55.0
  // of the last regime is our fix of the published branch's drop to ~0 at 77.2.
  return {
      {"mild", 0.0, 10.4, 5.3, 0.0, 0.0},
      {"severe", 10.4, 77.2, 0.0, 55.0, 0.0},
      {"catastrophic", 77.2, kInfinity, 61.9, -4778.7, 55.0},
  };
}

TgammaLaw::TgammaLaw(std::vector<TgammaRegime> regimes, double density, std::string name)
    : regimes_(std::move(regimes)), density_(density), name_(std::move(name)) {
  require_finite("density", density);
  require(density > 0.0, "density", density, "must be > 0 kg/m^3");
  validate(regimes_, {"T gamma law '" + name_ + "'", {}});
  rows_.reserve(regimes_.size());
  for (const TgammaRegime& r : regimes_) rows_.push_back({r.upper, r.slope, r.intercept, r.floor});
  rate_to_depth_ = 1e-3 / density_;
}

TgammaLaw TgammaLaw::usfd(double density) {
  return TgammaLaw(usfd_regimes(), density, "usfd");
}

TgammaLaw TgammaLaw::read_csv(std::istream& in, std::string_view source, double density,
                              std::string name) {
  const std::vector<detail::TableLine> lines = detail::read_table(in, source, kTgammaCsvHeader);
  std::vector<TgammaRegime> regimes;
  detail::RowNaming naming{std::string(source), {}};
  for (const detail::TableLine& line : lines) {
    const auto number = [&](std::size_t column, bool allow_infinity) {
      return detail::table_number(line, column, kTgammaCsvHeader, source, allow_infinity);
    };
    regimes.push_back({line.fields[0], number(1, false), number(2, true), number(3, false),
                       number(4, false), number(5, false)});
    naming.lines.push_back(line.number);
  }
  validate(regimes, naming);  // with the file's line numbers; the constructor checks again
  return TgammaLaw(std::move(regimes), density, std::move(name));
}

TgammaLaw TgammaLaw::load_csv(const std::string& path, double density, std::string name) {
  std::ifstream in(path);
  if (!in) detail::table_error(path, 0, "cannot open the file");
  return read_csv(in, path, density, std::move(name));
}

void TgammaLaw::write_csv(std::ostream& out) const {
  out << kTgammaCsvHeader << '\n';
  for (const TgammaRegime& r : regimes_) {
    detail::write_table_line(out, r.name, {r.lower, r.upper, r.slope, r.intercept, r.floor});
  }
}

}  // namespace wheelwear::wear
