#pragma once
// E6's measured causes (issue 66; docs/experiments.md, E6): why FBS's claims do not hold on these scans,
// from the run's own rows, as the lines `cause: …` under the claims (Claim::cause).
#include <string>
#include <vector>

#include "kit/row_groups.hpp"
#include "sextant/eval/registration_metrics.hpp"

namespace sextant {

/// FBS is not faster: how much of the scan each sample keeps (table 5.9: 3.19 % of the scan matched by
/// FBS), and the matching time per point kept, FBS's over GBS's. Empty without both samplers' rows.
std::string sample_size_cause(const MethodRows* fbs, const MethodRows* gbs);

/// FBS's mean error is not within the band: the translation parameter of FBS's largest median error, and
/// every method's median there. `errors[m]` are method m's registration errors, `names[m]` its name.
std::string sample_bias_cause(const std::vector<std::string>& names,
                              const std::vector<std::vector<RegistrationError>>& errors, std::size_t fbs);

/// FbML-NDT's errors are not Gaussian: every method's Jarque–Bera statistic on the parameter where FBS's
/// is largest (the 5 % critical value of χ²₂: 5.99).
std::string heavy_tail_cause(const std::vector<std::string>& names,
                             const std::vector<std::vector<RegistrationError>>& errors, std::size_t fbs);

}  // namespace sextant
