#pragma once
// Reads the reference CSV files of tests/data: a header row, then numeric or text cells.

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace wheelwear::testing {

/// One CSV row addressed by column name.
class CsvRow {
 public:
  CsvRow(const std::map<std::string, std::size_t>* columns, std::vector<std::string> cells)
      : columns_(columns), cells_(std::move(cells)) {}
  const std::string& text(const std::string& column) const { return cells_.at(index(column)); }
  double number(const std::string& column) const { return std::stod(text(column)); }
  std::size_t size() const { return cells_.size(); }  ///< cells in this row

 private:
  std::size_t index(const std::string& column) const {
    const auto it = columns_->find(column);
    if (it == columns_->end()) throw std::out_of_range("no CSV column " + column);
    return it->second;
  }
  const std::map<std::string, std::size_t>* columns_;
  std::vector<std::string> cells_;
};

/// A whole CSV file.
class CsvTable {
 public:
  explicit CsvTable(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::string line;
    std::getline(in, line);
    const auto header = split(line);
    for (std::size_t i = 0; i < header.size(); ++i) columns_[header[i]] = i;
    while (std::getline(in, line))
      if (!line.empty()) rows_.emplace_back(&columns_, split(line));
  }
  CsvTable(const CsvTable&) = delete;  // rows point at columns_
  const std::vector<CsvRow>& rows() const { return rows_; }
  std::size_t column_count() const { return columns_.size(); }

 private:
  static std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    while (std::getline(stream, cell, ',')) {
      if (!cell.empty() && cell.back() == '\r') cell.pop_back();  // CRLF files
      cells.push_back(cell);
    }
    return cells;
  }
  std::map<std::string, std::size_t> columns_;
  std::vector<CsvRow> rows_;
};

/// The ellipticity a/b of a reference row's label: "0.5" or "1/0.7" (Kalker's b/a rows), exact
/// where the file's rounded a_over_b column is not.
inline double ellipticity_from_label(const std::string& label) {
  if (label.rfind("1/", 0) == 0) return 1.0 / std::stod(label.substr(2));
  return std::stod(label);
}

/// Path of a file in tests/data.
inline std::string test_data(const std::string& relative) {
  return std::string(WHEELWEAR_TEST_DATA) + "/" + relative;
}

}  // namespace wheelwear::testing
