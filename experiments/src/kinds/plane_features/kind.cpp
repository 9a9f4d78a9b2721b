// `plane_features`: `params.study` picks the study (plane_features/study.hpp), which
// validates, prepares the runs and lays out its report.
#include "plane_features/study.hpp"

#include "kinds.hpp"
#include "sextant/core/settings_reader.hpp"

namespace sextant {
namespace {

std::unique_ptr<PlaneFeaturesStudy> study_of(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  std::string study;
  in.require("study", study);
  if (study == "merging") return make_merging_study();
  if (study == "extraction") return make_extraction_study();
  in.fail("study", "key 'study': '" + study + "' is not merging or extraction");
}

class PlaneFeaturesKind : public RunKind {
 public:
  std::string name() const override { return "plane_features"; }
  void validate(const ExperimentConfig& config) const override { study_of(config)->validate(config); }
  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return study_of(config)->prepare(config);
  }
  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    return study_of(config)->report(config, runs, rows);
  }
};

}  // namespace

std::unique_ptr<RunKind> make_plane_features_kind() {
  return std::make_unique<PlaneFeaturesKind>();
}

}  // namespace sextant
