// What a run's page keeps of its trajectories and says of its steps (run_view.hpp): the decimated
// polyline (Douglas–Peucker on position and on the value the line is coloured by) and a step's verdict.
#include <algorithm>
#include <cmath>
#include <utility>

#include "sextant/eval/run_view.hpp"

namespace sextant {
namespace {

/// x in units of `tolerance` (tolerance 0: any x > 0 is too far).
double in_units(double x, double tolerance) {
  return tolerance > 0.0 ? x / tolerance : x > 0.0 ? INFINITY : 0.0;
}

/// How far vertex k's value lies from the chord's between vertices a and b (linear in the index), in
/// units of `tolerance`. NaN is a colour of its own: a chord between two NaNs fits NaN vertices only;
/// a chord between a NaN and a number fits none, and the vertices on either side of a change between
/// NaN and numbers are the ones that must stay (infinitely far), the others fit.
double value_deviation(const std::vector<double>& v, std::size_t a, std::size_t b, std::size_t k,
                       const std::vector<std::size_t>& at, double tolerance) {
  const double va = v[at[a]], vb = v[at[b]], vk = v[at[k]];
  if (std::isnan(va) && std::isnan(vb)) return std::isnan(vk) ? 0.0 : INFINITY;
  if (std::isnan(va) || std::isnan(vb)) {
    const bool change =
        std::isnan(v[at[k - 1]]) != std::isnan(vk) || std::isnan(v[at[k + 1]]) != std::isnan(vk);
    return change ? INFINITY : 0.0;
  }
  if (std::isnan(vk)) return INFINITY;
  const double t = static_cast<double>(k - a) / static_cast<double>(b - a);
  return in_units(std::abs(vk - (va + t * (vb - va))), tolerance);
}

/// The distance of p from the segment a–b.
double segment_distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& p) {
  const Eigen::Vector3d d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

}  // namespace

std::string to_string(StepVerdict verdict) {
  switch (verdict) {
    case StepVerdict::trusted: return "trusted";
    case StepVerdict::recovered: return "recovered";
    case StepVerdict::untrusted: return "untrusted";
    case StepVerdict::not_converged: return "not converged";
    case StepVerdict::unassessed: return "no verdict";
  }
  return "no verdict";
}

StepVerdict verdict_of(const RunViewStep& step) {
  if (!step.assessed) return StepVerdict::unassessed;
  if (!step.trusted)
    return step.converged && step.trust != "not_converged" ? StepVerdict::untrusted
                                                           : StepVerdict::not_converged;
  return step.recovered ? StepVerdict::recovered : StepVerdict::trusted;
}

std::vector<std::size_t> decimate_polyline(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<double>& values, double tolerance,
                                           double value_tolerance, const std::vector<bool>& keep) {
  // The finite vertices, as one polyline.
  std::vector<std::size_t> finite;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].allFinite()) finite.push_back(i);
  if (finite.size() <= 2) return finite;
  std::vector<bool> kept(finite.size(), false);
  kept.front() = kept.back() = true;
  // Douglas–Peucker with a stack of spans [a, b] of `finite` (no recursion: long runs stay shallow);
  // the forced vertices split the line first.
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  std::size_t start = 0;
  for (std::size_t k = 1; k < finite.size(); ++k) {
    if (k + 1 < finite.size() && !(keep.size() == points.size() && keep[finite[k]])) continue;
    kept[k] = true;
    spans.emplace_back(start, k);
    start = k;
  }
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    if (b <= a + 1) continue;
    const Eigen::Vector3d& pa = points[finite[a]];
    const Eigen::Vector3d& pb = points[finite[b]];
    double worst = 0.0;
    std::size_t at = a;
    for (std::size_t k = a + 1; k < b; ++k) {
      const double position = in_units(segment_distance(pa, pb, points[finite[k]]), tolerance);
      const double colour =
          values.size() == points.size() ? value_deviation(values, a, b, k, finite, value_tolerance) : 0.0;
      const double deviation = std::max(position, colour);
      if (deviation > worst) worst = deviation, at = k;
    }
    if (worst <= 1.0) continue;
    kept[at] = true;
    spans.emplace_back(a, at);
    spans.emplace_back(at, b);
  }
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < finite.size(); ++k)
    if (kept[k]) out.push_back(finite[k]);
  return out;
}

}  // namespace sextant
