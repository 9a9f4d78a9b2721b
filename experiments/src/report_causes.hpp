#pragma once
// Every claim and sanity check that does not hold, beside its cause (issue 66): the report's causes.md and
// the sentence on its front page that counts how many carry one. A cause is measured by the experiment's
// own run (Claim::cause); one without a cause is listed as such, not left out.
#include <string>
#include <vector>

#include "report_overview.hpp"

namespace sextant {

/// "Of the 3 claims and checks that do not hold, 1 carries a measured cause" (no full stop); empty when
/// every one holds or is undecided.
std::string causes_sentence(const std::vector<OverviewEntry>& entries);

/// The table of causes.md: experiment, claim or check, the claim, its cause ("none measured yet" without).
std::string causes_markdown(const std::vector<OverviewEntry>& entries);

}  // namespace sextant
