#pragma once
// E11's params and report layout (plane_features/extraction.cpp runs; the layout of table 5.10
// is in plane_features/extraction_report.cpp, figs 5.21–5.25 in plane_features/extraction_figures.cpp).
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/features/association.hpp"
#include "sextant/features/extraction.hpp"

namespace sextant {

struct ExtractionStudyParams {
  PlaneExtractionSettings extraction;
  AssociationSettings association;
  std::size_t turn_scan = 3;                    ///< the pair turn_scan → turn_scan + 1 holds the sharp turn
  std::vector<std::size_t> figure_scans{0, 1};  ///< scans whose merged features are drawn
  std::size_t first_scans = 5;                  ///< scans listed in the extraction table
  std::size_t min_visible_points = 300;         ///< recall counts true planes with this many points
  double normal_tolerance_deg = 3.0;            ///< a detected plane matches its true plane within ...
  double distance_tolerance = 0.05;             ///< ... these tolerances [deg, m]
};

/// Reads and checks `params` (InputError with file, line, key).
ExtractionStudyParams read_extraction_study_params(const ExperimentConfig& config);

/// The three poses the association of scan i + 1 into scan i is tried with.
inline const std::vector<std::string>& association_poses() {
  static const std::vector<std::string> poses{"none", "odometry", "truth"};
  return poses;
}

/// Appends the convex hulls of `landmarks` moved by T to series name_x, name_y (NaN between hulls).
void store_hulls(const std::vector<PlaneLandmark>& landmarks, const Eigen::Isometry3d& T,
                 const std::string& name, RunRow& row);

/// Figs 5.21–5.25 in the thesis' order from the outlines the runs stored (figures without data are left out).
std::vector<ReportFigure> extraction_figures(const ExtractionStudyParams& params,
                                             const std::map<std::size_t, const RunRow*>& by_scan);

ReportSection extraction_report(const ExperimentConfig& config, const ExtractionStudyParams& params,
                                const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows);

}  // namespace sextant
