#pragma once
// Private helpers of the readers: whole-file reading, line iteration with 1-based numbers, and
// locale-independent number parsing (std::from_chars) that reports the offending token.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace sextant::detail {

/// The whole file as bytes; InputError when it cannot be opened.
/// InputError unless `file` is a regular file (after symlinks): a folder, a device such as
/// /dev/zero (which never ends), a pipe or a symlink loop is named as such.
void require_regular_file(const std::filesystem::path& file);

std::string read_file_bytes(const std::filesystem::path& file);

/// Calls f(line, line_number) for every line (without '\n' or '\r'); line numbers start at 1.
template <class F>
void for_each_line(std::string_view text, F&& f) {
  long number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    f(line, ++number);
    start = end + 1;
  }
}

/// True when the line holds only whitespace (or nothing).
bool is_blank(std::string_view line);

/// Parses the whitespace- or comma-separated numbers of `line` into `out` (cleared first).
/// Returns false and sets `bad_token` at the first token that is not a number. "nan" and
/// "inf" parse (the callers drop and count such points).
bool parse_numbers(std::string_view line, std::vector<double>& out, std::string* bad_token);

/// True when `v` is finite and inside float's range (so the cast to float is exact up to
/// rounding); NaN, ±Inf and out-of-range values (1e308) are dropped and counted alike.
bool fits_float(double v);

/// "cannot read 'abc' as a number" style message.
std::string bad_number_problem(const std::string& token);

/// Formats a double with up to 9 significant digits (enough for float round trips).
void append_number(std::string& out, double value);

}  // namespace sextant::detail
