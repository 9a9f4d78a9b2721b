// The view of an odometry run (odometry_view.hpp): one record per step, from the result and the
// per-step table's errors (steps_table.hpp: the same numbers as steps.csv).
#include "sextant/pipeline/odometry_view.hpp"

#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "sextant/pipeline/steps_table.hpp"

namespace sextant {
namespace {

const StepsColumn& column(const StepsTable& table, const std::string& name) {
  for (const StepsColumn& c : table.columns)
    if (c.name == name) return c;
  throw std::logic_error("steps table without the column " + name);
}

}  // namespace

RunView odometry_run_view(const Dataset& dataset, std::size_t first, const OdometryResult& result,
                          const std::vector<Eigen::Isometry3d>& poses,
                          const std::optional<std::vector<Eigen::Isometry3d>>& truth, const RunViewMap& map,
                          const std::string& title) {
  RunView view;
  view.title = title;
  view.map = map.points;
  view.estimate = poses;
  if (truth && truth->size() == poses.size()) view.reference = *truth;
  view.reference_name = "ground truth";
  view.error_name = "the step's motion against the ground truth's";
  const StepsTable table = steps_table(result, first, truth);
  const StepsColumn& error_m = column(table, "error_m");
  const StepsColumn& error_deg = column(table, "error_deg");
  for (std::size_t i = 0; i < result.steps.size() && i + 1 < poses.size(); ++i) {
    const OdometryStep& step = result.steps[i];
    RunViewStep s;
    s.number = i;
    s.pose = i + 1;
    s.from_scan = first + i;
    s.to_scan = first + i + 1;
    if (const auto stamp = dataset.stamp(first + i + 1)) s.stamp = *stamp;
    s.trusted = step.trusted();
    s.recovered = step.recovered();
    s.converged = step.converged;
    s.trust = to_string(step.quality.trust);
    s.first_trust = to_string(step.first_trust);
    s.recovery = step.recovery;
    s.reason = step.quality.reason;
    s.status = step.status;
    if (!error_m.missing) s.error_m = error_m.reals[i];
    if (!error_deg.missing) s.error_deg = error_deg.reals[i];
    view.steps.push_back(s);
  }
  std::ostringstream caption;
  caption << result.steps.size() << " steps: " << result.untrusted() << " not trusted, " << result.recovered()
          << " recovered. The map: " << map.scans_read << " of " << poses.size()
          << " scans placed by the trajectory, one point per " << std::setprecision(3) << map.voxel
          << " m voxel.";
  view.caption = caption.str();
  return view;
}

void write_odometry_view(const std::filesystem::path& path, const Dataset& dataset, std::size_t first,
                         const OdometryResult& result, const std::vector<Eigen::Isometry3d>& poses,
                         const std::optional<std::vector<Eigen::Isometry3d>>& truth, const RunMap& map,
                         const std::string& title) {
  check_run_view_scripts();
  write_run_view(odometry_run_view(dataset, first, result, poses, truth, run_view_map(map), title), path);
}

}  // namespace sextant
