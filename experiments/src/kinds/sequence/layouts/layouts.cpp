// The table of the sequence kind's report layouts: `report:` name → report, reference check, what
// it needs of the run. Adding a layout: its file in this folder and one line here.
#include "sequence/layouts/layouts.hpp"

#include "sequence/settings.hpp"

namespace sextant {

// Each layout's report (sequence/layouts/<layout>.cpp) and reference check (sequence/report.cpp).
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
  for (const SequenceLayout& l : sequence_layouts()) {
    if (name == l.name) return &l;
  }
  return nullptr;
}

std::string sequence_layout_names() {
  const auto& table = sequence_layouts();
  std::string out;
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (i > 0) out += i + 1 == table.size() ? " or " : ", ";
    out += table[i].name;
  }
  return out;
}

}  // namespace sextant
