#pragma once
// Experiment YAML for the experiments tests (temporary folders: sextant_test/temp_dir.hpp).
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sextant_test/temp_dir.hpp"

namespace sextant::test {

/// A selftest experiment with `points` sweep values × 2 methods × `reps` repetitions.
inline std::string selftest_yaml(const std::string& name, int points, int reps, int sleep_ms) {
  return "name: " + name + "\nkind: selftest\nrepetitions: " + std::to_string(reps) +
         "\nseed: 7\nmethods:\n  - name: a\n  - name: b\nsweep:\n  x: {from: 1, to: " +
         std::to_string(points) + "}\nparams:\n  sleep_ms: " + std::to_string(sleep_ms) + "\n";
}

/// The HTML of the report section `<section id="id">` … `</section>` ("" when absent).
inline std::string report_section(const std::string& index_html, const std::string& id) {
  const std::size_t at = index_html.find("<section id=\"" + id + "\">");
  if (at == std::string::npos) return "";
  return index_html.substr(at, index_html.find("</section>", at) - at);
}

/// The targets of the 3D-view links (<p class="sx-view"><a href="…">) in a piece of the report.
inline std::vector<std::string> view_links(const std::string& html) {
  std::vector<std::string> out;
  const std::string open = "<p class=\"sx-view\"><a href=\"";
  for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, at + 1)) {
    const std::size_t from = at + open.size();
    out.push_back(html.substr(from, html.find('"', from) - from));
  }
  return out;
}

}  // namespace sextant::test
