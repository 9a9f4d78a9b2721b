#include "sextant/posegraph/variance_components.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include "sextant/posegraph/relative_pose_factor.hpp"

namespace sextant {
namespace variance_components_detail {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d S;
  S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return S;
}

/// Ω⁻¹ of a symmetric positive-definite Ω; false when it is not.
bool covariance_of(const Matrix6d& information, Matrix6d* covariance) {
  const Matrix6d sym = 0.5 * (information + information.transpose());
  const Eigen::LLT<Matrix6d> llt(sym);
  if (llt.info() != Eigen::Success || !sym.allFinite()) return false;
  *covariance = llt.solve(Matrix6d::Identity());
  *covariance = 0.5 * (*covariance + covariance->transpose());
  return true;
}

}  // namespace variance_components_detail

PoseGraph with_information_scaled(const PoseGraph& g, double odometry_variance, double closure_variance,
                                  const std::vector<Eigen::Isometry3d>& start) {
  PoseGraph out;
  for (const Eigen::Isometry3d& T : start.size() == g.size() ? start : g.poses()) out.add_node(T);
  for (const PoseGraphEdge& e : g.edges())
    out.add_edge(
        e.i, e.j, e.measured,
        Matrix6d(e.information / (e.kind == EdgeKind::odometry ? odometry_variance : closure_variance)),
        e.kind);
  return out;
}

Matrix6d pose_adjoint(const Eigen::Isometry3d& T) {
  const Eigen::Matrix3d R = T.rotation();
  Matrix6d A = Matrix6d::Zero();
  A.topLeftCorner<3, 3>() = R;
  A.topRightCorner<3, 3>() = variance_components_detail::skew(T.translation()) * R;
  A.bottomRightCorner<3, 3>() = R;
  return A;
}

bool group_redundancies(const PoseGraph& g, double* odometry_redundancy, double* closure_redundancy,
                        std::string* why) {
  using variance_components_detail::covariance_of;
  const auto fail = [&](const std::string& text) {
    if (why) *why = text;
    return false;
  };
  const std::size_t n = g.size();
  if (n < 2) return fail("fewer than two nodes");
  // The chain: one odometry edge k → k+1 for every k, its covariance in the world frame (the
  // perturbation of node k+1 moves every later node rigidly), accumulated as prefix sums S.
  std::vector<Matrix6d> step(n - 1, Matrix6d::Zero());
  std::vector<bool> seen(n - 1, false);
  struct Closure {
    std::size_t lo, hi;
    double sign;
    Matrix6d to_frame, covariance;  // Ad(T_j⁻¹), Ω⁻¹
  };
  std::vector<Closure> closures;
  for (const PoseGraphEdge& e : g.edges()) {
    Matrix6d covariance;
    if (!covariance_of(e.information, &covariance))
      return fail("an information matrix is not positive definite");
    if (e.kind == EdgeKind::odometry) {
      if (e.j != e.i + 1 || e.j >= n || seen[e.i])
        return fail("the odometry edges are not one chain k → k+1");
      seen[e.i] = true;
      const Matrix6d A = pose_adjoint(g.poses()[e.j]);
      step[e.i] = A * covariance * A.transpose();
    } else {
      if (e.i == e.j || e.i >= n || e.j >= n) return fail("a closure joins a node to itself or to no node");
      closures.push_back({std::min(e.i, e.j), std::max(e.i, e.j), e.j > e.i ? 1.0 : -1.0,
                          pose_adjoint(g.poses()[e.j].inverse()), covariance});
    }
  }
  if (std::find(seen.begin(), seen.end(), false) != seen.end()) return fail("the odometry chain has a gap");
  if (closures.empty()) return fail("no closures: nothing is redundant");
  std::vector<Matrix6d> S(n, Matrix6d::Zero());
  for (std::size_t k = 0; k + 1 < n; ++k) S[k + 1] = S[k] + step[k];

  // The misclosures' covariance, one 6 × 6 block per pair of closures (their shared chain).
  const Eigen::Index m = 6 * static_cast<Eigen::Index>(closures.size());
  Eigen::MatrixXd Q_o = Eigen::MatrixXd::Zero(m, m), Q_c = Eigen::MatrixXd::Zero(m, m);
  for (std::size_t c = 0; c < closures.size(); ++c) {
    const Closure& a = closures[c];
    Q_c.block<6, 6>(6 * Eigen::Index(c), 6 * Eigen::Index(c)) = a.covariance;
    for (std::size_t d = c; d < closures.size(); ++d) {
      const Closure& b = closures[d];
      const std::size_t lo = std::max(a.lo, b.lo), hi = std::min(a.hi, b.hi);
      if (lo >= hi) continue;
      const Matrix6d block = a.sign * b.sign * a.to_frame * (S[hi] - S[lo]) * b.to_frame.transpose();
      Q_o.block<6, 6>(6 * Eigen::Index(c), 6 * Eigen::Index(d)) = block;
      Q_o.block<6, 6>(6 * Eigen::Index(d), 6 * Eigen::Index(c)) = block.transpose();
    }
  }
  const Eigen::LDLT<Eigen::MatrixXd> Sigma_w(Q_o + Q_c);
  if (Sigma_w.info() != Eigen::Success) return fail("the misclosures' covariance cannot be factored");
  // r_g = tr(Σ_w⁻¹ Q_g) with the weights as they stand (the factors are in Q_g already). The two sum
  // to tr(Σ_w⁻¹ (Q_o + Q_c)) = tr(I) = m, the number of condition equations: one solve, not two.
  *closure_redundancy = Sigma_w.solve(Q_c).trace();
  *odometry_redundancy = static_cast<double>(m) - *closure_redundancy;
  if (!std::isfinite(*odometry_redundancy) || !std::isfinite(*closure_redundancy))
    return fail("the redundancies are not finite");
  return true;
}

VarianceComponents estimate_variance_components(const PoseGraph& g, const PoseGraphSettings& settings,
                                                const VarianceComponentSettings& vce) {
  VarianceComponents out;
  PoseGraphSettings plain = settings;
  plain.loss = RobustLoss::none;
  plain.robust_odometry = false;
  std::vector<Eigen::Isometry3d> start = g.poses();
  for (out.iterations = 0; out.iterations < vce.max_iterations; ++out.iterations) {
    PoseGraph probe = with_information_scaled(g, out.odometry, out.closures, start);
    const PoseGraphReport solved = probe.optimize(plain);
    if (!solved.ok) {
      out.message = "solve: " + solved.message;
      return out;
    }
    start = probe.poses();
    // v_gᵀ W_g v_g: each edge's error at the solution, weighted by its current information.
    double square[2] = {0.0, 0.0};
    for (const PoseGraphEdge& e : probe.edges()) {
      const Vector6d v = relative_pose_error(e.measured, start[e.i], start[e.j]);
      square[e.kind == EdgeKind::odometry ? 0 : 1] += v.dot(e.information * v);
    }
    double r_o = 0.0, r_c = 0.0;
    if (!group_redundancies(probe, &r_o, &r_c, &out.message)) return out;
    out.odometry_square_sum = square[0];
    out.closure_square_sum = square[1];
    out.odometry_redundancy = r_o;
    out.closure_redundancy = r_c;
    out.ok = true;
    // σ²_g ← σ²_g · v_gᵀW_g v_g / r_g (Förstner 1979); a group without redundancy keeps its factor.
    const auto update = [&](double factor, double sum, double r) {
      if (!(r > 1e-9)) return factor;
      return std::clamp(factor * sum / r, vce.min_factor, vce.max_factor);
    };
    const double odometry = update(out.odometry, square[0], r_o);
    const double closures = vce.estimate_closures ? update(out.closures, square[1], r_c) : out.closures;
    const double change =
        std::max(std::abs(odometry / out.odometry - 1.0), std::abs(closures / out.closures - 1.0));
    out.odometry = odometry;
    out.closures = closures;
    if (change < vce.tolerance) {
      out.converged = true;
      ++out.iterations;
      break;
    }
  }
  out.message =
      out.converged ? "converged" : "not converged in " + std::to_string(vce.max_iterations) + " iterations";
  return out;
}

}  // namespace sextant
