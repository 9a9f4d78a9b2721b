#pragma once
// Plane SLAM driven by real extraction and semantic association (§4.2, §4.2.5). Per scan:
//   1. predict with the odometry increment u = odometry_increment(o(k−1), o(k)) (eq. 4.72);
//   2. extract plane landmarks from the scan (§4.1, features/extraction.hpp);
//   3. transform them to the world with the predicted pose (eqs. 4.57–4.61);
//   4. associate them with the map's semantic landmarks (C_o, C_t, C_p tests, §4.2.5), then
//      drop matches whose innovation fails the χ² gate (innovation_gate.hpp; with SEIF its
//      Markov-blanket covariance) — a dropped observation neither updates nor augments;
//   5. update with the matched observations z = (nᴸ, dᴸ) (eq. 4.64), augment with the new ones
//      (eqs. 4.57–4.58, 4.67–4.68);
//   6. copy the filter's (n, d) into the map landmarks and merge the associated observations'
//      semantic data (centroid, covariance, hull, area) into them (merge_landmark_semantics).
// The map's semantic landmarks are parallel to the filter's landmarks (same index).
//
// FastSLAM (filter fastslam2, particle_association on): steps 3–6 run in every particle against
// its own landmarks (plane_particle_association.hpp, FastSlam::update_associating): each particle
// transforms the planes with its own predicted pose, associates them by the same tests and gate,
// updates, and creates its own new landmarks. What the step reports is the representative
// particle's (the highest-weight one, FastSlam::representative()): its matched / gated counts,
// its landmark per observation, and its semantic map as map() — map_size is its map's size;
// candidates_tested sums over the particles.
//
//   PlaneSlamSettings s;                    // or read_plane_slam_settings (filters/yaml.hpp)
//   PlaneSlam slam(s, to_pose6(first_ground_truth), seed);
//   for (i …) PlaneSlamStep step = slam.step(scan(i), odometry_pose(i));   // first call: no predict
//
// Or, for a whole sequence: run_plane_slam(s, scans, odometry, initial_pose, seed), with a
// per-scan callback (what the caller records) and, for hybrid SLAM, a motion source.
//
// Hybrid SLAM (E21) drives the prediction with a scan matcher instead of the odometry and shares
// the extraction with it: extract(scan) runs step 2 and returns the extraction (its cell-plane
// inliers are FbML-NDT's sample, Table 3.2), then step(u, Q) runs steps 1 and 3–6 on it.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/core/units.hpp"
#include "sextant/features/association.hpp"
#include "sextant/features/extraction.hpp"
#include "sextant/filters/filter.hpp"
#include "sextant/filters/relative_motion.hpp"
#include "sextant/filters/slam_runner.hpp"

namespace sextant {

/// The largest P0 scale [-]: E13 scales P0 by up to 1e6 to show the UKF failing; beyond 1e12
/// the initial σ passes kilometres and the covariances overflow their precision.
inline constexpr double kMaxP0Scale = 1e12;

struct PlaneSlamSettings {
  std::string filter = "ekf";  ///< the filter: ekf, ukf, ckf, rspkf, seif, eif, eseif (filter.hpp)
  /// Builds `filter` with settings of its own (read_plane_slam_settings: from the YAML map
  /// `filter_settings`); empty: `filter` with its defaults (default_filter)
  FilterFactory filter_factory;
  PlaneExtractionSettings extraction;  ///< §4.1
  AssociationSettings association;     ///< §4.2.5
  // Q: noise of one odometry increment (eq. 4.72). 2D odometry says nothing about z, roll and
  // pitch, so those entries carry the vehicle's unmodelled motion.
  double sigma_xy = 0.2;           ///< σ of δx, δy [m]
  double sigma_z = 0.1;            ///< σ of δz [m]
  double sigma_roll_pitch = 0.01;  ///< σ of δα, δβ [rad]
  double sigma_yaw = 0.02;         ///< σ of δγ [rad]
  // R: noise of one plane observation (eq. 4.64).
  double sigma_normal = 0.02;   ///< σ of each normal component [1]
  double sigma_distance = 0.1;  ///< σ of d [m]
  // P0 = p0_scale · diag(σ_t², σ_t², σ_t², σ_r², σ_r², σ_r²) for the initial pose.
  double initial_sigma_translation = 0.01;  ///< [m]
  double initial_sigma_rotation = 0.001;    ///< [rad]
  double p0_scale = 1.0;               ///< the thesis scales P0 up to show UKF failures [-, ≤ kMaxP0Scale]
  double gate_probability = 0.99;      ///< χ² gate of step 4 at this probability; 0 turns it off [-]
  bool merge_semantics = true;         ///< step 6 (off: map semantics stay as first seen)
  bool record_pose_covariance = true;  ///< pose covariance per step (O(n³) for information filters)
  /// FastSLAM (fastslam2): steps 3–6 per particle against its own landmarks (header comment); off: as
  /// the Gaussian filters, against the weighted-mean map with one association for every particle
  bool particle_association = true;

  bool valid(std::string* why) const;
  /// The filter on `model`: filter_factory's, else default_filter(filter)'s.
  std::unique_ptr<Filter> build_filter(std::shared_ptr<const SlamModel> model) const;
  Matrix6d process_noise() const;             ///< Q
  Eigen::Matrix4d observation_noise() const;  ///< R
  Matrix6d initial_covariance() const;        ///< P0
};

/// One scan of plane SLAM.
struct PlaneSlamStep {
  SlamStepRecord filter;      ///< pose after the step, statuses, counts and predict/update/augment times
  std::size_t extracted = 0;  ///< landmarks extracted from the scan
  std::size_t matched = 0;    ///< associated with the map (= filter.updated when the update ran)
  std::size_t gated = 0;      ///< semantic matches the χ² gate dropped (not in `matched`)
  std::size_t map_size = 0;   ///< landmarks in the map after the step
  /// Per extracted landmark: the filter landmark it observed or created, or −1 (gated, or
  /// augmentation failed).
  std::vector<int> observation_landmark;
  std::size_t candidates_tested = 0;  ///< association pairs evaluated
  double extraction_seconds = 0.0;
  double association_seconds = 0.0;
  double seconds = 0.0;  ///< wall time of the whole step
};

class PlaneSlam {
 public:
  /// Throws std::invalid_argument for invalid settings, InputError for bad filter settings.
  PlaneSlam(PlaneSlamSettings settings, const Pose6& initial_pose, std::uint64_t seed);

  /// Processes one scan (sensor frame) with the odometry pose it was taken at. The first call
  /// only extracts and augments (the filter starts at the initial pose).
  PlaneSlamStep step(const PointCloud& scan, const Pose6& odometry_pose);
  /// Step 2 alone: extracts the scan's planes for the next step(u, Q) and returns the extraction.
  const PlaneExtraction& extract(const PointCloud& scan);
  /// Steps 1 and 3–6 on the last extract(), predicting with the control u of eq. (4.72) and its
  /// covariance Q (the first step does not predict).
  PlaneSlamStep step(const Vector6d& u, const Matrix6d& Q);

  const Filter& filter() const { return *filter_; }
  Pose6 pose() const;
  /// The semantic map, parallel to the filter's landmarks.
  const std::vector<PlaneLandmark>& map() const { return map_; }
  /// The last scan's extracted landmarks in the sensor frame (inliers index the scan).
  const std::vector<PlaneLandmark>& last_observed() const { return extraction_.landmarks; }

 private:
  void sync_map_planes();
  /// Steps 3–6 per particle (FastSLAM, plane_slam_particles.cpp).
  void particle_step(PlaneSlamStep& out);

  PlaneSlamSettings s_;
  double gate_ = 0.0;  ///< χ² quantile of gate_probability (0: no gate)
  std::unique_ptr<Filter> filter_;
  Rng rng_;
  std::vector<PlaneLandmark> map_;
  PlaneExtraction extraction_;  ///< the last scan's (landmarks: the observations)
  double extraction_seconds_ = 0.0;
  Pose6 last_odometry_;
  bool started_ = false;
};

struct PlaneSlamRun {
  std::vector<PlaneSlamStep> steps;
  std::vector<Pose6> trajectory;  ///< estimated pose after every scan
  FilterSummary summary;          ///< the filter's status counts over the run
  std::size_t failed_steps = 0;   ///< steps with any non-ok filter status
  std::size_t map_size = 0;
};

/// Called after every scan with its index, its step and the filter after it.
using PlaneSlamStepCallback =
    std::function<void(std::size_t scan, const PlaneSlamStep& step, const Filter& filter)>;
/// What scan i ≥ 1 predicts with, from its extraction and the filter before the step, given the
/// odometry's increment (eq. 4.72) and Q: hybrid SLAM's scan matcher (E21).
using PlaneSlamMotionSource =
    std::function<MotionIncrement(std::size_t scan, const PlaneExtraction& extraction, const Filter& filter,
                                  const MotionIncrement& odometry)>;

/// Runs plane SLAM over `count` scans: scan(i) gives scan i in the sensor frame, odometry[i]
/// its odometry pose (world ← sensor); the filter starts at `initial_pose`. Scan i extracts, then
/// predicts with the odometry increment o(i−1) ⊖ o(i) (eq. 4.72) or `motion`'s, then steps.
PlaneSlamRun run_plane_slam(const PlaneSlamSettings& settings, std::size_t count,
                            const std::function<PointCloud(std::size_t)>& scan,
                            const std::vector<Eigen::Isometry3d>& odometry, const Pose6& initial_pose,
                            std::uint64_t seed, const PlaneSlamStepCallback& on_step = {},
                            const PlaneSlamMotionSource& motion = {});

}  // namespace sextant
