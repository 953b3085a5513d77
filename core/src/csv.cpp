#include "wheelwear/core/csv.hpp"

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"

namespace wheelwear::core {

namespace {

// Reads `text` one field at a time; `at` is the next character, `line` its line.
class CsvScanner {
 public:
  CsvScanner(std::string_view text, std::string_view source) : text_(text), source_(source) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;  // a UTF-8 byte-order mark
  }

  // Skips blank and comment lines; false at the end of the text.
  bool next_record() {
    while (at_ < text_.size()) {
      std::size_t end = text_.find('\n', at_);
      if (end == std::string_view::npos) end = text_.size();
      const std::string_view row = trim(text_.substr(at_, end - at_));
      if (!row.empty() && row.front() != '#') return true;
      at_ = end + 1;
      ++line_;
    }
    return false;
  }

  CsvRecord record() {
    CsvRecord r;
    r.line = line_;
    while (true) {
      r.fields.push_back(field());
      if (at_ < text_.size() && text_[at_] == ',') {
        ++at_;
        continue;
      }
      // The end of the line (or of the text).
      if (at_ < text_.size()) {
        ++at_;
        ++line_;
      }
      return r;
    }
  }

 private:
  std::string field() {
    std::size_t start = at_;
    while (start < text_.size() && (text_[start] == ' ' || text_[start] == '\t')) ++start;
    if (start < text_.size() && text_[start] == '"') return quoted(start);
    std::size_t end = start;
    while (end < text_.size() && text_[end] != ',' && text_[end] != '\n') ++end;
    at_ = end;
    return std::string(trim(text_.substr(start, end - start)));
  }

  std::string quoted(std::size_t open) {
    const int opened = line_;
    std::string value;
    std::size_t i = open + 1;
    while (true) {
      if (i >= text_.size())
        throw InputError(std::string(source_) + " line " + std::to_string(opened) +
                         ": a quoted field is never closed; end it with a double quote");
      const char c = text_[i];
      if (c == '"' && i + 1 < text_.size() && text_[i + 1] == '"') {
        value += '"';
        i += 2;
        continue;
      }
      if (c == '"') break;
      if (c == '\n') ++line_;
      if (c != '\r' || (i + 1 < text_.size() && text_[i + 1] != '\n')) value += c;
      ++i;
    }
    ++i;  // the closing quote
    while (i < text_.size() && (text_[i] == ' ' || text_[i] == '\t' || text_[i] == '\r')) ++i;
    if (i < text_.size() && text_[i] != ',' && text_[i] != '\n')
      throw InputError(std::string(source_) + " line " + std::to_string(line_) +
                       ": text after a quoted field's closing quote; put the whole field in "
                       "quotes and double the quotes inside it");
    at_ = i;
    return value;
  }

  std::string_view text_;
  std::string_view source_;
  std::size_t at_ = 0;
  int line_ = 1;
};

}  // namespace

std::vector<CsvRecord> read_csv(std::string_view text, std::string_view source) {
  CsvScanner scanner(text, source);
  std::vector<CsvRecord> records;
  while (scanner.next_record()) records.push_back(scanner.record());
  return records;
}

std::string csv_field(std::string_view field) {
  const bool plain = field.find_first_of(",\"\r\n") == std::string_view::npos &&
                     trim(field).size() == field.size() && (field.empty() || field.front() != '#');
  if (plain) return std::string(field);
  std::string out = "\"";
  for (const char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + '"';
}

}  // namespace wheelwear::core
