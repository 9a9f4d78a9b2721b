#include "sextant/features/association.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sextant {

namespace {

constexpr std::int64_t kHalf = std::int64_t{1} << 20;

std::int64_t cell_coordinate(double value, double inv_cell) {
  const double c = std::floor(value * inv_cell);
  return static_cast<std::int64_t>(std::clamp(c, -double(kHalf), double(kHalf - 1)));
}

std::uint64_t pack(std::int64_t x, std::int64_t y, std::int64_t z) {
  auto field = [](std::int64_t v) {
    return static_cast<std::uint64_t>(std::clamp(v, -kHalf, kHalf - 1) + kHalf);
  };
  return (field(x) << 42) | (field(y) << 21) | field(z);
}

}  // namespace

bool AssociationSettings::valid(std::string* why) const {
  if (!thresholds.valid(why)) return false;
  if (!(search_radius > 0.0 && std::isfinite(search_radius))) {
    if (why) *why = "search_radius must be positive";
    return false;
  }
  return true;
}

LandmarkIndex::LandmarkIndex(const std::vector<PlaneLandmark>& map, double cell_size)
    : cell_size_(cell_size > 0.0 && std::isfinite(cell_size) ? cell_size : 1.0) {
  const double inv = 1.0 / cell_size_;
  centroids_.reserve(map.size());
  cells_.reserve(map.size());
  for (std::size_t i = 0; i < map.size(); ++i) {
    const Eigen::Vector3d& c = map[i].centroid;
    centroids_.push_back(c);
    if (!c.allFinite()) continue;
    cells_[pack(cell_coordinate(c.x(), inv), cell_coordinate(c.y(), inv), cell_coordinate(c.z(), inv))]
        .push_back(i);
  }
}

void LandmarkIndex::query(const Eigen::Vector3d& point, double radius, std::vector<std::size_t>* out) const {
  out->clear();
  if (!point.allFinite()) return;
  const double inv = 1.0 / cell_size_;
  const std::int64_t cx = cell_coordinate(point.x(), inv), cy = cell_coordinate(point.y(), inv),
                     cz = cell_coordinate(point.z(), inv);
  const double r2 = radius * radius;
  for (std::int64_t dx = -1; dx <= 1; ++dx) {
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dz = -1; dz <= 1; ++dz) {
        const auto it = cells_.find(pack(cx + dx, cy + dy, cz + dz));
        if (it == cells_.end()) continue;
        for (std::size_t i : it->second) {
          if ((centroids_[i] - point).squaredNorm() <= r2) out->push_back(i);
        }
      }
    }
  }
  std::sort(out->begin(), out->end());
}

AssociationResult associate_landmarks(const std::vector<PlaneLandmark>& observed_in_world,
                                      const std::vector<PlaneLandmark>& map,
                                      const AssociationSettings& settings) {
  return associate_landmarks(observed_in_world, map, LandmarkIndex(map, settings.search_radius), settings);
}

AssociationResult associate_landmarks(const std::vector<PlaneLandmark>& observed_in_world,
                                      const std::vector<PlaneLandmark>& map, const LandmarkIndex& index,
                                      const AssociationSettings& settings) {
  return associate_landmarks(
      observed_in_world, map.size(), [&](std::size_t m) -> const PlaneLandmark& { return map[m]; },
      [&](const PlaneLandmark& o, std::vector<std::size_t>* out) {
        index.query(o.centroid, settings.search_radius, out);
      },
      settings);
}

// §4.2.5: orientation and translation tests first, then closeness; the best candidate of each
// observation by C_p, conflicts on one map landmark resolved in favour of the smaller C_p.
AssociationResult associate_landmarks(const std::vector<PlaneLandmark>& observed_in_world,
                                      std::size_t map_size,
                                      const std::function<const PlaneLandmark&(std::size_t)>& map_at,
                                      const LandmarkCandidates& candidate_query,
                                      const AssociationSettings& settings) {
  AssociationResult result;
  std::vector<LandmarkMatch> proposals;
  std::vector<std::size_t> candidates;
  for (std::size_t o = 0; o < observed_in_world.size(); ++o) {
    candidate_query(observed_in_world[o], &candidates);
    LandmarkMatch best;
    best.criteria.closeness = std::numeric_limits<double>::infinity();
    bool found = false;
    for (std::size_t m : candidates) {
      if (m >= map_size) continue;
      MergeCriteria c;
      ++result.candidates_tested;
      if (!merge_test(observed_in_world[o], map_at(m), settings.thresholds, &c)) continue;
      if (c.closeness < best.criteria.closeness) {
        best = LandmarkMatch{o, m, c};
        found = true;
      }
    }
    if (found) proposals.push_back(best);
  }
  std::stable_sort(proposals.begin(), proposals.end(), [](const LandmarkMatch& a, const LandmarkMatch& b) {
    return a.criteria.closeness < b.criteria.closeness;
  });
  std::vector<bool> map_taken(map_size, false), observed_matched(observed_in_world.size(), false);
  for (const auto& p : proposals) {
    if (map_taken[p.map]) continue;
    map_taken[p.map] = true;
    observed_matched[p.observed] = true;
    result.matches.push_back(p);
  }
  std::sort(result.matches.begin(), result.matches.end(),
            [](const LandmarkMatch& a, const LandmarkMatch& b) { return a.observed < b.observed; });
  for (std::size_t o = 0; o < observed_in_world.size(); ++o) {
    if (!observed_matched[o]) result.new_landmarks.push_back(o);
  }
  return result;
}

}  // namespace sextant
