#pragma once
// Reading and writing the CSV tables of the wear laws, and naming a table's rows in error
// messages. Private to the wear module.

#include <cstddef>
#include <initializer_list>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace wheelwear::wear::detail {

// One data line of a table: its 1-based line number in the source and its trimmed fields.
struct TableLine {
  int number = 0;
  std::vector<std::string> fields;
};

// How errors name a table and its rows: "<source>:<line>" for a file, "<source>: regime <i>"
// for regimes given in code (then `lines` is empty).
struct RowNaming {
  std::string source;
  std::vector<int> lines;

  std::string at(std::size_t row) const;     // prefix of an error about `row`
  std::string other(std::size_t row) const;  // "line 7" / "regime 3", to refer to another row
};

// Throws InputError("<source>:<line>: <problem>"), or "<source>: <problem>" when line <= 0.
[[noreturn]] void table_error(std::string_view source, int line, std::string_view problem);

// Reads the lines of a table: skips blank lines and lines starting with '#', checks that the
// first other line equals `header` (fields compared after trimming spaces) and that every data
// line has as many fields. Throws InputError on an empty file, a bad header, a wrong field
// count or a header without data lines.
std::vector<TableLine> read_table(std::istream& in, std::string_view source,
                                  std::string_view header);

// Field `column` of `line` as a number. Throws InputError naming the source, the line and the
// header's column when the field is not a number, is NaN, or is infinite and !allow_infinity.
double table_number(const TableLine& line, std::size_t column, std::string_view header,
                    std::string_view source, bool allow_infinity);

// Checks a regime or region name: non-empty, no comma, no line break, no surrounding spaces,
// not starting with '#', so that it survives a write and a read. Throws InputError otherwise.
void check_row_name(const std::string& name, const RowNaming& naming, std::size_t row);

// Writes one table line: the name, then the numbers, comma-separated.
void write_table_line(std::ostream& out, const std::string& name,
                      std::initializer_list<double> numbers);

}  // namespace wheelwear::wear::detail
