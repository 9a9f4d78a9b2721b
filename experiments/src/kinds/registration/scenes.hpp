#pragma once
// Displaced pairs of the `registration` kind (§5.1.1.1): a scene is a scan pair with a known
// relative pose; its input is moved so that the true transform becomes a chosen offset D and the
// matcher starts from the identity ("without any initialisation").
//
//   params:
//     pairs: displaced
//     displaced:
//       offset_unit: ndt_cell    # offsets in NDT cell edges of the scene's reference | m
//       scenes:
//         - {name: campus_020, scan: 20}            # dataset scans 20 → 21 (second: default scan + 1)
//         - {name: velodyne, reference: a.pcd, input: b.pcd, truth: T.txt}   # 4×4, p_ref = T·p_in
//         - {name: room, reference: a.pcd, input: b.pcd, truth_pose: [x, y, z, α, β, γ]}  # [m, deg]
//       snapshot: {scene: campus_100, offset: 2, direction: 0, yaw: 15}  # clouds kept for figs 5.1/5.2
//       snapshot_points: 1500
//   sweep:
//     scene: [campus_020, velodyne]   # scene names (default: every scene)
//     offset: [0, 0.5, 1]             # translation magnitude [offset_unit]
//     direction: [0, 1, 2, 3]         # 0: +x, +yaw   1: +y, −yaw   2: −x, −yaw   3: −y, +yaw
//     yaw: [0, 5, 10]                 # rotation about z [deg] (signed by direction)
//     tx: [0, 5]                      # translation along x [m] (added to the offset)
//
// Paths are relative to the config file. Without a `displaced` block the one scene is
// params.scan → params.second of the dataset.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>
#include <Eigen/Geometry>

#include "registration/settings.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"
#include "sextant/experiments/run_plan.hpp"

namespace sextant {

struct SceneSpec {
  std::string name;
  long scan = -1, second = -1;                  ///< dataset scans (scan ≥ 0), or
  std::string reference, input, truth;          ///< files (absolute after reading)
  std::optional<Eigen::Isometry3d> truth_pose;  ///< truth given inline
};

struct SnapshotSpec {
  std::string scene;
  double offset = 0, direction = 0, yaw = 0;
};

struct DisplacedSettings {
  bool cells = true;  ///< offsets in NDT cell edges (else metres)
  std::vector<SceneSpec> scenes;
  std::optional<SnapshotSpec> snapshot;
  int snapshot_points = 1500;
};

/// Reads params.displaced (InputError with file, line, key); the legacy single scene without it.
DisplacedSettings read_displaced_settings(const ExperimentConfig& config, const RegistrationParams& params);
/// Checks the displaced sweep axes (scene names known, direction in 0..3).
void check_displaced_sweep(const ExperimentConfig& config, const DisplacedSettings& settings);

/// The translation direction [deg] and yaw sign of a `direction` value.
struct Direction {
  double heading_deg;
  double yaw_sign;
};
Direction direction_of(int direction);

/// One displaced registration problem.
struct DisplacedCase {
  const PointCloud* reference = nullptr;
  PointCloud input;  ///< moved so that `truth` maps it into the reference frame
  Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
  std::size_t scene = 0;
  double cell_edge = 0;  ///< NDT cell edge of the scene [m]
  double offset_m = 0, heading_deg = 0, yaw_deg = 0;
  bool snapshot = false;  ///< this run's clouds are kept for the figures
};

class DisplacedScenes {
 public:
  /// Loads every scene (files, dataset scans) in parallel; a missing file is an error naming it.
  DisplacedScenes(const ExperimentConfig& config, const RegistrationParams& params, const Dataset& dataset);
  DisplacedCase displace(const RunSpec& run) const;
  const DisplacedSettings& settings() const { return settings_; }

 private:
  struct Scene {
    PointCloud reference, input;
    Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
    double cell_edge = 0;
  };
  DisplacedSettings settings_;
  std::vector<Scene> scenes_;
};

/// A subsample (at most `count`, deterministic stride) of the points between the 30th and 95th
/// height percentiles, flattened x, y, z — the top-down figures' view without ground and floor.
std::vector<double> snapshot_points(const PointCloud& cloud, int count);

}  // namespace sextant
