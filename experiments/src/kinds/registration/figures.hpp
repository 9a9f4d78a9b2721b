#pragma once
// Figures shared by the registration layouts: the per-parameter error of every pair against the
// scan index (figs 5.7–5.9, 5.11, 5.13) and the mean error per parameter of several methods
// (figs 5.10, 5.14, grouped bar charts: one group per parameter, one bar per method).
#include <array>
#include <string>
#include <vector>

#include "sextant/eval/registration_metrics.hpp"
#include "sextant/experiments/report_model.hpp"

namespace sextant {

/// Errors of tx, ty, tz [cm] (translation) or α, β, γ [deg] against `scan`; `limit` > 0 draws
/// dashed lines at ±limit (the 50 cm success line).
ReportFigure parameter_error_figure(const std::string& id, const std::string& caption,
                                    const std::string& title, const std::vector<double>& scan,
                                    const std::vector<RegistrationError>& errors, bool translation,
                                    double limit);

/// Mean error per parameter (3 translation or 3 rotation parameters) of each named series.
ReportFigure mean_error_figure(const std::string& id, const std::string& caption, const std::string& title,
                               const std::vector<std::string>& names,
                               const std::vector<std::array<double, 6>>& means, bool translation);

/// Fig. 5.10's legend entry: "name (success r %, k/n pairs)" for a method averaged over the pairs
/// it solved (solved_only), or "name (all n pairs; r % within the criterion)" for the odometry,
/// averaged over every pair; so the figure itself says how many pairs each bar stands for.
std::string fig_5_10_legend(const std::string& name, const RegistrationStats& stats, bool solved_only);

/// Mean of each parameter over the errors (NaN-free entries only).
std::array<double, 6> mean_parameters(const std::vector<RegistrationError>& errors);

}  // namespace sextant
