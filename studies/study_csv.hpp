#pragma once
// The CSV files of the benchmark studies: a header and rows of cells, written sorted, and
// optionally merged with the rows of an earlier file so that a study can rerun only some of
// its methods.

#include <cstddef>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace wheelwear::bench {

/// The fields of one line of `text` between `separator`s (a trailing '\r' dropped).
std::vector<std::string> split(const std::string& text, char separator);

/// Position of `value` in `order`; values not in it sort last (order.size()).
std::size_t rank(const std::vector<std::string>& order, const std::string& value);

/// A results CSV: its header and its rows as cells. With `merge`, the rows of an earlier file
/// at the same path whose method is not rerun are read back first; columns are matched by
/// name, and a column the earlier file lacks takes its entry in `defaults`.
class StudyCsv {
 public:
  StudyCsv(std::filesystem::path path, const std::string& header, bool merge,
           const std::set<std::string>& rerun, const std::map<std::string, std::string>& defaults);

  void add(const std::string& line) {  // one row without its newline
    rows_.push_back(split(line, ','));
  }

  /// Writes header and rows, stably sorted by the rank of each column of `order` in its list.
  void write(const std::vector<std::pair<std::string, std::vector<std::string>>>& order);

 private:
  std::size_t column_(const std::string& name) const { return rank(header_, name); }
  std::filesystem::path path_;
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace wheelwear::bench
