// The table of the registration kind's report layouts: `report:` name → report, reference check,
// the series the runs record. Adding a layout: its file in this folder and one line here.
#include "registration/layouts/layouts.hpp"

#include "kit/layout_table.hpp"
#include "registration/settings.hpp"

namespace sextant {

// Each layout's report and reference check, both in its file (registration/layouts/<layout>.cpp).
ReportSection accuracy_report(const ExperimentConfig&, const RegistrationParams&, const std::vector<RunSpec>&,
                              const std::vector<const RunRow*>&);
ReportSection basin_report(const ExperimentConfig&, const RegistrationParams&, const std::vector<RunSpec>&,
                           const std::vector<const RunRow*>&);
ReportSection init_layer_report(const ExperimentConfig&, const RegistrationParams&,
                                const std::vector<RunSpec>&, const std::vector<const RunRow*>&);
ReportSection sampling_report(const ExperimentConfig&, const RegistrationParams&, const std::vector<RunSpec>&,
                              const std::vector<const RunRow*>&);
ReportSection strategies_report(const ExperimentConfig&, const RegistrationParams&,
                                const std::vector<RunSpec>&, const std::vector<const RunRow*>&);
ReportSection zero_guess_report(const ExperimentConfig&, const RegistrationParams&,
                                const std::vector<RunSpec>&, const std::vector<const RunRow*>&);
void check_accuracy_reference(const ExperimentConfig&);
void check_basin_reference(const ExperimentConfig&);
void check_init_layer_reference(const ExperimentConfig&);
void check_sampling_reference(const ExperimentConfig&);
void check_strategies_reference(const ExperimentConfig&);
void check_zero_guess_reference(const ExperimentConfig&);

const std::vector<RegistrationLayout>& registration_layouts() {
  // name, report, reference check, trace_xi, adaptive_start
  static const std::vector<RegistrationLayout> table{
      {"accuracy", accuracy_report, check_accuracy_reference, false, false},
      {"basin", basin_report, check_basin_reference, false, false},
      {"init_layer", init_layer_report, check_init_layer_reference, false, true},
      {"sampling", sampling_report, check_sampling_reference, false, false},
      {"strategies", strategies_report, check_strategies_reference, false, false},
      {"zero_guess", zero_guess_report, check_zero_guess_reference, true, false},
  };
  return table;
}

const RegistrationLayout* find_registration_layout(const std::string& name) {
  return find_layout(registration_layouts(), name);
}

std::string registration_layout_names() {
  return layout_names(registration_layouts());
}

}  // namespace sextant
