// `simulation`: 2D simulations without a dataset; `params.model` picks the model's line in the
// table of simulation/layouts/layouts.cpp, which validates, runs and lays out its report.
#include <memory>
#include <string>
#include <vector>

#include "sextant/core/error.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "simulation/layouts/layouts.hpp"

namespace sextant {
namespace simulation_kind {

class SimulationSession : public KindSession {
 public:
  explicit SimulationSession(const ExperimentConfig& config)
      : config_(config), layout_(simulation_layout(config)) {}
  void run(const RunSpec& run, RunRow& row) const override { layout_.run(config_, run, row); }

 private:
  ExperimentConfig config_;
  const SimulationLayout& layout_;
};

class SimulationKind : public RunKind {
 public:
  std::string name() const override { return "simulation"; }
  void validate(const ExperimentConfig& config) const override {
    if (config.dataset.source != DatasetSource::kNone)
      throw InputError(config.file, "", "key 'dataset': the simulation kind needs no dataset");
    simulation_layout(config).validate(config);
  }
  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return std::make_unique<SimulationSession>(config);
  }
  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    return simulation_layout(config).report(config, runs, rows);
  }
};

}  // namespace simulation_kind

std::unique_ptr<RunKind> make_simulation_kind() {
  return std::make_unique<simulation_kind::SimulationKind>();
}

}  // namespace sextant
