#include "text_parse.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "sextant/core/error.hpp"

namespace sextant::detail {
namespace {

bool is_separator(char c) {
  return c == ' ' || c == '\t' || c == ',' || c == '\r' || c == '\f' || c == '\v';
}

}  // namespace

void require_regular_file(const std::filesystem::path& file) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(file, ec);
  if (ec && status.type() != std::filesystem::file_type::not_found)  // e.g. a symlink loop
    throw FileError(file.string(), "cannot open: " + ec.message(), ec.value());
  if (std::filesystem::is_directory(status))
    throw InputError(file.string(), "", "is a folder, expected a file");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw InputError(file.string(), "",
                     "not a regular file (a device, pipe or socket, which may never end): copy the data "
                     "into a file first");
}

std::string read_file_bytes(const std::filesystem::path& file) {
  require_regular_file(file);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError::from_errno(file.string(), "cannot open", errno);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool is_blank(std::string_view line) {
  for (char c : line) {
    if (!is_separator(c) && c != '\n') return false;
  }
  return true;
}

bool parse_numbers(std::string_view line, std::vector<double>& out, std::string* bad_token) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_separator(line[i])) ++i;
    if (i >= line.size()) break;
    std::size_t end = i;
    while (end < line.size() && !is_separator(line[end])) ++end;
    const char* first = line.data() + i;
    const char* last = line.data() + end;
    if (*first == '+') ++first;  // from_chars rejects a leading '+'
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(first, last, value);
    // Out of range: too large (1e999) is reported as non-finite rather than as malformed; too small
    // (1e-400) is the nearest double, 0 or subnormal, as strtod gives it (it is a finite number).
    if (ec == std::errc::result_out_of_range && ptr == last) {
      value = std::strtod(std::string(first, last).c_str(), nullptr);
    } else if (ec != std::errc() || ptr != last || first == last) {
      if (bad_token) *bad_token = std::string(line.substr(i, end - i));
      return false;
    }
    out.push_back(value);
    i = end;
  }
  return true;
}

bool fits_float(double v) {
  return std::isfinite(v) && std::abs(v) <= static_cast<double>(std::numeric_limits<float>::max());
}

std::string bad_number_problem(const std::string& token) {
  return "cannot read '" + token + "' as a number";
}

void append_number(std::string& out, double value) {
  char buffer[32];
  const int n = std::snprintf(buffer, sizeof buffer, "%.9g", value);
  out.append(buffer, static_cast<std::size_t>(n));
}

}  // namespace sextant::detail
