#pragma once
// A view of a trajectory run as one offline HTML page (three.js, WebGL; like cloud_view's): the map
// (world-frame points, shaded by height), the estimated trajectory, the reference where there is
// one, and the steps along the estimate: those not trusted, those not converged and those recovered
// marked in their own colours. A click on a step, or on its entry in the list beside the view, shows
// its number, time, trust verdict and reason, and its error against the reference when known. The
// estimate can be coloured by that error; the camera orbits in 3D or looks straight down (top view).
//
//   RunView view;
//   view.title = "odometry: campus";
//   view.map = world_points;                 // world frame
//   view.estimate = result.poses;            // world ← sensor, one per pose
//   view.reference = truth;                  // the same poses' reference, or empty
//   view.steps.push_back({...});             // one record per step, drawn at estimate[step.pose]
//   write_run_view(view, "run.html");        // three.js inlined: one self-contained file
//
// Decimated to stay responsive for long runs: the map to max_map_points (evenly strided), each
// trajectory to the vertices that change its line by more than a tenth of a pixel at full view or
// its error colour by more than 2 % of the scale (Douglas–Peucker, every marked step kept). Every
// pose stays on the page, so that any step can be picked. three.js and its fat lines
// (examples/js/lines) come from Debian's libjs-three, inlined; nothing loads from the network.
#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/eval/cloud_view.hpp"

namespace sextant {

struct AssociatedPoses;
struct TrajectoryEvaluation;

/// Map points a run's page keeps by default: 150 000 (1.8 MB of float32 coordinates, ≈ 2.4 MB on the
/// page), the cloud view's per-cloud cap for the two or three clouds a pair shows.
constexpr std::size_t kRunViewMaxMapPoints = 150000;

/// What the page says of a step, and the colour of its marker.
enum class StepVerdict {
  trusted,        ///< trusted as the matcher returned it: not marked
  recovered,      ///< trusted after a recovery (the wide basin, or a restart)
  untrusted,      ///< not trusted (the chained motion is a suspect registration, the guess, …)
  not_converged,  ///< not trusted, and the registration did not converge
  unassessed,     ///< no trust is known (a trajectory from a file): not marked
};

/// "trusted", "recovered", "untrusted", "not converged", "no verdict".
std::string to_string(StepVerdict verdict);

/// One step (or pose) of the run.
struct RunViewStep {
  std::size_t number = 0;  ///< shown as "step N" (RunView::step_name)
  std::size_t pose = 0;    ///< the estimate's pose it is drawn at (an odometry step: the scan it registers)
  /// The scans it links (from → to), shown when from < to; 0, 0: none
  std::size_t from_scan = 0, to_scan = 0;
  double stamp = std::numeric_limits<double>::quiet_NaN();  ///< [s]; NaN: no clock
  bool assessed = true;  ///< false: no trust is known (the flags below mean nothing)
  bool trusted = true;
  bool recovered = false;  ///< trusted after a recovery
  bool converged = true;
  std::string trust;        ///< the verdict's name ("ok", "low_overlap", …)
  std::string first_trust;  ///< the first registration's, before any recovery
  std::string recovery;     ///< how it was recovered, or what was chained instead ("" none)
  std::string reason;       ///< why it is not trusted
  std::string status;       ///< the registration's termination
  double error_m = std::numeric_limits<double>::quiet_NaN();    ///< against the reference; NaN: none
  double error_deg = std::numeric_limits<double>::quiet_NaN();  ///< against the reference; NaN: none
};

/// The marker a step gets: unassessed, then not converged, untrusted, recovered, trusted.
StepVerdict verdict_of(const RunViewStep& step);

struct RunView {
  std::string title;
  std::string caption;                       ///< a line below the title (escaped)
  PointCloud map;                            ///< world frame; non-finite points are dropped
  std::vector<Eigen::Isometry3d> estimate;   ///< world ← sensor, per pose
  std::vector<Eigen::Isometry3d> reference;  ///< the same poses' reference, or empty
  std::string estimate_name = "estimate", reference_name = "reference";
  std::vector<RunViewStep> steps;
  std::string step_name = "step";  ///< what a record is called on the page ("step", "pose")
  /// What the steps' errors are, in the panel and on the colour scale
  std::string error_name = "error against the reference";
  bool colour_by_error = false;  ///< the estimate opens coloured by its error (a toggle either way)
  std::size_t max_map_points = kRunViewMaxMapPoints;
};

/// Indices of the vertices of `points` a drawn polyline keeps (ascending, first and last included):
/// the vertex farthest from the chord of the kept ones around it is kept while it lies more than
/// `tolerance` from it, or its value more than `value_tolerance` from the chord's (linear in the
/// vertex index; NaN is a value of its own, and the vertices on both sides of a change between NaN and
/// numbers are kept), and every vertex whose `keep` is true. Non-finite points are left out. `values`
/// and `keep` are empty or one per point.
std::vector<std::size_t> decimate_polyline(const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<double>& values, double tolerance,
                                           double value_tolerance, const std::vector<bool>& keep);

/// The page. Throws std::invalid_argument for an inconsistent view (a reference of another length, a
/// step's pose outside the estimate, max_map_points 0) and InputError naming the path and the package
/// libjs-three when three.js or its line scripts are missing from `three_js_dir`.
std::string render_run_view(const RunView& view, const std::filesystem::path& three_js_dir = kThreeJsDir);
/// Renders and writes atomically.
void write_run_view(const RunView& view, const std::filesystem::path& path,
                    const std::filesystem::path& three_js_dir = kThreeJsDir);
/// InputError (naming the file and libjs-three) unless every script a run's page inlines is there:
/// a command checks before a long run, not after it.
void check_run_view_scripts(const std::filesystem::path& three_js_dir = kThreeJsDir);

/// check_run_view_scripts, then InputError("--view") unless `path` names a file in a folder that
/// exists.
void check_run_view_path(const std::filesystem::path& path);

/// `sextant eval`'s view: the reference, the estimate as aligned for the ATE, and one record per pose
/// with its ATE error (translation and rotation); no trust. `timed`: the pairs' stamps are times
/// (TUM files), shown beside each pose; otherwise they are indices (KITTI files) and not shown.
RunView evaluation_run_view(const AssociatedPoses& pairs, const TrajectoryEvaluation& evaluation,
                            const std::string& title, bool timed);

}  // namespace sextant
