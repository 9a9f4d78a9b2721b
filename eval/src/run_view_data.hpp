#pragma once
// Private helper of the eval module: what a run's page holds (run_view.hpp), before it is written: the
// map kept, the framing, the decimated lines, the verdict counts, and the page's JSON block.
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sextant/eval/run_view.hpp"

namespace sextant::detail {

struct RunPage {
  std::vector<Eigen::Vector3f> map;        ///< the finite map points kept (at most max_map_points)
  std::size_t finite_map_points = 0;       ///< of how many finite ones
  std::vector<Eigen::Vector3d> estimate;   ///< every pose's position
  std::vector<std::size_t> line;           ///< the estimate's vertices drawn (decimate_polyline)
  std::vector<Eigen::Vector3d> reference;  ///< the reference's vertices drawn; empty: none
  bool has_reference = false;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< the scene's centre: coordinates are relative to it
  double radius = 1.0;                               ///< its half diagonal
  double error_scale = 0.0;                          ///< the top of the error colours (0: no errors)
  std::array<std::size_t, 5> verdicts{};             ///< steps per StepVerdict
  bool assessed() const;                             ///< any step has a verdict
};

/// Validates `view` (std::invalid_argument) and prepares its page.
RunPage run_page(const RunView& view);
/// The page's <script type="application/json"> block.
std::string run_page_json(const RunView& view, const RunPage& page);

}  // namespace sextant::detail
