// The table of the sequence kind's report layouts: `report:` name → report, reference check, what
// it needs of the run. Adding a layout: its file in this folder and one line here.
#include "sequence/layouts/layouts.hpp"

#include "kit/layout_table.hpp"
#include "sequence/settings.hpp"

namespace sextant {

// Each layout's report and reference check, both in its file (sequence/layouts/<layout>.cpp).
ReportSection dead_reckoning_report(const ExperimentConfig&, const SequenceParams&,
                                    const std::vector<RunSpec>&, const std::vector<const RunRow*>&);
ReportSection kalman_report(const ExperimentConfig&, const SequenceParams&, const std::vector<RunSpec>&,
                            const std::vector<const RunRow*>&);
void check_dead_reckoning_reference(const ExperimentConfig&);
void check_kalman_reference(const ExperimentConfig&);

const std::vector<SequenceLayout>& sequence_layouts() {
  // name, report, reference check, needs_kf, ellipses
  static const std::vector<SequenceLayout> table{
      {"dead_reckoning", dead_reckoning_report, check_dead_reckoning_reference, false, false},
      {"kalman", kalman_report, check_kalman_reference, true, true},
  };
  return table;
}

const SequenceLayout* find_sequence_layout(const std::string& name) {
  return find_layout(sequence_layouts(), name);
}

std::string sequence_layout_names() {
  return layout_names(sequence_layouts());
}

}  // namespace sextant
