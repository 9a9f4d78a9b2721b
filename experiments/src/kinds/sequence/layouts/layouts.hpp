#pragma once
// The sequence kind's report layouts. A layout is one file in this folder plus one line in the
// table of layouts.cpp: its `report:` name, its report, the check of its `reference:` block and
// what it needs of the run (the KF's covariances, the ellipses it draws).
#include <string>
#include <vector>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

struct SequenceParams;

using SequenceReport = ReportSection (*)(const ExperimentConfig& config, const SequenceParams& params,
                                         const std::vector<RunSpec>& runs,
                                         const std::vector<const RunRow*>& rows);
/// Checks the layout's `reference:` block (InputError with file, line, key).
using SequenceReferenceCheck = void (*)(const ExperimentConfig& config);

struct SequenceLayout {
  const char* name = "";  ///< the value of `report:`
  SequenceReport report = nullptr;
  SequenceReferenceCheck check_reference = nullptr;
  bool needs_kf = false;  ///< it reports the KF's alarms and covariances (filter: kf)
  bool ellipses = false;  ///< it draws covariance ellipses (params ellipses_at is checked)
};

/// The table, in the order the error message names them.
const std::vector<SequenceLayout>& sequence_layouts();
/// nullptr for an unknown name.
const SequenceLayout* find_sequence_layout(const std::string& name);
/// "dead_reckoning or kalman": the names for an error message.
std::string sequence_layout_names();

}  // namespace sextant
