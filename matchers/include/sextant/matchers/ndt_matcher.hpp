#pragma once
// Classic 3D P2D-NDT (eqs. 3.1–3.6): one fixed grid, Magnusson's Gaussian score with the
// outlier-mixture constants, Newton with a backtracking line search; optional trilinear
// interpolation over the 8 neighbouring cells. YAML keys: cell_size, volume_divisions,
// outlier_ratio, trilinear, max_iterations, epsilon, step_control (line_search by default; none = the plain
// Newton step; more_thuente = Magnusson's Moré–Thuente line search, with line_search_mu, line_search_eta,
// line_search_max_step, line_search_iterations), min_points, max_eigen_ratio, dof, threads.
#include <memory>
#include <string>

#include "sextant/core/units.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/ndt_grid.hpp"
#include "sextant/matchers/optimizer_settings.hpp"

namespace sextant {

/// The largest cell edge `ndt` accepts [m] (1e30 used to "converge" 140 m / 157° off).
inline constexpr double kMaxNdtCellSize = kMaxSettingLength;

struct NdtSettings {
  double cell_size = 0.0;       ///< cell edge [m, ≤ kMaxNdtCellSize]; 0 → from volume_divisions
  int volume_divisions = 64;    ///< cell volume = bounding volume / this (64 = ML-NDT layer 2) [count]
  double outlier_ratio = 0.55;  ///< Magnusson's p_outlier in (0, 1)
  bool trilinear = false;       ///< score against the 8 surrounding cells
  /// Threads of each score evaluation: 1 runs on the calling thread, 0 uses all hardware
  /// threads; bit-identical results for every value (fixed blocks, ndt_score.hpp) [count, ≥ 0]
  int threads = 1;
  CellStatsSettings cells;
  OptimizerSettings optimizer;  ///< Newton with line search, cap 35, ε = 1e-4
  NdtSettings();
  bool valid(std::string* why) const;
};

class NdtMatcher final : public Matcher {
 public:
  explicit NdtMatcher(NdtSettings settings = {});
  std::string name() const override { return "ndt"; }
  void set_reference(const PointCloud& reference) override;
  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override;

  const NdtGrid& grid() const { return grid_; }

 private:
  NdtSettings settings_;
  NdtGrid grid_;
  std::size_t reference_points_ = 0;
  double cell_edge_ = 0.0;  ///< of grid_ [m]
};

}  // namespace sextant
