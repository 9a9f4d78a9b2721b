#pragma once
// For the tests of run views (eval/run_view.hpp): the page's JSON block parsed, its base64 float32
// coordinates decoded, the page's own markup (scripts and styles emptied) for a well-formedness check,
// and the page opened in headless Chromium (its DOM after the scripts ran).
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace sextant::test {

inline std::string page_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The page's <script type="application/json" id="sx-data"> block, parsed (null when there is none).
inline nlohmann::json page_data(const std::string& page) {
  const std::string open = "<script type=\"application/json\" id=\"sx-data\">";
  const std::size_t a = page.find(open);
  if (a == std::string::npos) return nullptr;
  const std::size_t b = page.find("</script>", a);
  return nlohmann::json::parse(page.substr(a + open.size(), b - a - open.size()));
}

/// Little-endian float32 x, y, z triples from base64.
inline std::vector<Eigen::Vector3f> page_points(const std::string& text) {
  std::vector<unsigned char> bytes;
  std::uint32_t buffer = 0;
  int bits = 0;
  for (const char c : text) {
    int v = -1;
    if (c >= 'A' && c <= 'Z') v = c - 'A';
    if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
    if (c >= '0' && c <= '9') v = c - '0' + 52;
    if (c == '+') v = 62;
    if (c == '/') v = 63;
    if (v < 0) continue;  // '=' padding
    buffer = (buffer << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes.push_back(static_cast<unsigned char>((buffer >> bits) & 0xFF));
    }
  }
  std::vector<Eigen::Vector3f> out;
  for (std::size_t k = 0; k + 12 <= bytes.size(); k += 12) {
    Eigen::Vector3f p;
    for (int j = 0; j < 3; ++j) {
      std::uint32_t u = 0;
      for (int b = 0; b < 4; ++b) u |= static_cast<std::uint32_t>(bytes[k + 4 * j + b]) << (8 * b);
      std::memcpy(&p[j], &u, 4);
    }
    out.push_back(p);
  }
  return out;
}

/// The page without its doctype and with every <script> and <style> element emptied: the markup the
/// page writes itself, which must be well-formed XML.
inline std::string page_markup(std::string page) {
  if (page.rfind("<!DOCTYPE html>", 0) == 0) page.erase(0, 15);
  for (const std::string tag : {"script", "style"}) {
    for (std::size_t at = page.find("<" + tag); at != std::string::npos; at = page.find("<" + tag, at + 1)) {
      const std::size_t body = page.find('>', at) + 1;
      const std::size_t end = page.find("</" + tag + ">", body);
      page.erase(body, end - body);
    }
  }
  return page;
}

inline bool chromium_installed() {
  return std::system("command -v chromium >/dev/null 2>&1") == 0;
}

/// Opens file://`page``fragment` in headless Chromium (SwiftShader WebGL, a fresh profile in `work`,
/// no network) and returns its DOM after the scripts ran; empty when Chromium failed or took longer
/// than `timeout_s` (a page that freezes).
inline std::string chromium_dom(const std::filesystem::path& page, const std::string& fragment,
                                const std::filesystem::path& work, int timeout_s = 180) {
  std::filesystem::create_directories(work);
  const std::filesystem::path dom = work / "dom.html";
  const std::string command =
      "timeout " + std::to_string(timeout_s) +
      " chromium --headless --no-sandbox --disable-gpu --use-gl=swiftshader --enable-unsafe-swiftshader "
      "--no-first-run --disable-background-networking --disable-component-update --disable-sync "
      "--window-size=1400,900 --user-data-dir='" +
      (work / "profile").string() + "' --virtual-time-budget=20000 --dump-dom 'file://" + page.string() +
      fragment + "' > '" + dom.string() + "' 2>/dev/null";
  if (std::system(command.c_str()) != 0) return "";
  return page_text(dom);
}

/// The value of attribute `name` of the first element that has one in `dom` (empty when none has).
inline std::string dom_attribute(const std::string& dom, const std::string& name) {
  const std::size_t a = dom.find(" " + name + "=\"");
  if (a == std::string::npos) return "";
  const std::size_t start = a + name.size() + 3;
  return dom.substr(start, dom.find('"', start) - start);
}

}  // namespace sextant::test
