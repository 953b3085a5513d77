#include "wheelwear/core/text.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "wheelwear/core/input_error.hpp"

namespace wheelwear::core {

std::string read_file_bytes(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw InputError(path.string() + ": no such file");
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(path.string() + ": not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open the file for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path.string() + ": read error");
  return buffer.str();
}

std::string read_text_file(const std::filesystem::path& path) {
  std::string text = read_file_bytes(path);
  if (text.empty()) throw InputError(path.string() + ": the file is empty");
  check_text(text, path.string());
  return text;
}

void check_text(std::string_view text, std::string_view source) {
  const std::size_t window = std::min<std::size_t>(text.size(), 4096);
  std::size_t control = 0, first = window;
  for (std::size_t i = 0; i < window; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const bool bad =
        c == 0 || ((c < 0x20 || c == 0x7f) && c != '\t' && c != '\n' && c != '\r' && c != '\f');
    if (!bad) continue;
    ++control;
    first = std::min(first, i);
    if (c == 0) break;
  }
  const auto nul = text.find('\0');
  if (nul != std::string_view::npos || 20 * control > window) {
    const std::size_t at = nul != std::string_view::npos ? std::min(nul, first) : first;
    throw InputError(std::string(source) + ": binary data at byte " + std::to_string(at + 1) +
                     ": not a text profile file");
  }
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

std::string_view trim(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return text;
}

std::string to_lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::optional<double> parse_number(std::string_view token) {
  if (token.empty()) return std::nullopt;
  bool negative = false;
  if (token.front() == '+' || token.front() == '-') {
    negative = token.front() == '-';
    token.remove_prefix(1);
    if (token.empty() || token.front() == '+' || token.front() == '-') return std::nullopt;
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) {
    // from_chars reports out-of-range values instead of returning +-inf or 0 like strtod.
    if (error == std::errc::result_out_of_range && end == token.data() + token.size()) {
      const std::string copy(token);
      value = std::strtod(copy.c_str(), nullptr);
    } else {
      return std::nullopt;
    }
  }
  return negative ? -value : value;
}

std::string format_mm(double metres, int decimals) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(decimals);
  out << metres * 1e3 << " mm";
  return out.str();
}

std::string format_number(double value) {
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string("nan");
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored))
    throw InputError(path.string() + ": is a folder; give a file name");
  const std::filesystem::path folder =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  // O_EXCL with a random name instead of mkstemp: the file gets the usual permissions (0666
  // minus the umask) rather than mkstemp's 0600, without touching the process umask.
  std::random_device random;
  std::string pattern;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    // Appended piece by piece: GCC 12 reports a false -Wrestrict for "." + std::string.
    std::string name(1, '.');
    name += path.filename().string();
    name += ".tmp.";
    name += std::to_string(::getpid());
    name += '.';
    name += std::to_string(random());
    pattern = (folder / name).string();
    fd = ::open(pattern.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) {
    const int error = errno;
    // A folder that is not there is the input's fault; one that refuses the file, the system's.
    if (error == ENOENT || error == ENOTDIR)
      throw InputError(path.string() + ": the folder " + folder.string() +
                       " does not exist; create it or choose another path");
    throw IoError(path.string() + ": cannot create a temporary file in " + folder.string() + ": " +
                  std::strerror(error));
  }
  std::size_t written = 0;
  bool ok = true;
  while (written < content.size()) {
    const ssize_t n = ::write(fd, content.data() + written, content.size() - written);
    if (n <= 0) {
      ok = false;
      break;
    }
    written += static_cast<std::size_t>(n);
  }
  ok = ::fsync(fd) == 0 && ok;
  ok = ::close(fd) == 0 && ok;
  std::error_code error;
  if (ok) std::filesystem::rename(pattern, path, error);
  if (!ok || error) {
    std::filesystem::remove(pattern, error);
    throw IoError(path.string() + ": cannot write the file (left unchanged)");
  }
}

double parse_inclination(std::string_view text, std::string_view field) {
  const auto refuse = [&] {
    return InputError(std::string(field) + " " + std::string(text) +
                      ": give 1:N (1:40) or a slope tan(theta) (0.025), or none");
  };
  if (text == "none") return 0.0;
  if (const std::size_t colon = text.find(':'); colon != std::string_view::npos) {
    const auto one = parse_number(text.substr(0, colon));
    const auto n = parse_number(text.substr(colon + 1));
    if (!one || *one != 1.0 || !n || !std::isfinite(*n) || *n < 5.0) throw refuse();
    return std::atan(1.0 / *n);
  }
  const auto slope = parse_number(text);
  // A bare 40 is 1:40 mistyped, not a slope of 40.
  if (!slope || !std::isfinite(*slope) || std::abs(*slope) > 0.2) throw refuse();
  return std::atan(*slope);
}

}  // namespace wheelwear::core
