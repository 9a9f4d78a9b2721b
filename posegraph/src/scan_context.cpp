#include "sextant/posegraph/scan_context.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sextant {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

}  // namespace

bool ScanContextSettings::valid(std::string* why) const {
  const auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (rings < 1 || sectors < 3) return fail("rings must be ≥ 1 and sectors ≥ 3");
  if (!(max_range > 0.0) || !std::isfinite(max_range)) return fail("max_range must be a positive number [m]");
  if (!std::isfinite(height_offset)) return fail("height_offset must be a number [m]");
  if (ring_key_neighbours < 1) return fail("ring_key_neighbours must be ≥ 1");
  if (!(max_distance >= 0.0 && max_distance <= 1.0)) return fail("max_distance must be in [0, 1]");
  if (min_index_gap < 1) return fail("min_index_gap must be ≥ 1");
  if (stride < 1) return fail("stride must be ≥ 1");
  return true;
}

ScanContext make_scan_context(const PointCloud& cloud, const ScanContextSettings& settings) {
  const auto rings = static_cast<Eigen::Index>(settings.rings);
  const auto sectors = static_cast<Eigen::Index>(settings.sectors);
  ScanContext sc;
  sc.image = Eigen::MatrixXf::Zero(rings, sectors);
  const double ring_width = settings.max_range / static_cast<double>(settings.rings);
  for (const Eigen::Vector3f& p : cloud.points()) {
    const double range = std::hypot(double(p.x()), double(p.y()));
    if (!(range < settings.max_range)) continue;  // also drops NaN
    const double height = double(p.z()) + settings.height_offset;
    if (!(height > 0.0)) continue;
    double azimuth = std::atan2(double(p.y()), double(p.x()));  // (−π, π]
    if (azimuth < 0.0) azimuth += kTwoPi;
    const auto ring = std::min<Eigen::Index>(static_cast<Eigen::Index>(range / ring_width), rings - 1);
    const auto sector = std::min<Eigen::Index>(
        static_cast<Eigen::Index>(azimuth / kTwoPi * static_cast<double>(sectors)), sectors - 1);
    float& bin = sc.image(ring, sector);
    bin = std::max(bin, static_cast<float>(height));
  }
  sc.ring_key = sc.image.rowwise().mean();
  return sc;
}

ScanContextMatch compare_scan_contexts(const ScanContext& earlier, const ScanContext& later) {
  const Eigen::Index sectors = earlier.image.cols();
  ScanContextMatch best;
  if (later.image.cols() != sectors || later.image.rows() != earlier.image.rows() || sectors == 0)
    return best;
  const Eigen::RowVectorXf norm_a = earlier.image.colwise().norm();
  const Eigen::RowVectorXf norm_b = later.image.colwise().norm();
  const Eigen::MatrixXf dots = earlier.image.transpose() * later.image;  // (sector of A) × (sector of B)
  for (Eigen::Index n = 0; n < sectors; ++n) {
    double sum = 0.0;
    int columns = 0;
    for (Eigen::Index s = 0; s < sectors; ++s) {
      const Eigen::Index a = (s + n) % sectors;
      if (norm_a(a) <= 0.0f || norm_b(s) <= 0.0f) continue;
      sum += 1.0 - double(dots(a, s)) / (double(norm_a(a)) * double(norm_b(s)));
      ++columns;
    }
    if (columns == 0) continue;
    const double d = sum / columns;
    if (d < best.distance) {
      best.distance = d;
      best.shift = static_cast<int>(n);
    }
  }
  best.yaw = best.shift * kTwoPi / static_cast<double>(sectors);
  if (best.yaw > M_PI) best.yaw -= kTwoPi;
  return best;
}

Eigen::Isometry3d PlaceMatch::guess() const {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(match.yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

std::vector<PlaceMatch> find_place_matches(const std::vector<ScanContext>& contexts,
                                           const ScanContextSettings& settings) {
  std::vector<PlaceMatch> out;
  std::vector<std::pair<float, std::size_t>> by_key;
  for (std::size_t j = settings.min_index_gap; j < contexts.size(); ++j) {
    if (!out.empty() && j < out.back().j + settings.stride) continue;
    // The ring keys' nearest earlier scans: an exact linear search (a few floats per scan; a tree
    // pays only at far more scans than a sequence's loop search meets).
    by_key.clear();
    for (std::size_t i = 0; i + settings.min_index_gap <= j; ++i)
      by_key.emplace_back((contexts[i].ring_key - contexts[j].ring_key).squaredNorm(), i);
    const std::size_t k = std::min(settings.ring_key_neighbours, by_key.size());
    std::partial_sort(by_key.begin(), by_key.begin() + static_cast<std::ptrdiff_t>(k), by_key.end());
    PlaceMatch best;
    for (std::size_t q = 0; q < k; ++q) {
      const ScanContextMatch m = compare_scan_contexts(contexts[by_key[q].second], contexts[j]);
      if (m.distance < best.match.distance) best = {by_key[q].second, j, m};
    }
    if (best.match.distance <= settings.max_distance) out.push_back(best);
  }
  return out;
}

}  // namespace sextant
