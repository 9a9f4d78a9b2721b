#pragma once
// The registration kind's report layouts. A layout is one file in this folder plus one line in
// the table of layouts.cpp: its `report:` name, its report, the check of its `reference:` block
// and the series its runs record beyond the common ones.
#include <string>
#include <vector>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

struct RegistrationParams;

using RegistrationReport = ReportSection (*)(const ExperimentConfig& config, const RegistrationParams& params,
                                             const std::vector<RunSpec>& runs,
                                             const std::vector<const RunRow*>& rows);
/// Checks the layout's `reference:` block (InputError with file, line, key).
using RegistrationReferenceCheck = void (*)(const ExperimentConfig& config);

struct RegistrationLayout {
  const char* name = "";  ///< the value of `report:`
  RegistrationReport report = nullptr;
  RegistrationReferenceCheck check_reference = nullptr;
  bool trace_xi = false;        ///< its runs record ξ after each iteration (series trace_xi)
  bool adaptive_start = false;  ///< it reports methods with `adaptive_start`
};

/// The table, in the order the error message names them.
const std::vector<RegistrationLayout>& registration_layouts();
/// nullptr for an unknown name.
const RegistrationLayout* find_registration_layout(const std::string& name);
/// "accuracy, basin, … or zero_guess": the names for an error message.
std::string registration_layout_names();

}  // namespace sextant
