// `plane_features`: `params.study` picks the study's line in the table of
// plane_features/layouts/layouts.cpp, which validates, prepares the runs and lays out its report.
#include <memory>
#include <string>
#include <vector>

#include "plane_features/layouts/layouts.hpp"
#include "sextant/experiments/run_kind.hpp"

namespace sextant {
namespace plane_features_kind {

class PlaneFeaturesKind : public RunKind {
 public:
  std::string name() const override { return "plane_features"; }
  void validate(const ExperimentConfig& config) const override {
    plane_features_layout(config).validate(config);
  }
  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return plane_features_layout(config).prepare(config);
  }
  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    return plane_features_layout(config).report(config, runs, rows);
  }
};

}  // namespace plane_features_kind

std::unique_ptr<RunKind> make_plane_features_kind() {
  return std::make_unique<plane_features_kind::PlaneFeaturesKind>();
}

}  // namespace sextant
