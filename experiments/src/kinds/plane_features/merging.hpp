#pragma once
// E10's shared pieces (plane_features/merging.cpp runs and reports; the figures 4.1 and 4.2 are
// in plane_features/merging_figures.cpp): the study's params and the planes of §4.1's two cases.
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "sextant/experiments/report_model.hpp"
#include "sextant/features/landmark.hpp"
#include "sextant/features/merging.hpp"

namespace sextant {

struct Grid {
  double from = 0, to = 0, step = 1;
};

struct MergingParams {
  double noise_variance = 0.2;
  std::vector<std::pair<Grid, Grid>> planes;  ///< (x, z) grids of planes 1, 2, 3
  double case2_shift = 5.0;
  MergeThresholds thresholds;
};

/// Planes 1–3 of case `which` (1 or 2; case 2 shifts planes 2 and 3 along y, fig. 4.2) from Rng(seed):
/// the fitted landmarks and each plane's generated points.
struct MergingCase {
  std::vector<PlaneLandmark> planes;
  std::vector<std::vector<Eigen::Vector3f>> points;
};
MergingCase make_case(const MergingParams& p, int which, std::uint64_t seed);

/// Fig. 4.1 (the merging problem, case 1 face-on) and fig. 4.2 (the points of case `which` from above).
ReportFigure merging_problem_figure(const MergingParams& p, std::uint64_t seed);
ReportFigure planes_figure(const MergingParams& p, int which, std::uint64_t seed);

}  // namespace sextant
