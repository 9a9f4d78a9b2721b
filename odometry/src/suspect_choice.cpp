// The registration chained when none is trusted: the scans pick a band of fits, the motion prior
// picks inside it (suspect_choice.hpp).
#include "sextant/odometry/suspect_choice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sextant {

double alignment_distance(const PointCloud& input, const Eigen::Isometry3d& a, const Eigen::Isometry3d& b,
                          std::size_t max_points) {
  const std::size_t n = input.size();
  if (n == 0 || max_points == 0) return 0.0;
  const std::size_t stride = std::max<std::size_t>(1, n / max_points);
  double sum = 0.0;
  std::size_t used = 0;
  for (std::size_t i = 0; i < n; i += stride, ++used) {
    const Eigen::Vector3d p = input[i].cast<double>();
    sum += (a * p - b * p).squaredNorm();
  }
  return std::sqrt(sum / static_cast<double>(used));
}

std::size_t choose_suspect(const std::vector<SuspectCandidate>& candidates, const PointCloud& input,
                           const Eigen::Isometry3d& guess, double fit_band) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const SuspectCandidate& c : candidates) lowest = std::min(lowest, c.fit_ratio);
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].fit_ratio > fit_band * lowest) continue;
    const double distance = alignment_distance(input, candidates[i].relative, guess);
    const bool nearer = distance < best_distance;
    const bool tie_lower_fit =
        distance == best_distance && candidates[i].fit_ratio < candidates[best].fit_ratio;
    if (nearer || tie_lower_fit) {
      best = i;
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace sextant
