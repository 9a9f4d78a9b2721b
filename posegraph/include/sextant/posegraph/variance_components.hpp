#pragma once
// Variance component estimation for a pose graph's edge groups (Helmert; Förstner 1979, "Ein
// Verfahren zur Schätzung von Varianz- und Kovarianzkomponenten"; Koch, "Parameter Estimation and
// Hypothesis Testing in Linear Models", §3.6). The stated information of each group g (odometry,
// loop closures) is trusted up to an unknown variance factor σ²_g: Σ_g,true = σ²_g · Ω_g⁻¹. With
// the graph solved under the current factors (no robust loss), each group's weighted residual
// square sum and redundancy give the update
//
//   σ²_g ← σ²_g · (v_gᵀ W_g v_g) / r_g,     W_g = Ω_g / σ²_g,   r_g = tr(W_g Σ_v̂,g),   Σ_g r_g = n − u
//
// iterated to the fixed point (the REML estimate). v_g are the edges' errors e = [t(E); log R(E)]
// at the solution (relative_pose_factor.hpp). The redundancies come from the condition form of the
// same adjustment (Förstner's eq. for r_g = tr(Σ_w⁻¹ B_g Σ_g B_gᵀ)): for an odometry chain (edge k
// joins nodes k and k+1) plus C closures, the misclosures w (6C) have the covariance
//
//   Σ_w = σ²_o Q_o + σ²_c Q_c,   Q_c = blockdiag(Ω_c⁻¹),
//   Q_o[c,d] = ±Ad(T_jc⁻¹) · Σ_{k ∈ path_c ∩ path_d} Ad(T_k+1) Ω_k⁻¹ Ad(T_k+1)ᵀ · Ad(T_jd⁻¹)ᵀ
//
// (the chain's covariance accumulated in the world frame, from prefix sums: O(N + C²)), and
// r_g = σ²_g tr(Σ_w⁻¹ Q_g); r_o + r_c = 6C. A group whose factor is not estimated keeps 1.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/pose.hpp"
#include "sextant/posegraph/pose_graph.hpp"

namespace sextant {

struct VarianceComponentSettings {
  int max_iterations = 200;       ///< the fixed point converges slowly when a group has little redundancy
  double tolerance = 1e-3;        ///< stop when every factor changes by less than this, relatively
  bool estimate_closures = true;  ///< false: the closures' stated information is taken as it is
  double min_factor = 1e-6, max_factor = 1e12;  ///< the factors are kept inside
};

struct VarianceComponents {
  bool ok = false;  ///< false: no closure, odometry edges not a chain k → k+1, or a solve failed
  std::string message;
  double odometry = 1.0, closures = 1.0;  ///< σ²_o, σ²_c (multiply the stated covariances)
  double odometry_redundancy = 0.0, closure_redundancy = 0.0;  ///< r_o, r_c at the end
  double odometry_square_sum = 0.0, closure_square_sum = 0.0;  ///< v_gᵀ W_g v_g at the end
  int iterations = 0;
  bool converged = false;
};

/// `g` with each odometry Ω divided by `odometry_variance` and each closure Ω by
/// `closure_variance`, starting from `start` (its own poses when `start` has another size).
PoseGraph with_information_scaled(const PoseGraph& g, double odometry_variance, double closure_variance,
                                  const std::vector<Eigen::Isometry3d>& start = {});

/// The adjoint of T = (R, t) in the error's [t; rotation] order, [[R, [t]×R], [0, R]]: a
/// perturbation ξ in T's own frame (T·D) is the world-frame perturbation Ad(T)·ξ (D'·T).
Matrix6d pose_adjoint(const Eigen::Isometry3d& T);

/// The redundancy of each group, r_o and r_c, with the graph's poses taken as the adjusted ones and
/// its information as the weights; r_o + r_c = 6·closures. False (with the reason) when the
/// odometry edges are not one chain k → k+1 over all nodes or an information is not invertible.
bool group_redundancies(const PoseGraph& g, double* odometry_redundancy, double* closure_redundancy,
                        std::string* why);

/// σ²_o and σ²_c by iterated variance component estimation; `settings.loss` is not used (every
/// solve is plain least squares). The graph is not changed.
VarianceComponents estimate_variance_components(const PoseGraph& g, const PoseGraphSettings& settings,
                                                const VarianceComponentSettings& vce = {});

}  // namespace sextant
