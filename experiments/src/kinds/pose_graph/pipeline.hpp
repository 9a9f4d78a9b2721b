#pragma once
// One run of the `pose_graph` kind. The odometry method: run_odometry chains ML-NDT
// registrations over the scans (odometry/odometry.hpp); loop-closure candidates along that chained
// trajectory are verified by the same matcher from the chain's relative guess and accepted by
// loop_closure.hpp; the pose graph (pose_graph.hpp) over the chain, with each edge's information
// from its registration Hessian (R = H⁻¹, eq. 3.50), is solved with the accepted closures, and —
// for the robustness check — again with `false_closures` injected "same place" closures between
// poses that are truly far apart, once with the robust loss and once without. A filter method:
// the plane_slam kind's record_plane_slam (kit/plane_slam_record.hpp) over the same scans.
// Every trajectory is scored by ATE (SE(3) Umeyama), Wulf (eqs. 6.1–6.3) and Kümmerle (eq. 6.6).
#include <cstdint>
#include <vector>

#include "kit/plane_slam_record.hpp"
#include "pose_graph/params.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/matchers/matcher_spec.hpp"

namespace sextant {

/// The campus' first scans, generated once and served through core's Dataset interface (so that
/// run_odometry reads them without generating them again); also the filters' per-scan landmarks.
class PreloadedCampus : public Dataset {
 public:
  PreloadedCampus(const synth::Campus& campus, std::size_t scans, bool with_landmarks);

  const DatasetMetadata& metadata() const override { return metadata_; }
  PointCloud scan(std::size_t i, ScanLoadReport* report = nullptr) const override;
  std::optional<Eigen::Isometry3d> odometry(std::size_t i) const override;
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const override;

  const synth::Campus& campus() const { return *data_.campus; }
  const std::vector<PointCloud>& clouds() const { return data_.clouds; }
  const CampusScans& filter_data() const { return data_; }

 private:
  DatasetMetadata metadata_;
  CampusScans data_;
};

/// The odometry method: chain, loop closures, graph solves; fills row.values and row.series.
void run_pose_graph_method(const PreloadedCampus& data, const PoseGraphParams& params,
                           const RegistrationSpec& method, const MatcherSpec& closure, std::uint64_t seed,
                           RunRow& row);
/// A plane-SLAM filter over the first `scans` scans.
void run_filter_method(const PreloadedCampus& data, const PoseGraphParams& params,
                       const PlaneSlamMethod& method, std::uint64_t seed, const std::string& file,
                       RunRow& row);

}  // namespace sextant
