#pragma once
/// Comma-separated tables as RFC 4180 writes them — fields in double quotes may hold commas,
/// line breaks and doubled quotes — with what hand-written tables add: a UTF-8 byte-order mark
/// at the start, lines starting with '#' (comments) and blank lines, both skipped between
/// records, and blanks around unquoted fields.

#include <string>
#include <string_view>
#include <vector>

namespace wheelwear::core {

/// One record of a table and the line it starts on (1-based).
struct CsvRecord {
  std::vector<std::string> fields;
  int line = 0;
};

/// The records of `text`, in order. Unquoted fields are trimmed; quoted ones are kept as
/// written between their quotes ("" stands for one quote). Throws InputError naming `source`
/// and the line for a quote that is never closed or text after a closing quote.
std::vector<CsvRecord> read_csv(std::string_view text, std::string_view source);

/// `field` as one CSV field: unchanged when it needs no quotes, else in double quotes with its
/// quotes doubled (a comma, a quote, a line break, a leading '#' or blanks at either end).
std::string csv_field(std::string_view field);

}  // namespace wheelwear::core
