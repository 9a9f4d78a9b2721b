// run_view's page: the HTML (title, caption, legend with toggles, the colour and camera controls,
// the step panel and the list of marked steps; every text escaped), three.js and its line scripts
// inlined, the run as JSON (run_view_data.cpp) and the viewer (run_view_script.cpp).
#include "sextant/eval/run_view.hpp"

#include <sstream>

#include "page_encoding.hpp"
#include "run_view_data.hpp"
#include "run_view_script.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/eval/table.hpp"

namespace sextant {
namespace {

/// The fat-line scripts of libjs-three (examples/js/lines), in the order they depend on each other.
const char* const kLineScripts[] = {"LineSegmentsGeometry.js", "LineGeometry.js", "LineMaterial.js",
                                    "LineSegments2.js", "Line2.js"};

std::filesystem::path line_script(const std::filesystem::path& dir, const char* name) {
  return dir / "examples" / "js" / "lines" / name;
}

}  // namespace

void check_run_view_scripts(const std::filesystem::path& three_js_dir) {
  find_three_js(three_js_dir);
  for (const char* name : kLineScripts) {
    const std::filesystem::path path = line_script(three_js_dir, name);
    if (!std::filesystem::is_regular_file(path))
      throw InputError(path.string(), "",
                       "three.js's line script not found: the run view needs the Debian package libjs-three "
                       "(apt-get install libjs-three), which installs it there");
  }
}

void check_run_view_path(const std::filesystem::path& path) {
  check_run_view_scripts();
  const std::filesystem::path file = std::filesystem::absolute(path);
  if (file.filename().empty() || std::filesystem::is_directory(file))
    throw InputError("--view", "", "'" + path.string() + "' is a folder; expected a file such as run.html");
  if (!std::filesystem::is_directory(file.parent_path()))
    throw InputError("--view", "", "the folder of '" + path.string() + "' does not exist");
}

std::string render_run_view(const RunView& view, const std::filesystem::path& three_js_dir) {
  const detail::RunPage data = detail::run_page(view);
  check_run_view_scripts(three_js_dir);
  const std::vector<Eigen::Vector3f>& map = data.map;
  const std::size_t poses = data.estimate.size(), line = data.line.size();
  const bool assessed = data.assessed();
  const auto& verdicts = data.verdicts;
  std::ostringstream page;
  const auto count = [](std::size_t n, const std::string& what) {  // "1 step", "2 steps"
    return "<span class=\"sx-count\">" + detail::grouped(n) + " " + escape_html(what) + (n == 1 ? "" : "s") +
           "</span>";
  };
  page << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
       << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n<title>"
       << escape_html(view.title) << "</title>\n<style>\n"
       << detail::run_view_style() << "</style>\n</head>\n<body>\n<canvas id=\"sx-canvas\"></canvas>\n"
       << "<div id=\"sx-panel\" class=\"sx-box\">\n<h1>" << escape_html(view.title) << "</h1>\n";
  if (!view.caption.empty()) page << "<p class=\"sx-caption\">" << escape_html(view.caption) << "</p>\n";
  page << "<ul class=\"sx-legend\">\n";
  if (!map.empty())
    page << "<li><label><input type=\"checkbox\" data-layer=\"map\" checked=\"checked\"/><span "
            "class=\"sx-swatch "
            "sx-height\">"
         << "</span>map "
         << "<span class=\"sx-count\">"
         << (map.size() < data.finite_map_points
                 ? detail::grouped(map.size()) + " of " + detail::grouped(data.finite_map_points)
                 : detail::grouped(map.size()))
         << " points, shaded by height</span></label></li>\n";
  page << "<li><label><input type=\"checkbox\" data-layer=\"estimate\" checked=\"checked\"/><span "
          "class=\"sx-swatch "
          "sx-line sx-estimate\"></span>"
       << escape_html(view.estimate_name) << " " << count(poses, "pose") << "</label></li>\n";
  if (data.has_reference)
    page << "<li><label><input type=\"checkbox\" data-layer=\"reference\" checked=\"checked\"/><span "
            "class=\"sx-swatch "
            "sx-line sx-reference\"></span>"
         << escape_html(view.reference_name) << "</label></li>\n";
  const std::pair<StepVerdict, const char*> markers[] = {{StepVerdict::untrusted, "untrusted"},
                                                         {StepVerdict::not_converged, "not converged"},
                                                         {StepVerdict::recovered, "recovered"}};
  for (const auto& [verdict, label] : markers) {
    if (!assessed) break;  // no trust is known: no markers to speak of
    const auto v = static_cast<int>(verdict);
    page << "<li" << (verdicts[static_cast<std::size_t>(v)] ? "" : " class=\"sx-absent\"")
         << "><label><input type=\"checkbox\" data-layer=\"marker" << v
         << "\" checked=\"checked\"/><span class=\"sx-dot sx-v" << v << "\"></span>" << label << " "
         << count(verdicts[static_cast<std::size_t>(v)], view.step_name) << "</label></li>\n";
  }
  page << "</ul>\n";
  if (data.error_scale > 0.0)
    page << "<div class=\"sx-colour\"><label><input type=\"checkbox\" id=\"sx-by-error\""
         << (view.colour_by_error ? " checked=\"checked\"" : "") << "/> colour the "
         << escape_html(view.estimate_name) << " by its error</label><div class=\"sx-caption\">"
         << escape_html(view.error_name)
         << "</div><div class=\"sx-bar\"><span>0 m</span><span id=\"sx-scale-mid\"></span><span "
            "id=\"sx-scale\"></span></div></div>\n";
  page << "<div class=\"sx-tools\"><button type=\"button\" id=\"sx-3d\" title=\"key 3\">3D</button>"
       << "<button type=\"button\" id=\"sx-top\" title=\"key T\">top view</button>"
       << "<button type=\"button\" id=\"sx-reset\" title=\"key R\">reset</button>"
       << "<label" << (map.empty() ? " hidden=\"hidden\"" : "")
       << ">points <input type=\"range\" id=\"sx-size\" min=\"1\" max=\"6\" step=\"0.5\" value=\""
       << (map.size() <= 20000 ? "2.5" : "1.5") << "\"/></label></div>\n"
       << "<p class=\"sx-help\">Click a " << escape_html(view.step_name)
       << " on the line or in the list · drag: rotate (top view: pan) · right- or shift-drag: pan · wheel: "
          "zoom · N / P: next / previous in the list. "
       << (map.empty()
               ? "The line "
               : "The map keeps at most " + detail::grouped(view.max_map_points) + " points; the line ")
       << detail::grouped(line) << " of " << detail::grouped(poses) << " vertices"
       << (assessed ? ", every marked " + escape_html(view.step_name) + " among them" : std::string())
       << ".</p>\n"
       << "<p id=\"sx-status\" class=\"sx-status\">Loading…</p>\n"
       << "<noscript><p class=\"sx-error\">The 3D view needs JavaScript.</p></noscript>\n</div>\n"
       << "<div id=\"sx-side\" class=\"sx-box\">\n<div id=\"sx-step\"><p class=\"sx-hint\">Click a "
       << escape_html(view.step_name) << " on the line, or an entry below.</p></div>\n"
       << "<div class=\"sx-nav\"><button type=\"button\" id=\"sx-prev\">◀ previous</button><button "
          "type=\"button\" "
          "id=\"sx-next\">next ▶</button><label>"
       << escape_html(view.step_name) << " <input type=\"number\" id=\"sx-goto\" min=\"0\"/></label></div>\n"
       << "<div class=\"sx-nav\"><select id=\"sx-list-kind\"></select></div>\n"
       << "<div id=\"sx-list\"></div>\n</div>\n<script>\n"
       << detail::read_inline_script(find_three_js(three_js_dir)) << "\n</script>\n";
  for (const char* name : kLineScripts)
    page << "<script>\n" << detail::read_inline_script(line_script(three_js_dir, name)) << "\n</script>\n";
  page << "<script type=\"application/json\" id=\"sx-data\">" << detail::run_page_json(view, data)
       << "</script>\n<script>\n"
       << detail::run_view_panel_script() << detail::run_view_script() << "</script>\n</body>\n</html>\n";
  return page.str();
}

void write_run_view(const RunView& view, const std::filesystem::path& path,
                    const std::filesystem::path& three_js_dir) {
  write_file_atomically(path, render_run_view(view, three_js_dir));
}

}  // namespace sextant
