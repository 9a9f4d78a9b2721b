// cloud_view's page: the HTML (title, caption, state buttons, legend with toggles; every text
// escaped), three.js inlined or referenced, the clouds as JSON (float32 coordinates in base64,
// one 4×4 column-major pose or null per state) and the viewer script (cloud_view_script.cpp).
#include "sextant/eval/cloud_view.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <locale>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "cloud_view_script.hpp"
#include "page_encoding.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/eval/table.hpp"

namespace sextant {
namespace {

/// Bright colours that stay apart on the dark background; further clouds get golden-angle hues.
const char* const kPalette[] = {"#3d8bff", "#ff5a36", "#5fd35f", "#ffd23e",
                                "#b07cff", "#2ee6e6", "#ff4fa3", "#e8e8e8"};

std::string hue_colour(std::size_t k) {
  const double h = std::fmod(0.13 + 0.618033988749895 * static_cast<double>(k), 1.0) * 6.0;
  const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
  double rgb[3] = {0, 0, 0};
  const int sector = static_cast<int>(h);
  const int hi[6] = {0, 1, 1, 2, 2, 0}, mid[6] = {1, 0, 2, 1, 0, 2};
  rgb[hi[sector]] = 1.0;
  rgb[mid[sector]] = x;
  char out[8];
  std::snprintf(out, sizeof out, "#%02x%02x%02x", static_cast<int>(100 + 155 * rgb[0]),
                static_cast<int>(100 + 155 * rgb[1]), static_cast<int>(100 + 155 * rgb[2]));
  return out;
}

bool is_colour(const std::string& c) {
  return c.size() == 7 && c[0] == '#' && std::all_of(c.begin() + 1, c.end(), [](char ch) {
           return std::isxdigit(static_cast<unsigned char>(ch));
         });
}

/// Explicit colours as given (lower case); the others from the palette, skipping colours in use.
std::vector<std::string> cloud_colours(const CloudView& view) {
  std::vector<std::string> out(view.clouds.size());
  std::vector<std::string> used;
  for (std::size_t i = 0; i < view.clouds.size(); ++i) {
    const std::string& c = view.clouds[i].color;
    if (c.empty()) continue;
    if (!is_colour(c))
      throw std::invalid_argument("cloud view: colour '" + c + "' of cloud '" + view.clouds[i].name +
                                  "' is not #rrggbb");
    out[i] = detail::lower_ascii(c);
    used.push_back(out[i]);
  }
  std::size_t next = 0;
  for (std::string& c : out) {
    if (!c.empty()) continue;
    for (;; ++next) {
      const std::string candidate = next < std::size(kPalette) ? kPalette[next] : hue_colour(next);
      if (std::find(used.begin(), used.end(), candidate) == used.end()) {
        c = candidate;
        used.push_back(c);
        break;
      }
    }
  }
  return out;
}

std::string pose_json(const std::optional<Eigen::Isometry3d>& T) {
  if (!T) return "null";
  const Eigen::Matrix4d m = T->matrix();
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(17);
  out << '[';
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out << (c || r ? "," : "") << m(r, c);
  out << ']';
  return out.str();
}

std::string read_three_js(const std::filesystem::path& dir) {
  return detail::read_inline_script(find_three_js(dir));
}

/// The finite points of a cloud, subsampled to `cap`.
std::vector<Eigen::Vector3f> kept_points(const PointCloud& cloud, std::size_t cap) {
  std::vector<Eigen::Vector3f> finite;
  finite.reserve(cloud.size());
  for (const Eigen::Vector3f& p : cloud.points())
    if (p.allFinite()) finite.push_back(p);
  std::vector<Eigen::Vector3f> out;
  for (const std::size_t i : view_subsample(finite.size(), cap)) out.push_back(finite[i]);
  return out;
}

/// The camera's framing: the centre and half diagonal of the box between the 2 % and 98 % quantiles
/// of every axis, over the kept points of every cloud in every state (a few far returns do not
/// shrink the scene to a dot); at most about 20 000 points are looked at.
std::pair<Eigen::Vector3d, double> framing(
    const std::vector<std::vector<Eigen::Vector3f>>& kept,
    const std::vector<std::vector<std::optional<Eigen::Isometry3d>>>& poses) {
  std::size_t total = 0;
  for (std::size_t i = 0; i < kept.size(); ++i) total += kept[i].size() * poses[i].size();
  const std::size_t stride = std::max<std::size_t>(1, total / 20000);
  std::array<std::vector<double>, 3> axes;
  for (std::size_t i = 0; i < kept.size(); ++i)
    for (const auto& pose : poses[i]) {
      if (!pose) continue;
      for (std::size_t k = 0; k < kept[i].size(); k += stride) {
        const Eigen::Vector3d p = *pose * kept[i][k].cast<double>();
        for (int a = 0; a < 3; ++a) axes[a].push_back(p[a]);
      }
    }
  if (axes[0].empty()) return {Eigen::Vector3d::Zero(), 1.0};
  const auto [lo, hi] = detail::central_box(axes);
  return {0.5 * (lo + hi), std::max(0.5 * (hi - lo).norm(), 1e-3)};
}

std::size_t finite_count(const PointCloud& cloud) {
  return static_cast<std::size_t>(std::count_if(cloud.points().begin(), cloud.points().end(),
                                                [](const Eigen::Vector3f& p) { return p.allFinite(); }));
}

}  // namespace

std::vector<std::size_t> view_subsample(std::size_t n, std::size_t cap) {
  const std::size_t m = std::min(n, cap);
  std::vector<std::size_t> out(m);
  for (std::size_t i = 0; i < m; ++i)
    out[i] = n <= cap ? i : static_cast<std::size_t>((static_cast<unsigned long long>(i) * n) / cap);
  return out;
}

std::string render_cloud_view(const CloudView& view, const CloudViewOptions& options) {
  const std::size_t states = std::max<std::size_t>(1, view.states.size());
  for (const ViewCloud& c : view.clouds) {
    if (!c.poses.empty() && c.poses.size() != states)
      throw std::invalid_argument("cloud view: cloud '" + c.name + "' has " + std::to_string(c.poses.size()) +
                                  " poses for " + std::to_string(states) + " states");
    if (!c.in_states.empty() && c.in_states.size() != states)
      throw std::invalid_argument("cloud view: cloud '" + c.name + "' has " +
                                  std::to_string(c.in_states.size()) + " state flags for " +
                                  std::to_string(states) + " states");
  }
  const std::string src = options.three_js_src;
  if (detail::lower_ascii(src).find("http:") != std::string::npos ||
      detail::lower_ascii(src).find("https:") != std::string::npos || src.rfind("//", 0) == 0)
    throw std::invalid_argument("cloud view: three.js must come from a local file, not '" + src + "'");
  if (view.max_points == 0) throw std::invalid_argument("cloud view: max_points must be at least 1");
  const std::vector<std::string> colours = cloud_colours(view);

  std::ostringstream page;
  page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>"
       << escape_html(view.title) << "</title>\n<style>\n"
       << detail::cloud_view_style() << "</style>\n</head>\n<body>\n<canvas id=\"sx-canvas\"></canvas>\n"
       << "<div id=\"sx-panel\">\n<h1>" << escape_html(view.title) << "</h1>\n";
  if (!view.caption.empty()) page << "<p class=\"sx-caption\">" << escape_html(view.caption) << "</p>\n";
  if (view.states.size() > 1) {
    page << "<div class=\"sx-states\" role=\"group\" aria-label=\"state\">";
    for (std::size_t s = 0; s < view.states.size(); ++s)
      page << "<button type=\"button\" data-state=\"" << s << "\" title=\"key " << s + 1 << "\">"
           << escape_html(view.states[s]) << "</button>";
    page << "</div>\n";
  }
  // Per cloud: the points kept, and its pose in each state (none where it is left out or not finite).
  std::vector<std::vector<Eigen::Vector3f>> kept_of;
  std::vector<std::vector<std::optional<Eigen::Isometry3d>>> poses_of;
  for (const ViewCloud& c : view.clouds) {
    kept_of.push_back(kept_points(c.points, view.max_points));
    auto& poses = poses_of.emplace_back();
    for (std::size_t s = 0; s < states; ++s) {
      const Eigen::Isometry3d T = c.poses.empty() ? Eigen::Isometry3d::Identity() : c.poses[s];
      const bool in = (c.in_states.empty() || c.in_states[s]) && T.matrix().allFinite();
      poses.push_back(in ? std::optional<Eigen::Isometry3d>(T) : std::nullopt);
    }
  }
  const auto [centre, radius] = framing(kept_of, poses_of);
  std::ostringstream json;
  json.imbue(std::locale::classic());
  json.precision(9);
  json << "{\"three\":" << detail::script_json_string(src.empty() ? "inlined" : src)
       << ",\"states\":" << states << ",\"centre\":[" << centre.x() << "," << centre.y() << "," << centre.z()
       << "],\"radius\":" << radius << ",\"clouds\":[";
  page << "<ul class=\"sx-legend\">\n";
  for (std::size_t i = 0; i < view.clouds.size(); ++i) {
    const ViewCloud& c = view.clouds[i];
    const std::vector<Eigen::Vector3f>& kept = kept_of[i];
    const std::size_t finite = finite_count(c.points);
    page << "<li><label><input type=\"checkbox\" data-cloud=\"" << i << "\" checked>"
         << "<span class=\"sx-swatch\" style=\"background:" << colours[i] << "\"></span>"
         << escape_html(c.name) << " <span class=\"sx-count\">"
         << (kept.size() < finite ? detail::grouped(kept.size()) + " of " + detail::grouped(finite)
                                  : detail::grouped(kept.size()))
         << " points</span></label></li>\n";
    json << (i ? "," : "") << "\n{\"color\":\"" << colours[i] << "\",\"count\":" << kept.size()
         << ",\"poses\":[";
    for (std::size_t s = 0; s < states; ++s) json << (s ? "," : "") << pose_json(poses_of[i][s]);
    json << "],\"points\":\"" << detail::base64(detail::float32_bytes(kept)) << "\"}";
  }
  json << "]}";
  // Sparse scenes get larger points by default (the slider changes it).
  std::size_t total = 0;
  for (const auto& kept : kept_of) total += kept.size();
  const char* size = total <= 10000 ? "4" : total <= 150000 ? "2.5" : "2";
  page << "</ul>\n<div class=\"sx-tools\"><label>point size <input type=\"range\" id=\"sx-size\" min=\"1\" "
          "max=\"8\" step=\"0.5\" value=\""
       << size
       << "\"></label><button type=\"button\" id=\"sx-reset\">reset "
          "view</button></div>\n"
       << "<p class=\"sx-help\">Drag: rotate · right-drag or shift-drag: pan · wheel: zoom · double-click or "
          "R: reset"
       << (view.states.size() > 1
               ? " · keys 1–" + std::to_string(std::min<std::size_t>(9, states)) + ": state"
               : std::string())
       << ". At most " << detail::grouped(view.max_points) << " points per cloud (evenly strided).</p>\n"
       << "<p id=\"sx-status\" class=\"sx-status\">Loading…</p>\n"
       << "<noscript><p class=\"sx-error\">The 3D view needs JavaScript.</p></noscript>\n</div>\n";
  if (src.empty())
    page << "<script>\n" << read_three_js(options.three_js_dir) << "\n</script>\n";
  else
    page << "<script src=\"" << escape_html(src) << "\"></script>\n";
  page << "<script type=\"application/json\" id=\"sx-data\">" << json.str() << "</script>\n<script>\n"
       << detail::cloud_view_script() << "</script>\n</body>\n</html>\n";
  return page.str();
}

void write_cloud_view(const CloudView& view, const std::filesystem::path& path,
                      const CloudViewOptions& options) {
  write_file_atomically(path, render_cloud_view(view, options));
}

}  // namespace sextant
