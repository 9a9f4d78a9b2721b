#pragma once
// Trajectory benchmarks: Wulf (eqs. 6.1–6.3, absolute errors), Kümmerle (eq. 6.6, relative
// displacement errors), ATE after Umeyama alignment and RPE (evo's semantics), and KITTI-style
// drift over 100–800 m segments. Poses are world ← body, associated by index; estimate and
// reference must have the same length. Units: metres and radians (convert for tables).
// Problems with the input (different lengths, too few poses, NaN) are reported in `status`,
// never thrown.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/trajectory.hpp"
#include "sextant/eval/statistics.hpp"
#include "sextant/eval/umeyama.hpp"

namespace sextant {

using PoseList = std::vector<Eigen::Isometry3d>;

/// The poses of a stamped trajectory, in order.
PoseList poses_of(const Trajectory& trajectory);

/// Outcome of a trajectory metric's input checks.
struct MetricStatus {
  bool ok = true;
  std::string message;  ///< why not ok
};

// ---- Wulf ----------------------------------------------------------------------------------

struct WulfResult {
  MetricStatus status;
  double position_rms = 0.0;               ///< σ_Wulf of e_pos, eqs. (6.1)–(6.2) [m]
  double orientation_rms = 0.0;            ///< σ_Wulf of e_ori, eqs. (6.1), (6.3) [rad]
  std::vector<double> position_errors;     ///< e_pos,i [m]
  std::vector<double> orientation_errors;  ///< e_ori,i [rad]
};

/// e_pos,i = ‖p_i − p_i*‖ (6.2); e_ori,i = ‖(α, β, γ)_i − (α, β, γ)_i*‖ with each difference
/// wrapped to (−π, π] (6.3, the thesis' eq. (3.8) angles); σ = sqrt(Σ e² / N) (6.1).
WulfResult wulf_metric(const PoseList& estimate, const PoseList& reference);

// ---- Kümmerle ------------------------------------------------------------------------------

/// A relation between poses i and j; the reference displacement δ*_ij comes from the reference
/// trajectory unless given explicitly (Kümmerle's manually verified relations).
struct PoseRelation {
  std::size_t i = 0, j = 0;
  bool has_reference_motion = false;
  Eigen::Isometry3d reference_motion = Eigen::Isometry3d::Identity();  ///< δ*_ij = x*_j ⊖ x*_i
};

/// (i, i+1) for i = 0 … n−2.
std::vector<PoseRelation> consecutive_relations(std::size_t pose_count);

struct KummerleResult {
  MetricStatus status;
  double translation_rms = 0.0;            ///< sqrt(Σ trans(δ_ij ⊖ δ*_ij)² / N), eq. (6.6) [m]
  double rotation_rms = 0.0;               ///< sqrt(Σ rot(δ_ij ⊖ δ*_ij)² / N), eq. (6.6) [rad]
  std::vector<double> translation_errors;  ///< per relation [m]
  std::vector<double> rotation_errors;     ///< per relation [rad]
};

/// Eq. (6.6), translation and rotation evaluated separately (as the thesis recommends):
/// δ_ij = x_i⁻¹ x_j, error ε = δ*_ij⁻¹ δ_ij, trans = ‖t(ε)‖, rot = angle(ε).
/// `reference` may be empty when every relation carries its reference motion.
KummerleResult kummerle_metric(const PoseList& estimate, const PoseList& reference,
                               const std::vector<PoseRelation>& relations);
/// Over consecutive pairs.
KummerleResult kummerle_metric(const PoseList& estimate, const PoseList& reference);

// ---- ATE -----------------------------------------------------------------------------------

enum class Alignment {
  none,    ///< compare as given
  se3,     ///< rigid Umeyama alignment of the estimate's positions onto the reference's
  sim3,    ///< with scale (monocular-style)
  origin,  ///< the estimate's first pose moved onto the reference's first (T = ref₀ · est₀⁻¹)
};

struct AteResult {
  MetricStatus status;
  Similarity3 alignment;                   ///< applied to the estimate: p ↦ s·R·p + t
  SampleStats translation;                 ///< ‖p_ref − align(p_est)‖ [m]; translation.rms is the ATE
  SampleStats rotation;                    ///< angle(R_ref⁻¹ · R_align · R_est) [rad]
  std::vector<double> translation_errors;  ///< per pose [m]
  /// se3/sim3: the positions were too close to a line to fix the rotation about it, which the
  /// orientations fixed instead (alignment_roll.hpp).
  bool roll_from_orientations = false;
};

AteResult absolute_trajectory_error(const PoseList& estimate, const PoseList& reference,
                                    Alignment alignment = Alignment::se3);

// ---- RPE -----------------------------------------------------------------------------------

/// evo's `evo_rpe` pair selection.
struct RpeSettings {
  enum class Unit { frames, meters };
  Unit unit = Unit::frames;
  double delta = 1.0;      ///< step between the poses of a pair [frames or m, along the reference]
  bool all_pairs = false;  ///< false: consecutive non-overlapping pairs; true: a pair from every pose
  double tolerance = 0.1;  ///< meters + all_pairs: accept a pair when |path − delta| ≤ this [m]

  bool valid(std::string* why) const;
};

struct RpeResult {
  MetricStatus status;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  SampleStats translation;  ///< ‖t(E_ij)‖ with E_ij = (ref_i⁻¹ ref_j)⁻¹ (est_i⁻¹ est_j) [m]
  SampleStats rotation;     ///< angle(E_ij) [rad]
  std::vector<double> translation_errors;
  std::vector<double> rotation_errors;
  /// Signed mean of the pairs' errors E_ij in pose i's frame, with its standard error (SD / √N):
  /// E_ij's rotation vector [rad] and translation [m]. A bias every step shares (each one pitched
  /// up by the same small angle) lies many standard errors from 0, where the unsigned RPE above
  /// cannot tell it from noise; it is what a drift is made of.
  Eigen::Vector3d mean_rotation_vector = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_vector_standard_error = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d translation_standard_error = Eigen::Vector3d::Zero();
  /// The motion's scale error: each pair's estimated motion minus the reference's, along the
  /// reference's motion (est_i⁻¹ est_j against ref_i⁻¹ ref_j, pose i's frame), summed over the pairs
  /// and divided by the reference's path over them [fraction: −0.0004 = every motion 0.04 % short],
  /// with its standard error (the along-motion errors' SD · √N over that path). Pairs whose reference
  /// moves less than kScaleMinMotion have no direction and are left out (scale_pairs counts the
  /// others; 0: NaN). A constant scale error is a drift of its own size. The axes' means above show
  /// it too where the sensor always moves along one of its own axes; this needs no such axis.
  double scale_error = 0.0;
  double scale_standard_error = 0.0;
  std::size_t scale_pairs = 0;
};

/// Reference motions shorter than this have no direction for RpeResult::scale_error [m].
inline constexpr double kScaleMinMotion = 0.01;

/// Pair indices as evo selects them (frames: (0,d), (d,2d), … or every (i, i+d); meters: path
/// length along the reference, see RpeSettings).
std::vector<std::pair<std::size_t, std::size_t>> rpe_pairs(const PoseList& reference,
                                                           const RpeSettings& settings);

RpeResult relative_pose_error(const PoseList& estimate, const PoseList& reference,
                              const RpeSettings& settings = {});

// ---- KITTI drift ---------------------------------------------------------------------------

struct KittiDriftSettings {
  std::vector<double> segment_lengths{100, 200, 300, 400, 500, 600, 700, 800};  ///< [m]
  std::size_t step = 10;  ///< first frames of segments: 0, step, 2·step, … (KITTI devkit: 10)

  bool valid(std::string* why) const;
};

struct KittiSegmentDrift {
  double length = 0.0;       ///< [m]
  std::size_t segments = 0;  ///< segments of this length found
  double translation = 0.0;  ///< mean ‖t(E)‖ / length [fraction: 0.01 = 1 %]
  double rotation = 0.0;     ///< mean angle(E) / length [rad/m]
};

struct KittiDriftResult {
  MetricStatus status;
  std::vector<KittiSegmentDrift> per_length;  ///< one per segment length (segments may be 0)
  std::size_t segments = 0;                   ///< all segments
  double translation = 0.0;                   ///< mean over all segments [fraction]; ×100 for KITTI's %
  double rotation = 0.0;                      ///< mean over all segments [rad/m]
};

/// The KITTI odometry devkit's metric: for every first frame (every `step`) and length L, the last
/// frame is the first whose path distance along the reference exceeds the first's by more than L;
/// E = (ref_i⁻¹ ref_j)⁻¹ (est_i⁻¹ est_j); errors ‖t(E)‖ / L and angle(E) / L averaged.
KittiDriftResult kitti_drift(const PoseList& estimate, const PoseList& reference,
                             const KittiDriftSettings& settings = {});

/// Cumulative path length along the poses' positions [m]; result[0] = 0.
std::vector<double> path_distances(const PoseList& poses);

}  // namespace sextant
