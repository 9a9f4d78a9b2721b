// The offline pages' encodings (page_encoding.hpp).
#include "page_encoding.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "sextant/core/error.hpp"

namespace sextant::detail {

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* const kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = static_cast<std::uint32_t>(bytes[i]) << 16;
    if (n > 1) v |= static_cast<std::uint32_t>(bytes[i + 1]) << 8;
    if (n > 2) v |= bytes[i + 2];
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += n > 1 ? kDigits[(v >> 6) & 63] : '=';
    out += n > 2 ? kDigits[v & 63] : '=';
  }
  return out;
}

std::vector<unsigned char> float32_bytes(const std::vector<Eigen::Vector3f>& points) {
  std::vector<unsigned char> bytes;
  bytes.reserve(points.size() * 12);
  for (const Eigen::Vector3f& p : points)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t u = 0;
      std::memcpy(&u, &p[k], 4);
      for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<unsigned char>((u >> (8 * b)) & 0xFF));
    }
  return bytes;
}

std::string script_json_string(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == '<' || c == '>' || c == '&') {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

std::string lower_ascii(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string grouped(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += "\u2009";
    out += digits[i];
  }
  return out;
}

std::string read_inline_script(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot open the script");
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) throw InputError(path.string(), "", "cannot read the script");
  std::string js = text.str();
  if (lower_ascii(js).find("</script") != std::string::npos)
    throw InputError(path.string(), "", "contains '</script' and cannot be inlined into a page");
  return js;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> central_box(std::array<std::vector<double>, 3>& axes) {
  Eigen::Vector3d lo, hi;
  for (int a = 0; a < 3; ++a) {
    std::vector<double>& v = axes[a];
    const auto at = [&v](double q) {
      const auto n = static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
      std::nth_element(v.begin(), v.begin() + n, v.end());
      return v[static_cast<std::size_t>(n)];
    };
    lo[a] = at(0.02);
    hi[a] = at(0.98);
  }
  return {lo, hi};
}

}  // namespace sextant::detail
