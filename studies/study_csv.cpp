#include "study_csv.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace wheelwear::bench {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator)) {
    if (!part.empty() && part.back() == '\r') part.pop_back();
    parts.push_back(part);
  }
  return parts;
}

std::size_t rank(const std::vector<std::string>& order, const std::string& value) {
  return static_cast<std::size_t>(std::find(order.begin(), order.end(), value) - order.begin());
}

StudyCsv::StudyCsv(std::filesystem::path path, const std::string& header, bool merge,
                   const std::set<std::string>& rerun,
                   const std::map<std::string, std::string>& defaults)
    : path_(std::move(path)), header_(split(header, ',')) {
  if (!merge || !std::filesystem::exists(path_)) return;
  std::ifstream in(path_);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> old_header = split(line, ',');
  for (const std::string& name : old_header)
    if (rank(header_, name) == header_.size())
      throw std::runtime_error(path_.string() + ": column " + name +
                               " is not written by this study; rerun without --methods");
  std::vector<std::size_t> source(header_.size());  // old column of each new one
  for (std::size_t i = 0; i < header_.size(); ++i) {
    source[i] = rank(old_header, header_[i]);
    if (source[i] == old_header.size() && !defaults.contains(header_[i]))
      throw std::runtime_error(path_.string() + ": column " + header_[i] +
                               " is missing; rerun without --methods");
  }
  while (std::getline(in, line)) {
    const std::vector<std::string> old = split(line, ',');
    if (old.size() != old_header.size())
      throw std::runtime_error(path_.string() + ": row '" + line + "' has " +
                               std::to_string(old.size()) + " cells, the header " +
                               std::to_string(old_header.size()));
    if (rerun.contains(old[rank(old_header, "method")])) continue;
    std::vector<std::string> row(header_.size());
    for (std::size_t i = 0; i < header_.size(); ++i)
      row[i] = source[i] < old.size() ? old[source[i]] : defaults.at(header_[i]);
    rows_.push_back(std::move(row));
  }
  std::cerr << path_.string() << ": kept " << rows_.size() << " rows of other methods\n";
}

void StudyCsv::write(const std::vector<std::pair<std::string, std::vector<std::string>>>& order) {
  const auto key = [&](const std::vector<std::string>& row) {
    std::vector<std::size_t> ranks;
    for (const auto& [column, values] : order) ranks.push_back(rank(values, row[column_(column)]));
    return ranks;
  };
  std::stable_sort(rows_.begin(), rows_.end(),
                   [&](const auto& p, const auto& q) { return key(p) < key(q); });
  std::ofstream out(path_);
  const auto write_cells = [&](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << cells[i];
    out << "\n";
  };
  write_cells(header_);
  for (const auto& row : rows_) write_cells(row);
  if (!out) throw std::runtime_error("cannot write " + path_.string());
}

}  // namespace wheelwear::bench
