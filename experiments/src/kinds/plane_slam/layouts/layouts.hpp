#pragma once
// The plane_slam kind's report layouts. A layout is one file in this folder plus one line in the
// table of layouts.cpp: its `report:` name, its report and the check of its `reference:` block.
#include <string>
#include <vector>

#include "plane_slam/report.hpp"

namespace sextant {

using PlaneSlamReport = ReportSection (*)(const ExperimentConfig& config, const PlaneSlamParams& params,
                                          const PlaneSlamRows& data);
/// Checks the layout's `reference:` block (InputError with file, line, key).
using PlaneSlamReferenceCheck = void (*)(const ExperimentConfig& config);

struct PlaneSlamLayout {
  const char* name = "";  ///< the value of `report:` (PlaneSlamParams::report)
  PlaneSlamReport report = nullptr;
  PlaneSlamReferenceCheck check_reference = nullptr;
};

/// The table, in the order the error message names them.
const std::vector<PlaneSlamLayout>& plane_slam_layouts();
/// The line of params.report; InputError at params.report's line for a name not in the table.
const PlaneSlamLayout& plane_slam_layout(const ExperimentConfig& config, const PlaneSlamParams& params);

}  // namespace sextant
