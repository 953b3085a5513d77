#pragma once
// The strict reader of CONTACT's reference files (tests/data/contact): one file with its
// expected row count, its units converted to SI in one place (contact_cases.hpp uses it).

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include "support/csv_table.hpp"

namespace wheelwear::testing::contact {

/// One reference file and the number of data rows it holds.
struct ContactFile {
  std::string_view name;  ///< file name in tests/data/contact
  std::size_t rows = 0;   ///< data rows (header excluded)
};

namespace detail {

// The files' units, converted to SI only here.
inline double mm(double v) {
  return v * 1e-3;
}
inline double mm2(double v) {
  return v * 1e-6;
}
inline double mpa(double v) {
  return v * 1e6;
}
inline double per_mm(double v) {
  return v * 1e3;
}  // 1/mm, N/mm, W/mm -> per m
inline double n_mm(double v) {
  return v * 1e-3;
}  // N mm -> N m

/// One file read strictly: it exists, holds exactly the expected rows, every row has a cell
/// for every column, and every number parses whole and is finite. Failures throw
/// std::runtime_error naming the file.
class Reader {
 public:
  Reader(const ContactFile& file, const std::string& directory)
      : path_(directory + "/" + std::string(file.name)), table_(path_) {
    if (table_.rows().size() != file.rows)
      fail("holds " + std::to_string(table_.rows().size()) + " data rows, expected " +
           std::to_string(file.rows));
    for (std::size_t k = 0; k < table_.rows().size(); ++k)
      if (table_.rows()[k].size() != table_.column_count())
        fail("row " + std::to_string(k + 1) + " has " + std::to_string(table_.rows()[k].size()) +
             " cells, the header " + std::to_string(table_.column_count()));
  }
  Reader(const Reader&) = delete;

  std::size_t rows() const { return table_.rows().size(); }

  const std::string& text(std::size_t k, const std::string& column) const {
    try {
      return table_.rows()[k].text(column);
    } catch (const std::out_of_range&) {
      fail("no column " + column);
    }
  }

  double number(std::size_t k, const std::string& column) const {
    const std::string& cell = text(k, column);
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(cell, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (cell.empty() || used != cell.size() || !std::isfinite(value))
      fail("row " + std::to_string(k + 1) + ", " + column + ": '" + cell + "' is not a number");
    return value;
  }

  int count(std::size_t k, const std::string& column) const {
    const double value = number(k, column);
    if (value != std::round(value) || std::abs(value) > 1e9)
      fail("row " + std::to_string(k + 1) + ", " + column + ": not a whole number");
    return static_cast<int>(value);
  }

  /// The ellipticity a/b of a label "0.5" or "1/0.7".
  double ellipticity(std::size_t k) const {
    const std::string& label = text(k, "g_label");
    try {
      return ellipticity_from_label(label);
    } catch (const std::exception&) {
      fail("row " + std::to_string(k + 1) + ": g_label '" + label + "' is not an ellipticity");
    }
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("CONTACT reference " + path_ + ": " + what);
  }

 private:
  std::string path_;
  CsvTable table_;
};

}  // namespace detail

}  // namespace wheelwear::testing::contact
