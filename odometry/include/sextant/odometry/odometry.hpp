#pragma once
// Scan-matching odometry: registrations chained over consecutive scans of a dataset (§5.1.3's
// dead reckoning by a matcher, and the relative poses a pose graph is built from, §7.2):
//
//   OdometrySettings s;                       // ML-NDT on a GBS sample (s.registration)
//   s.guess = OdometryGuess::constant_velocity;
//   const OdometryResult r = run_odometry(dataset, s, /*first=*/0, /*count=*/100);
//   r.poses[i];                                // world ← scan first + i
//   r.steps[i].relative;                       // scan first + i + 1 in the frame of scan first + i
//   r.steps[i].hessian;                        // information of that relative pose, R = H⁻¹ (eq. 3.50)
//
// poses[i + 1] = poses[i] · steps[i].relative. Each registration i ← i + 1 starts from the guess
// mode's relative pose; with the dataset's odometry and scan-to-scan matching the registrations do
// not depend on each other and run in parallel (identical results for any thread count).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/core/enum_names.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/matchers/sensor_kind.hpp"
#include "sextant/odometry/deskew.hpp"
#include "sextant/odometry/platform.hpp"

namespace sextant {

/// Where each registration starts from.
enum class OdometryGuess {
  odometry,  ///< the odometry increment (dataset odometry, or OdometrySettings::odometry)
  /// The previous relative motion (identity for the first step), scaled by Δt_i / Δt_{i−1} when the
  /// dataset has times: keyframes of irregular spacing keep the velocity, not the last step
  constant_velocity,
  identity,  ///< no motion
};

/// What scan i is registered against.
enum class OdometryMap {
  scan,       ///< scan i − 1
  local_map,  ///< the last `local_map_scans` scans, in the frame of scan i − 1 (voxel-filtered when large)
};

/// The matcher and sampler of the registrations (matcher_choice.hpp: from their specs,
/// matcher_spec.hpp). Each worker builds its own.
struct OdometryRegistration {
  MatcherChoice matcher = matcher_choice(MlndtSettings{});          ///< default ML-NDT
  SamplerFactory sampler = sampler_factory(GridSamplerSettings{});  ///< default GBS
};

struct OdometrySettings {
  OdometryRegistration registration;
  OdometryGuess guess = OdometryGuess::odometry;
  /// The local map by default: measured better than scan-to-scan on the benchmark sequences
  /// (docs/matcher_defaults.md, "Scan-to-scan or a local map"); scan-to-scan runs its registrations in
  /// parallel with the odometry guess
  OdometryMap map = OdometryMap::local_map;
  std::size_t local_map_scans = 5;            ///< local_map: scans in the map (k ≥ 1)
  std::size_t local_map_max_points = 150000;  ///< local_map: voxel-filter the map above this size
  double local_map_voxel = 0.2;               ///< local_map: voxel edge [m] (centroid per voxel)
  /// Register only what both sensors see from the guess (common_view.hpp): the reference's points in the
  /// input sensor's band of elevations and range, the input's in the reference sensor's; false registers
  /// the whole scans. The default of ML-NDT, the default matcher (MatcherTraits::common_view_by_default,
  /// matcher_traits.hpp): measured more accurate on the benchmark sequences (docs/matcher_defaults.md,
  /// "Registering only what both scans can see")
  bool common_view = true;
  /// Points closer than this to the sensor are dropped from every scan before matching (the
  /// vehicle's own body moves with the sensor and pulls registrations towards no motion) [m]; 0 keeps all.
  double min_range = 0.0;
  std::uint64_t seed = 1;  ///< per-step sampler seeds derive from it
  /// Per-scan sampler seeds (index k: the registration of scan first + k, k ≥ 1) instead of the
  /// ones derived from `seed`; empty = derived. Lets a caller keep its own seed sequence.
  std::vector<std::uint64_t> seeds;
  /// World ← scan poses used instead of the dataset's odometry (e.g. simulated odometry), indexed
  /// from `first`; empty = the dataset's. Only their increments are used.
  std::vector<Eigen::Isometry3d> odometry;
  /// Pose of scan `first`; unset = its ground truth, else its odometry, else identity.
  std::optional<Eigen::Isometry3d> initial_pose;
  /// Guess odometry + map scan: run the independent registrations on all cores.
  bool parallel = true;
  /// When a registration is not trusted (registration_quality.hpp, and against the sequence: an
  /// overlap below 0.9 × or a fit above 1.1 × the median of the last 10 trusted steps): register
  /// again with the wide basin (mlndt and fbmlndt) from the guess, then (constant velocity) from no
  /// motion and the last trusted motion, and take the first result the absolute checks trust (the
  /// sequence check only triggers the search); else chain the last
  /// trusted motion (the odometry guess). Off: every registration is chained as the matcher
  /// returned it (its trust still recorded), a plain loop whose constant velocity continues the last
  /// chained motion.
  bool recover = true;
  /// With the constant-velocity guess and a clock: the hardest a platform accelerates or brakes. A
  /// motion that departs from the guess (velocity × Δt), and from that velocity held in the world,
  /// farther than this could in the time (and farther than QualitySettings' ambiguity tolerance) is not
  /// trusted on the scans' word alone
  /// (check_reachable_motion, sequence_trust.hpp). 1 g: a wheeled vehicle's tyres grip no harder
  /// (friction coefficient ≤ 1) [m/s²]; 0: no such check
  double max_acceleration = 9.81;
  /// The lidar (sensor_kind.hpp): the checks that rest on a spinning lidar's rings (no motion
  /// unconfirmed, the points above the horizon) apply only to a spinning one; automatic: measured on
  /// the first scan
  SensorKind sensor = SensorKind::automatic;
  /// What carries it (platform.hpp): the size of a wrong step, and of "no motion"; automatic: the
  /// sequence's typical step decides
  Platform platform = Platform::automatic;
  /// The checks of every registration; its ambiguity tolerance is a car's, which `platform` scales
  QualitySettings quality;
  /// Scans whose points carry their own time (PointCloud::time) are deskewed (deskew.hpp): each point
  /// moved into the scan's frame at its stamp by the constant velocity estimated around it, the motion
  /// the step's guess makes (the odometry's increment, or the last trusted motion continued), before the
  /// scan is registered and kept in the local map (docs/odometry.md, "Scans taken while moving").
  /// false: the points are registered where they were measured
  bool deskew = true;

  /// Empty when valid, else what is wrong.
  std::string problem() const;
};

/// One registration: scan i in the frame of scan i − 1.
struct OdometryStep {
  Eigen::Isometry3d relative = Eigen::Isometry3d::Identity();  ///< p_{i−1} = relative · p_i
  Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();     ///< where the registration started
  Matrix6d hessian = Matrix6d::Zero();  ///< the matcher's Hessian over ξ of `relative`; R = H⁻¹ (eq. 3.50)
  bool converged = false;
  int iterations = 0;
  double score = 0.0;
  std::size_t matched_points = 0;
  std::size_t reference_points = 0;  ///< points of the scan or local map registered against
  double seconds = 0.0;              ///< registration + reference model + sampling [s]
  std::string status;                ///< termination reason (registration_result.hpp)
  std::string fallback;              ///< empty, or what the matcher fell back to and why
  /// The assessment of the registration chained (after any recovery); trust kOk = believed.
  RegistrationQuality quality;
  /// How the step was recovered: "" (not needed, or recovery off), "wide_basin" (the first
  /// registration was not trusted; a wide-basin one is), "restart" (a matcher without a wide
  /// basin, registered again from another start, is), "least_suspect" (none is trusted, but one
  /// converged with enough overlap and every direction constrained and only its fit above the bar:
  /// of those with about the lowest fit, the one nearest the guess is chained (suspect_choice.hpp),
  /// the step stays untrusted), "guess" / "last_motion" (no such
  /// registration either: the odometry guess, or the last trusted motion of a constant-velocity run,
  /// is chained and the step stays untrusted).
  std::string recovery;
  Trust first_trust = Trust::kOk;  ///< the first registration's trust, before any recovery
  /// The first registration's own result, before any recovery: `relative` unless a recovery replaced
  /// it (a wide-basin answer, the least suspect one, the guess or the last trusted motion), which
  /// would otherwise lose what the scans said
  Eigen::Isometry3d first_relative = Eigen::Isometry3d::Identity();
  bool trusted() const { return quality.trusted(); }
  /// Trusted after the first registration was not: a wide-basin answer, or a restart
  bool recovered() const { return recovery == "wide_basin" || recovery == "restart"; }
};

struct OdometryResult {
  std::vector<Eigen::Isometry3d> poses;  ///< world ← scan first + i, i = 0 … count − 1
  SensorDetection sensor;                ///< the sensor the checks assumed, and what was measured
  std::optional<double> typical_step;    ///< the sequence's last typical step (MotionScale) [m]
  /// The size of a wrong step at the end of the run (platform_tolerance): what a step off the
  /// reference by more than this is
  QualitySettings tolerance;
  std::vector<OdometryStep> steps;  ///< count − 1 registrations; steps[i] links poses[i] and poses[i + 1]
  /// What reading each scan dropped (non-finite, no-return points), loads[i] of scan first + i
  std::vector<ScanLoadReport> loads;
  /// With deskew: the velocity scan first + i was deskewed by (unknown: kept as read, its points carry no
  /// time or no motion was known yet); empty with deskew off. registered_scan gives the scan as deskewed
  std::vector<SweepMotion> sweeps;
  std::size_t timed_scans = 0;  ///< scans whose points carry their own time
  /// Steps registered a second time, their scan deskewed by the velocity the step itself measured
  /// (without an odometry: chain_deskew.hpp)
  std::size_t registered_again = 0;
  std::size_t deskewed() const;  ///< scans deskewed by a known motion
  /// Over every scan: the points read, and those dropped
  ScanLoadReport dropped_total() const;
  std::size_t untrusted() const;  ///< steps whose chained motion is not trusted
  std::size_t recovered() const;  ///< steps recovered (wide basin, or restart)
};

/// Called after each finished registration with (done, total); never concurrently.
using OdometryProgress = std::function<void(std::size_t done, std::size_t total)>;

/// A scan where the chain placed it, for an observer that builds something of the run as it goes (the
/// run's map, run_map.hpp) without the run keeping any scan.
struct RegisteredScan {
  std::size_t index = 0;  ///< k: scan first + k of the dataset
  /// The whole scan as the chain read it (load_sequence_scan: in its sensor frame, without the points
  /// within min_range), not the common-view cut or the sample a registration used; valid during the call
  const PointCloud* scan = nullptr;
  /// world ← scan: equal to OdometryResult::poses[k], bit for bit
  Eigen::Isometry3d world_from_scan = Eigen::Isometry3d::Identity();
  /// The step that placed it (steps[k − 1]; null for scan `first`), its trust included; valid during
  /// the call
  const OdometryStep* step = nullptr;
};

/// Called once per scan, in the sequence's order, as soon as its pose is final; never concurrently.
/// It only reads: the run's results are the same with or without it.
using OdometryScanObserver = std::function<void(const RegisteredScan& scan)>;

/// Scan i of the dataset without the points closer than `min_range` to the sensor (as the chain
/// registers it); `report`, when given, gets what reading the file dropped.
PointCloud load_sequence_scan(const Dataset& dataset, std::size_t i, double min_range,
                              ScanLoadReport* report = nullptr);

/// Scan first + i as `result`'s run registered it and kept it in its map: load_sequence_scan, deskewed
/// by result.sweeps[i] when there is one.
PointCloud registered_scan(const Dataset& dataset, const OdometryResult& result, std::size_t first,
                           std::size_t i, double min_range);

/// Chains count − 1 registrations over scans first … first + count − 1. Throws InputError when the
/// range leaves the dataset, count < 1, the settings are invalid or the guess mode needs odometry the
/// dataset lacks (the message suggests constant_velocity). A registration that fails is kept as the
/// matcher returned it (converged = false, status says why) and the chain goes on. `observe`, when
/// given, sees every scan with its pose (OdometryScanObserver).
OdometryResult run_odometry(const Dataset& dataset, const OdometrySettings& settings, std::size_t first,
                            std::size_t count, const OdometryProgress& progress = {},
                            const OdometryScanObserver& observe = {});

/// "odometry" | "constant_velocity" | "identity"; InputError(`what`) naming the choices otherwise.
inline constexpr EnumNames<OdometryGuess, 3> kOdometryGuessNames{
    "guess mode",
    {{{OdometryGuess::odometry, "odometry"},
      {OdometryGuess::constant_velocity, "constant_velocity"},
      {OdometryGuess::identity, "identity"}}}};
bool from_string(const std::string& text, OdometryGuess* out);
std::string to_string(OdometryGuess guess);
/// "scan" | "local_map"; InputError(`what`) naming the choices otherwise.
inline constexpr EnumNames<OdometryMap, 2> kOdometryMapNames{
    "map mode", {{{OdometryMap::scan, "scan"}, {OdometryMap::local_map, "local_map"}}}};
bool from_string(const std::string& text, OdometryMap* out);
std::string to_string(OdometryMap map);

}  // namespace sextant
