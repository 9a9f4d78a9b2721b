#pragma once
// PCL's matchers behind our Matcher interface, so every experiment can put them beside ours:
// `pcl_ndt` (NormalDistributionsTransform), `pcl_icp` (IterativeClosestPoint) and `pcl_gicp`
// (GeneralizedIterativeClosestPoint). No PCL type appears here (PCL stays at the edges).
//
// What PCL exposes fills the RegistrationResult: T, converged, iterations, time, and
// score = PCL's fitness (mean squared nearest-neighbour distance of the aligned input [m²]).
// H: pcl_ndt gives the negated Hessian of PCL's NDT score at the solution (Magnusson's
// parameters [t, Rx·Ry·Rz angles], the same as eq. 3.8); pcl_icp and pcl_gicp expose none, so
// H stays zero. There is no per-iteration trace from PCL (trace stays empty).
#include <memory>
#include <string>

#include "sextant/matchers/matcher.hpp"

namespace sextant {

struct PclNdtSettings {
  double resolution = 1.0;  ///< voxel edge [m] (PCL's default)
  double step_size = 0.1;   ///< More–Thuente maximum step length [m and rad combined]
  /// PCL's transformation epsilon: PCL 1.13 stops when the squared translation of the last step
  /// is ≤ ε [m²]. Its steps are at most step_size long, so the tutorial's ε = 0.01 with
  /// step_size 0.1 always stops after one iteration; 1e-4 (steps below 1 cm) does not.
  double epsilon = 1e-4;
  int max_iterations = 35;      ///< iteration cap (PCL's default)
  double outlier_ratio = 0.55;  ///< Magnusson's outlier mixture ratio (PCL's default)

  bool valid(std::string* why) const;
};

struct PclIcpSettings {
  double max_correspondence_distance = 1.0;  ///< pairs farther apart are rejected [m]
  int max_iterations = 50;                   ///< iteration cap
  double epsilon = 1e-8;                     ///< PCL's transformation epsilon [m²]
  double fitness_epsilon = 1e-6;             ///< stop when the mean squared error changes less [m²]

  bool valid(std::string* why) const;
};

struct PclGicpSettings {
  double max_correspondence_distance = 1.0;  ///< pairs farther apart are rejected [m]
  int max_iterations = 50;                   ///< outer iteration cap
  double epsilon = 1e-8;                     ///< PCL's transformation epsilon [m²]
  int correspondence_randomness = 20;        ///< k nearest points per local covariance
  int max_optimizer_iterations = 20;         ///< BFGS iterations per outer iteration

  bool valid(std::string* why) const;
};

/// Throw std::invalid_argument when the settings are not valid.
std::unique_ptr<Matcher> make_pcl_ndt(const PclNdtSettings& settings);
std::unique_ptr<Matcher> make_pcl_icp(const PclIcpSettings& settings);
std::unique_ptr<Matcher> make_pcl_gicp(const PclGicpSettings& settings);

}  // namespace sextant
