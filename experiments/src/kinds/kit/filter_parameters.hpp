#pragma once
// Every filter's sigma-point rule and parameters as a report table (issue 25). The thesis never
// prints its UKF's α, β, κ; the sections that compare filters say which
// ones ran, from Filter::approximation() of the filter each method builds.
#include <memory>
#include <string>
#include <vector>

#include "sextant/eval/table.hpp"
#include "sextant/filters/filter_spec.hpp"
#include "sextant/filters/slam_model.hpp"

namespace sextant {

/// One method: its label and its filter.
struct FilterMethodSettings {
  std::string method;
  FilterSpec filter;
};

/// Table "sigma_points": method | filter | sigma points and parameters, one row per method, each
/// filter built (not run) on `model`.
Table sigma_point_table(const std::vector<FilterMethodSettings>& methods,
                        const std::shared_ptr<const SlamModel>& model);

/// True when some method is a sigma-point filter (ukf, ckf, rspkf): only then is the table shown.
bool has_sigma_point_filter(const std::vector<FilterMethodSettings>& methods);

}  // namespace sextant
