// run_view's page: the HTML (title, caption, legend with toggles, the colour and camera controls,
// the step panel and the list of marked steps; every text escaped), three.js and its line scripts
// inlined, the run as JSON (coordinates relative to the scene's centre as float32 in base64, the
// steps as one array per field, their texts once each) and the viewer (run_view_script.cpp).
#include "sextant/eval/run_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <locale>
#include <map>
#include <sstream>
#include <stdexcept>

#include "page_encoding.hpp"
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

std::vector<Eigen::Vector3d> positions(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(poses.size());
  for (const Eigen::Isometry3d& T : poses) out.push_back(T.translation());
  return out;
}

/// The map's 2 % and 98 % quantiles on each axis (a few far returns left out); at most about 20 000
/// points are looked at.
std::pair<Eigen::Vector3d, Eigen::Vector3d> map_box(const std::vector<Eigen::Vector3f>& map) {
  Eigen::Vector3d lo, hi;
  const std::size_t stride = std::max<std::size_t>(1, map.size() / 20000);
  for (int a = 0; a < 3; ++a) {
    std::vector<double> v;
    for (std::size_t k = 0; k < map.size(); k += stride) v.push_back(map[k][a]);
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

/// The scene's centre and half diagonal: the run fills the view. The box of every finite trajectory
/// position, widened by a quarter of its diagonal (at least 10 m) but not beyond the map's box, so that
/// the map around the run shows and a long-range sensor's far walls do not shrink the run to a dot; the
/// map's box alone when there is no trajectory to speak of (under 1 m).
std::pair<Eigen::Vector3d, double> framing(const std::vector<Eigen::Vector3f>& map,
                                           const std::vector<Eigen::Vector3d>& trajectory) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const Eigen::Vector3d& p : trajectory)
    if (p.allFinite()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const bool run = lo.allFinite() && (hi - lo).norm() >= 1.0;
  if (!map.empty()) {
    const auto [map_lo, map_hi] = map_box(map);
    if (!run) {
      lo = map_lo, hi = map_hi;
    } else {
      const double pad = std::max(0.25 * (hi - lo).norm(), 10.0);
      lo = lo.cwiseMin((lo.array() - pad).max(map_lo.array()).matrix());
      hi = hi.cwiseMax((hi.array() + pad).min(map_hi.array()).matrix());
    }
  }
  if (!lo.allFinite()) return {Eigen::Vector3d::Zero(), 1.0};
  return {0.5 * (lo + hi), std::max(0.5 * (hi - lo).norm(), 1.0)};
}

/// Writes numbers as JSON (null for NaN and infinities), `digits` significant digits.
class JsonNumbers {
 public:
  explicit JsonNumbers(int digits) {
    out_.imbue(std::locale::classic());
    out_.precision(digits);
  }
  template <class Values, class Get>
  std::string array(const Values& values, Get get) {
    out_.str("");
    out_ << '[';
    bool first = true;
    for (const auto& v : values) {
      const double x = static_cast<double>(get(v));
      out_ << (first ? "" : ",");
      first = false;
      if (std::isfinite(x))
        out_ << x;
      else
        out_ << "null";
    }
    out_ << ']';
    return out_.str();
  }

 private:
  std::ostringstream out_;
};

/// Each step's text as an index into one list of the distinct texts.
class TextTable {
 public:
  std::string indices(const std::vector<RunViewStep>& steps, std::string RunViewStep::*field) {
    std::string out = "[";
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const std::string& text = steps[i].*field;
      const auto [it, added] = index_.emplace(text, texts_.size());
      if (added) texts_.push_back(text);
      out += (i ? "," : "") + std::to_string(it->second);
    }
    return out + "]";
  }
  std::string texts() const {
    std::string out = "[";
    for (std::size_t i = 0; i < texts_.size(); ++i)
      out += (i ? "," : "") + detail::script_json_string(texts_[i]);
    return out + "]";
  }

 private:
  std::map<std::string, std::size_t> index_;
  std::vector<std::string> texts_;
};

/// The float32 coordinates of `points` relative to `origin`, base64 (float32 keeps a millimetre
/// 16 km away from the origin; the scene's centre keeps it for the whole of a run).
template <class Point>
std::string encoded(const std::vector<Point>& points, const Eigen::Vector3d& origin) {
  std::vector<Eigen::Vector3f> relative;
  relative.reserve(points.size());
  for (const Point& p : points)
    relative.push_back((p.template cast<double>() - origin).template cast<float>());
  return detail::base64(detail::float32_bytes(relative));
}

/// The top of the error colour scale: the 95th percentile of the finite errors (a few wild steps do
/// not wash the others out), else the largest, at least 1 mm.
double error_scale(const std::vector<RunViewStep>& steps) {
  std::vector<double> errors;
  for (const RunViewStep& s : steps)
    if (std::isfinite(s.error_m)) errors.push_back(s.error_m);
  if (errors.empty()) return 0.0;
  const auto n = static_cast<std::ptrdiff_t>(0.95 * static_cast<double>(errors.size() - 1));
  std::nth_element(errors.begin(), errors.begin() + n, errors.end());
  return std::max(errors[static_cast<std::size_t>(n)], 1e-3);
}

void validate(const RunView& view) {
  if (!view.reference.empty() && view.reference.size() != view.estimate.size())
    throw std::invalid_argument("run view: " + std::to_string(view.reference.size()) +
                                " reference poses for " + std::to_string(view.estimate.size()) +
                                " estimated ones");
  for (const RunViewStep& s : view.steps)
    if (s.pose >= view.estimate.size())
      throw std::invalid_argument("run view: " + view.step_name + " " + std::to_string(s.number) +
                                  " is drawn at pose " + std::to_string(s.pose) + " of " +
                                  std::to_string(view.estimate.size()));
  if (view.max_map_points == 0) throw std::invalid_argument("run view: max_map_points must be at least 1");
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
  validate(view);
  check_run_view_scripts(three_js_dir);
  std::vector<Eigen::Vector3f> finite_map;
  for (const Eigen::Vector3f& p : view.map.points())
    if (p.allFinite()) finite_map.push_back(p);
  std::vector<Eigen::Vector3f> map;
  for (const std::size_t i : view_subsample(finite_map.size(), view.max_map_points))
    map.push_back(finite_map[i]);
  const std::vector<Eigen::Vector3d> estimate = positions(view.estimate),
                                     reference = positions(view.reference);
  std::vector<Eigen::Vector3d> trajectory = estimate;
  trajectory.insert(trajectory.end(), reference.begin(), reference.end());
  const auto [origin, radius] = framing(map, trajectory);

  // The estimate's line keeps every marked step and follows its error colour; the reference's its shape.
  const double scale = error_scale(view.steps);
  std::vector<double> pose_error(estimate.size(), std::nan(""));
  std::vector<bool> marked(estimate.size(), false);
  std::array<std::size_t, 5> verdicts{};
  for (const RunViewStep& s : view.steps) {
    const StepVerdict v = verdict_of(s);
    ++verdicts[static_cast<std::size_t>(v)];
    marked[s.pose] = marked[s.pose] || (v != StepVerdict::trusted && v != StepVerdict::unassessed);
    if (std::isfinite(s.error_m))
      pose_error[s.pose] = std::max(std::isnan(pose_error[s.pose]) ? 0.0 : pose_error[s.pose], s.error_m);
  }
  const double tolerance = 2e-4 * radius;
  const std::vector<std::size_t> line = decimate_polyline(
      estimate, scale > 0.0 ? pose_error : std::vector<double>{}, tolerance, 0.02 * scale, marked);
  std::vector<Eigen::Vector3d> reference_line;
  for (const std::size_t i : decimate_polyline(reference, {}, tolerance, 0.0, {}))
    reference_line.push_back(reference[i]);

  std::ostringstream json;
  json.imbue(std::locale::classic());
  json.precision(17);
  JsonNumbers numbers(17), short_numbers(6);
  const auto& steps = view.steps;
  json << "{\"origin\":[" << origin.x() << "," << origin.y() << "," << origin.z() << "],\"radius\":" << radius
       << ",\"map\":{\"count\":" << map.size() << ",\"points\":\"" << encoded(map, origin)
       << "\"},\n\"estimate\":{\"name\":" << detail::script_json_string(view.estimate_name)
       << ",\"count\":" << estimate.size() << ",\"points\":\"" << encoded(estimate, origin)
       << "\",\"line\":" << numbers.array(line, [](std::size_t i) { return i; }) << "},\n\"reference\":";
  if (reference.empty())
    json << "null";
  else
    json << "{\"name\":" << detail::script_json_string(view.reference_name) << ",\"points\":\""
         << encoded(reference_line, origin) << "\"}";
  TextTable texts;
  json << ",\n\"steps\":{\"name\":" << detail::script_json_string(view.step_name)
       << ",\"count\":" << steps.size()
       << ",\"number\":" << numbers.array(steps, [](const RunViewStep& s) { return s.number; })
       << ",\n\"pose\":" << numbers.array(steps, [](const RunViewStep& s) { return s.pose; })
       << ",\n\"from\":" << numbers.array(steps, [](const RunViewStep& s) { return s.from_scan; })
       << ",\n\"to\":" << numbers.array(steps, [](const RunViewStep& s) { return s.to_scan; })
       << ",\n\"stamp\":" << numbers.array(steps, [](const RunViewStep& s) { return s.stamp; })
       << ",\n\"verdict\":"
       << numbers.array(steps, [](const RunViewStep& s) { return static_cast<int>(verdict_of(s)); })
       << ",\n\"converged\":"
       << numbers.array(steps, [](const RunViewStep& s) { return s.converged ? 1 : 0; })
       << ",\n\"error_m\":" << short_numbers.array(steps, [](const RunViewStep& s) { return s.error_m; })
       << ",\n\"error_deg\":" << short_numbers.array(steps, [](const RunViewStep& s) { return s.error_deg; })
       << ",\n\"trust\":" << texts.indices(steps, &RunViewStep::trust)
       << ",\n\"first_trust\":" << texts.indices(steps, &RunViewStep::first_trust)
       << ",\n\"recovery\":" << texts.indices(steps, &RunViewStep::recovery)
       << ",\n\"reason\":" << texts.indices(steps, &RunViewStep::reason)
       << ",\n\"status\":" << texts.indices(steps, &RunViewStep::status) << ",\n\"texts\":" << texts.texts()
       << "},\n\"error_name\":" << detail::script_json_string(view.error_name) << ",\"error_scale\":" << scale
       << ",\"colour_by_error\":" << (view.colour_by_error && scale > 0.0 ? "true" : "false") << "}";

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
         << (map.size() < finite_map.size()
                 ? detail::grouped(map.size()) + " of " + detail::grouped(finite_map.size())
                 : detail::grouped(map.size()))
         << " points, shaded by height</span></label></li>\n";
  page << "<li><label><input type=\"checkbox\" data-layer=\"estimate\" checked=\"checked\"/><span "
          "class=\"sx-swatch "
          "sx-line sx-estimate\"></span>"
       << escape_html(view.estimate_name) << " " << count(estimate.size(), "pose") << "</label></li>\n";
  if (!reference.empty())
    page << "<li><label><input type=\"checkbox\" data-layer=\"reference\" checked=\"checked\"/><span "
            "class=\"sx-swatch "
            "sx-line sx-reference\"></span>"
         << escape_html(view.reference_name) << "</label></li>\n";
  const std::pair<StepVerdict, const char*> markers[] = {{StepVerdict::untrusted, "untrusted"},
                                                         {StepVerdict::not_converged, "not converged"},
                                                         {StepVerdict::recovered, "recovered"}};
  const bool assessed = verdicts[static_cast<std::size_t>(StepVerdict::unassessed)] < steps.size();
  for (const auto& [verdict, label] : markers) {
    if (!assessed) break;  // no trust is known: no markers to speak of
    const auto v = static_cast<int>(verdict);
    page << "<li" << (verdicts[static_cast<std::size_t>(v)] ? "" : " class=\"sx-absent\"")
         << "><label><input type=\"checkbox\" data-layer=\"marker" << v
         << "\" checked=\"checked\"/><span class=\"sx-dot sx-v" << v << "\"></span>" << label << " "
         << count(verdicts[static_cast<std::size_t>(v)], view.step_name) << "</label></li>\n";
  }
  page << "</ul>\n";
  if (scale > 0.0)
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
       << detail::grouped(line.size()) << " of " << detail::grouped(estimate.size()) << " vertices"
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
  page << "<script type=\"application/json\" id=\"sx-data\">" << json.str() << "</script>\n<script>\n"
       << detail::run_view_panel_script() << detail::run_view_script() << "</script>\n</body>\n</html>\n";
  return page.str();
}

void write_run_view(const RunView& view, const std::filesystem::path& path,
                    const std::filesystem::path& three_js_dir) {
  write_file_atomically(path, render_run_view(view, three_js_dir));
}

}  // namespace sextant
