// What a run's page holds (run_view_data.hpp): the map kept, the framing, the decimated lines, and
// the JSON block (coordinates relative to the scene's centre as float32 in base64, the steps as one
// array per field, their texts once each).
#include "run_view_data.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <locale>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "page_encoding.hpp"

namespace sextant::detail {
namespace {

std::vector<Eigen::Vector3d> positions(const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(poses.size());
  for (const Eigen::Isometry3d& T : poses) out.push_back(T.translation());
  return out;
}

/// The map's 2 % and 98 % quantiles on each axis (a few far returns left out); at most about 20 000
/// points are looked at.
std::pair<Eigen::Vector3d, Eigen::Vector3d> map_box(const std::vector<Eigen::Vector3f>& map) {
  const std::size_t stride = std::max<std::size_t>(1, map.size() / 20000);
  std::array<std::vector<double>, 3> axes;
  for (std::size_t k = 0; k < map.size(); k += stride)
    for (int a = 0; a < 3; ++a) axes[a].push_back(map[k][a]);
  return detail::central_box(axes);
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

bool RunPage::assessed() const {
  std::size_t total = 0;
  for (const std::size_t n : verdicts) total += n;
  return verdicts[static_cast<std::size_t>(StepVerdict::unassessed)] < total;
}

RunPage run_page(const RunView& view) {
  validate(view);
  RunPage page;
  std::vector<Eigen::Vector3f> finite;
  for (const Eigen::Vector3f& p : view.map.points())
    if (p.allFinite()) finite.push_back(p);
  page.finite_map_points = finite.size();
  for (const std::size_t i : view_subsample(finite.size(), view.max_map_points))
    page.map.push_back(finite[i]);
  page.estimate = positions(view.estimate);
  const std::vector<Eigen::Vector3d> reference = positions(view.reference);
  page.has_reference = !reference.empty();
  std::vector<Eigen::Vector3d> trajectory = page.estimate;
  trajectory.insert(trajectory.end(), reference.begin(), reference.end());
  std::tie(page.origin, page.radius) = framing(page.map, trajectory);

  // The estimate's line keeps every marked step and follows its error colour; the reference's its shape.
  page.error_scale = error_scale(view.steps);
  std::vector<double> pose_error(page.estimate.size(), std::nan(""));
  std::vector<bool> marked(page.estimate.size(), false);
  for (const RunViewStep& s : view.steps) {
    const StepVerdict v = verdict_of(s);
    ++page.verdicts[static_cast<std::size_t>(v)];
    marked[s.pose] = marked[s.pose] || (v != StepVerdict::trusted && v != StepVerdict::unassessed);
    if (std::isfinite(s.error_m))
      pose_error[s.pose] = std::max(std::isnan(pose_error[s.pose]) ? 0.0 : pose_error[s.pose], s.error_m);
  }
  const double tolerance = 2e-4 * page.radius;  // a tenth of a pixel at full view
  page.line = decimate_polyline(page.estimate, page.error_scale > 0.0 ? pose_error : std::vector<double>{},
                                tolerance, 0.02 * page.error_scale, marked);
  for (const std::size_t i : decimate_polyline(reference, {}, tolerance, 0.0, {}))
    page.reference.push_back(reference[i]);
  return page;
}

std::string run_page_json(const RunView& view, const RunPage& page) {
  const Eigen::Vector3d& origin = page.origin;
  const double scale = page.error_scale;
  std::ostringstream json;
  json.imbue(std::locale::classic());
  json.precision(17);
  JsonNumbers numbers(17), short_numbers(6);
  const auto& steps = view.steps;
  json << "{\"origin\":[" << origin.x() << "," << origin.y() << "," << origin.z()
       << "],\"radius\":" << page.radius << ",\"map\":{\"count\":" << page.map.size() << ",\"points\":\""
       << encoded(page.map, origin)
       << "\"},\n\"estimate\":{\"name\":" << script_json_string(view.estimate_name)
       << ",\"count\":" << page.estimate.size() << ",\"points\":\"" << encoded(page.estimate, origin)
       << "\",\"line\":" << numbers.array(page.line, [](std::size_t i) { return i; }) << "},\n\"reference\":";
  if (!page.has_reference)
    json << "null";
  else
    json << "{\"name\":" << script_json_string(view.reference_name) << ",\"points\":\""
         << encoded(page.reference, origin) << "\"}";
  TextTable texts;
  json << ",\n\"steps\":{\"name\":" << script_json_string(view.step_name) << ",\"count\":" << steps.size()
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
       << "},\n\"error_name\":" << script_json_string(view.error_name) << ",\"error_scale\":" << scale
       << ",\"colour_by_error\":" << (view.colour_by_error && scale > 0.0 ? "true" : "false") << "}";
  return json.str();
}

}  // namespace sextant::detail
