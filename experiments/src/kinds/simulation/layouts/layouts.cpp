// The table of the simulation kind's models: `model:` name → checks, run, report.
// Adding a model: its file and one line here.
#include "simulation/layouts/layouts.hpp"

#include "kit/layout_table.hpp"

namespace sextant {

// Each model's checks, run and report (simulation/<model>.cpp).
void validate_room_2d(const ExperimentConfig&);
void run_room_2d(const ExperimentConfig&, const RunSpec&, RunRow&);
ReportSection room_2d_report(const ExperimentConfig&, const std::vector<RunSpec>&,
                             const std::vector<const RunRow*>&);
void validate_range_bearing(const ExperimentConfig&);
void run_range_bearing(const ExperimentConfig&, const RunSpec&, RunRow&);
ReportSection range_bearing_report(const ExperimentConfig&, const std::vector<RunSpec>&,
                                   const std::vector<const RunRow*>&);

const std::vector<SimulationLayout>& simulation_layouts() {
  // name, validate, run, report
  static const std::vector<SimulationLayout> table{
      {"room_2d", validate_room_2d, run_room_2d, room_2d_report},
      {"range_bearing", validate_range_bearing, run_range_bearing, range_bearing_report},
  };
  return table;
}

const SimulationLayout& simulation_layout(const ExperimentConfig& config) {
  return layout_named_by(simulation_layouts(), config, "model");
}

}  // namespace sextant
