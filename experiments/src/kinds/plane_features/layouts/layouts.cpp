// The table of the plane_features kind's studies: `study:` name → checks, session, report.
// Adding a study: its file and one line here.
#include "plane_features/layouts/layouts.hpp"

#include "kit/layout_table.hpp"

namespace sextant {

// Each study's checks, session and report (plane_features/<study>.cpp).
void validate_merging_study(const ExperimentConfig&);
std::unique_ptr<KindSession> prepare_merging_study(const ExperimentConfig&);
ReportSection merging_study_report(const ExperimentConfig&, const std::vector<RunSpec>&,
                                   const std::vector<const RunRow*>&);
void validate_extraction_study(const ExperimentConfig&);
std::unique_ptr<KindSession> prepare_extraction_study(const ExperimentConfig&);
ReportSection extraction_study_report(const ExperimentConfig&, const std::vector<RunSpec>&,
                                      const std::vector<const RunRow*>&);

const std::vector<PlaneFeaturesLayout>& plane_features_layouts() {
  // name, validate, prepare, report
  static const std::vector<PlaneFeaturesLayout> table{
      {"merging", validate_merging_study, prepare_merging_study, merging_study_report},
      {"extraction", validate_extraction_study, prepare_extraction_study, extraction_study_report},
  };
  return table;
}

const PlaneFeaturesLayout& plane_features_layout(const ExperimentConfig& config) {
  return layout_named_by(plane_features_layouts(), config, "study");
}

}  // namespace sextant
