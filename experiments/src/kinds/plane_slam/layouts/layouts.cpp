// The table of the plane_slam kind's report layouts: `report:` name → report, reference check.
// Adding a layout: its file in this folder and one line here.
#include "plane_slam/layouts/layouts.hpp"

#include "sextant/core/settings_reader.hpp"

namespace sextant {

// Each layout's report (plane_slam/layouts/<layout>.cpp); the reference check all of them share is
// check_plane_slam_reference (plane_slam/claims.cpp).
ReportSection accuracy_report(const ExperimentConfig&, const PlaneSlamParams&, const PlaneSlamRows&);
ReportSection seif_report(const ExperimentConfig&, const PlaneSlamParams&, const PlaneSlamRows&);
ReportSection benchmark_report(const ExperimentConfig&, const PlaneSlamParams&, const PlaneSlamRows&);
ReportSection eseif_report(const ExperimentConfig&, const PlaneSlamParams&, const PlaneSlamRows&);
ReportSection hybrid_report(const ExperimentConfig&, const PlaneSlamParams&, const PlaneSlamRows&);
ReportSection fastslam_report(const ExperimentConfig&, const PlaneSlamParams&, const PlaneSlamRows&);

const std::vector<PlaneSlamLayout>& plane_slam_layouts() {
  // name, report, reference check
  static const std::vector<PlaneSlamLayout> table{
      {"accuracy", accuracy_report, check_plane_slam_reference},
      {"seif", seif_report, check_plane_slam_reference},
      {"benchmark", benchmark_report, check_plane_slam_reference},
      {"eseif", eseif_report, check_plane_slam_reference},
      {"hybrid", hybrid_report, check_plane_slam_reference},
      {"fastslam", fastslam_report, check_plane_slam_reference},
  };
  return table;
}

const PlaneSlamLayout& plane_slam_layout(const ExperimentConfig& config, const PlaneSlamParams& params) {
  std::string names;
  for (const PlaneSlamLayout& l : plane_slam_layouts()) {
    if (params.report == l.name) return l;
    names += (names.empty() ? "" : ", ") + std::string(l.name);
  }
  SettingsReader(config.params, config.file)
      .fail("report", "key 'report': '" + params.report + "' is not one of " + names);
}

}  // namespace sextant
