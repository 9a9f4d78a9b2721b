// `pose_graph` (thesis §7.2 future work: globally consistent n-scan registration after Lu and
// Milios): one run = one method over the first scans of the synthetic campus at one repetition —
// the scan-matching odometry with its pose graph and loop closures, or a plane-SLAM filter for
// comparison (pose_graph/pipeline.hpp). The report is pose_graph/report.cpp.
#include <cmath>
#include <memory>

#include "kit/campus.hpp"
#include "pose_graph/params.hpp"
#include "pose_graph/pipeline.hpp"
#include "pose_graph/report.hpp"
#include "sextant/core/error.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/yaml.hpp"

namespace sextant {
namespace {

constexpr char kKind[] = "pose_graph";

class PoseGraphSession : public KindSession {
 public:
  PoseGraphSession(const ExperimentConfig& config, PoseGraphParams params,
                   std::vector<PoseGraphMethod> methods)
      : file_(config.file),
        params_(std::move(params)),
        methods_(std::move(methods)),
        campus_(open_campus(config, kKind)),
        data_(campus_, params_.scans ? params_.scans : campus_.size(),
              params_.filters.landmarks == LandmarkSource::kTrue) {}

  void run(const RunSpec& run, RunRow& row) const override {
    const PoseGraphMethod& method = methods_.at(run.method_index);
    if (method.is_filter)
      run_filter_method(data_, params_, method.filter, run.seed, file_, row);
    else
      run_pose_graph_method(data_, params_, method.odometry, method.closure, run.seed, row);
  }

 private:
  std::string file_;
  PoseGraphParams params_;
  std::vector<PoseGraphMethod> methods_;
  synth::Campus campus_;
  PreloadedCampus data_;
};

class PoseGraphKind : public RunKind {
 public:
  std::string name() const override { return kKind; }

  void validate(const ExperimentConfig& config) const override {
    const PoseGraphParams params = read_pose_graph_params(config);
    std::size_t odometry_methods = 0;
    for (const PoseGraphMethod& m : read_pose_graph_methods(config)) {
      if (m.is_filter)
        (void)plane_slam_settings(params.filters, m.filter, NAN, config.file);
      else
        ++odometry_methods;
    }
    if (odometry_methods != 1)
      throw InputError(config.file, "",
                       "key 'methods': the pose_graph kind needs exactly one method with a matcher "
                       "(the odometry the graph is built on); the others are filters");
    if (!config.sweep.empty())
      throw InputError(config.file, "",
                       "key 'sweep': the pose_graph kind has no sweep axes (use repetitions)");
    std::uint64_t seed = 0;
    const synth::CampusSettings campus = campus_settings(config, kKind, &seed);
    if (params.scans > static_cast<std::size_t>(campus.trajectory.scans))
      throw InputError(config.file, "", "key 'scans': more than the campus' trajectory.scans");
    if (params.scans == 1) throw InputError(config.file, "", "key 'scans': a sequence needs ≥ 2 scans");
  }

  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return std::make_unique<PoseGraphSession>(config, read_pose_graph_params(config),
                                              read_pose_graph_methods(config));
  }

  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    return pose_graph_report(config, read_pose_graph_params(config), read_pose_graph_methods(config), runs,
                             rows);
  }
};

}  // namespace

std::unique_ptr<RunKind> make_pose_graph_kind() {
  return std::make_unique<PoseGraphKind>();
}

}  // namespace sextant
