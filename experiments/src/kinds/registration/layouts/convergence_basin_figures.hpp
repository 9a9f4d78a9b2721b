#pragma once
// E1's figures (§5.1.1.1): the clouds before/after alignment (figs 5.1/5.2, also as a 3D scene),
// the six parameters
// against iteration (5.3/5.5), the score against iteration (5.4), Newton vs LM (5.6), success maps
// over offset × yaw and basin radii per method and scene.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

/// Top-down view of the snapshot run's clouds: the reference, and the input mapped by `T`.
ReportFigure cloud_figure(const std::string& id, const std::string& caption, const std::string& title,
                          const RunRow& snapshot, const Eigen::Isometry3d& T);

/// The snapshot run's clouds in 3D: the reference, and the input placed in one state each by the
/// identity guess, by every named row's estimate and by the ground truth.
ReportScene cloud_scene(const std::string& id, const std::string& caption, const std::string& title,
                        const RunRow& snapshot,
                        const std::vector<std::pair<std::string, const RunRow*>>& after);

/// tx, ty, tz [m] (one figure) and α, β, γ [deg] (another) of every iterate, the truth dashed.
std::vector<ReportFigure> parameter_figures(const std::string& method, const std::string& figure,
                                            const RunRow& row);

/// One curve per named row: the raw score (per_layer = false) or the score normalised within each
/// ML-NDT layer (per_layer = true; a new line starts at each layer).
ReportFigure score_figure(const std::string& id, const std::string& caption, const std::string& title,
                          const std::vector<std::pair<std::string, const RunRow*>>& rows, bool per_layer);

/// Translation error [m] of every iterate, one curve per named row (log scale).
ReportFigure error_figure(const std::string& id, const std::string& caption, const std::string& title,
                          const std::vector<std::pair<std::string, const RunRow*>>& rows);

/// A heat map with ticks and annotated cells; NaN cells grey.
ReportFigure heatmap_figure(const std::string& id, const std::string& caption, const std::string& title,
                            const std::string& x_label, const std::string& y_label, const std::string& bar,
                            const std::vector<std::string>& x_ticks, const std::vector<std::string>& y_ticks,
                            const Eigen::MatrixXd& values, double max_value, int precision);

}  // namespace sextant
