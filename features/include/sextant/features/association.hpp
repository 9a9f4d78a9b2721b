#pragma once
// Semantic data association of planar landmarks (§4.2.5): the merging tests (C_o, C_t, C_p)
// with their own thresholds between observed landmarks (already transformed to the world by
// the predicted pose) and map landmarks. Candidates come from a spatial hash on centroids, so
// the cost is linear in the number of observed landmarks and their nearby map landmarks.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sextant/features/landmark.hpp"
#include "sextant/features/merging.hpp"

namespace sextant {

struct AssociationSettings {
  MergeThresholds thresholds{20.0, 1.0, 15.0, 1e-4};  ///< relaxed t_o [deg], t_t [m], t_p [1]
  double search_radius = 30.0;  ///< map landmarks with centroids farther than this are not candidates [m]
  bool valid(std::string* why) const;
};

struct LandmarkMatch {
  std::size_t observed = 0;  ///< index into the observed landmarks
  std::size_t map = 0;       ///< index into the map landmarks
  MergeCriteria criteria;    ///< C_o, C_t, C_p, d_c of the pair
};

struct AssociationResult {
  std::vector<LandmarkMatch> matches;      ///< one-to-one, by observed index
  std::vector<std::size_t> new_landmarks;  ///< observed indices without a match
  std::size_t candidates_tested = 0;       ///< pairs evaluated
};

/// Spatial hash of map-landmark centroids (cell = search radius, 27-cell query).
class LandmarkIndex {
 public:
  LandmarkIndex(const std::vector<PlaneLandmark>& map, double cell_size);
  /// Indices of landmarks whose centroid lies within `radius` (≤ cell size) of `point`, ascending.
  void query(const Eigen::Vector3d& point, double radius, std::vector<std::size_t>* out) const;

 private:
  double cell_size_;
  std::vector<Eigen::Vector3d> centroids_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

/// Each observed landmark is matched to the passing map landmark of smallest C_p; conflicts
/// (two observations on one map landmark) go to the smaller C_p, the other becomes new.
AssociationResult associate_landmarks(const std::vector<PlaneLandmark>& observed_in_world,
                                      const std::vector<PlaneLandmark>& map,
                                      const AssociationSettings& settings);
AssociationResult associate_landmarks(const std::vector<PlaneLandmark>& observed_in_world,
                                      const std::vector<PlaneLandmark>& map, const LandmarkIndex& index,
                                      const AssociationSettings& settings);

/// The map landmarks near an observed one (within the search radius of its centroid; indices
/// below the map size, ascending).
using LandmarkCandidates = std::function<void(const PlaneLandmark& observed, std::vector<std::size_t>* out)>;
/// The same tests and conflict rule on a map given by its size, an accessor and a candidate
/// query (FastSLAM's per-particle maps, filters/plane_particle_association.hpp, which are not
/// vectors of landmarks).
AssociationResult associate_landmarks(const std::vector<PlaneLandmark>& observed_in_world,
                                      std::size_t map_size,
                                      const std::function<const PlaneLandmark&(std::size_t)>& map_at,
                                      const LandmarkCandidates& candidates,
                                      const AssociationSettings& settings);

}  // namespace sextant
