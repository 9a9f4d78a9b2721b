// `simulation`: 2D simulations without a dataset; `params.model` picks the model
// (simulation/model.hpp), which validates, runs and lays out its report.
#include "simulation/model.hpp"

#include "kinds.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"

namespace sextant {
namespace {

std::unique_ptr<SimulationModel> model_of(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  std::string model;
  in.require("model", model);
  if (model == "room_2d") return make_room_2d_model();
  if (model == "range_bearing") return make_range_bearing_model();
  in.fail("model", "key 'model': '" + model + "' is not room_2d or range_bearing");
}

class SimulationSession : public KindSession {
 public:
  explicit SimulationSession(const ExperimentConfig& config) : config_(config), model_(model_of(config)) {}
  void run(const RunSpec& run, RunRow& row) const override { model_->run(config_, run, row); }

 private:
  ExperimentConfig config_;
  std::unique_ptr<SimulationModel> model_;
};

class SimulationKind : public RunKind {
 public:
  std::string name() const override { return "simulation"; }
  void validate(const ExperimentConfig& config) const override {
    if (config.dataset.source != DatasetSource::kNone)
      throw InputError(config.file, "", "key 'dataset': the simulation kind needs no dataset");
    model_of(config)->validate(config);
  }
  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return std::make_unique<SimulationSession>(config);
  }
  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    return model_of(config)->report(config, runs, rows);
  }
};

}  // namespace

std::unique_ptr<RunKind> make_simulation_kind() {
  return std::make_unique<SimulationKind>();
}

}  // namespace sextant
