#include "optim/ceres_stage.hpp"

#include <ceres/ceres.h>

#include <cmath>
#include <vector>

namespace sextant {

namespace {

/// All points in one cost function: 3 residuals per point, zero for points without a cell.
class MahalanobisCost final : public ceres::CostFunction {
 public:
  MahalanobisCost(const NdtGrid& grid, const PointCloud& input, double unmatched_penalty, double max_distance)
      : grid_(grid),
        input_(input),
        unmatched_residual_(std::sqrt(unmatched_penalty)),
        max_distance_(max_distance),
        truncated_residual_(std::sqrt(max_distance)) {
    sqrt_information_.reserve(grid.gaussian_count());
    for (std::size_t g = 0; g < grid.gaussian_count(); ++g)
      sqrt_information_.push_back(grid.sqrt_information(static_cast<int>(g)));
    set_num_residuals(static_cast<int>(3 * input.size()));
    mutable_parameter_block_sizes()->push_back(6);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Map<const Vector6d> xi(parameters[0]);
    const Eigen::Matrix3d R = rotation_from_euler(xi(3), xi(4), xi(5));  // eq. (3.8)
    const Eigen::Matrix3d Rx = Eigen::AngleAxisd(xi(3), Eigen::Vector3d::UnitX()).toRotationMatrix();
    const Eigen::Matrix3d Ry = Eigen::AngleAxisd(xi(4), Eigen::Vector3d::UnitY()).toRotationMatrix();
    Eigen::Matrix3d A;  // ∂(R·x)/∂(α, β, γ) = a × u with u = R·x (see ndt_score.cpp)
    A << Eigen::Vector3d::UnitX(), Rx * Eigen::Vector3d::UnitY(), Rx * Ry * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d t = xi.head<3>();
    double* jac = jacobians ? jacobians[0] : nullptr;
    for (std::size_t k = 0; k < input_.size(); ++k) {
      Eigen::Map<Eigen::Vector3d> r(residuals + 3 * k);
      const Eigen::Vector3d u = R * input_[k].cast<double>();
      const Eigen::Vector3d x = u + t;
      const int g =
          grid_.lookup(static_cast<float>(x.x()), static_cast<float>(x.y()), static_cast<float>(x.z()));
      Eigen::Map<Eigen::Matrix<double, 3, 6, Eigen::RowMajor>> J(jac ? jac + 18 * k : nullptr);
      if (g < 0) {
        r = Eigen::Vector3d(unmatched_residual_, 0.0, 0.0);
        if (jac) J.setZero();
        continue;
      }
      const CellGaussian& cell = grid_.gaussian(g);
      const Eigen::Matrix3d& Lt = sqrt_information_[static_cast<std::size_t>(g)];
      const Eigen::Vector3d e = x - Eigen::Vector3d(cell.mean[0], cell.mean[1], cell.mean[2]);  // eq. (3.10)
      r = Lt * e;
      if (r.squaredNorm() > max_distance_) {  // min(eᵀC⁻¹e, τ): a constant beyond τ
        r = Eigen::Vector3d(truncated_residual_, 0.0, 0.0);
        if (jac) J.setZero();
        continue;
      }
      if (!jac) continue;
      Eigen::Matrix3d Jr;
      for (int i = 0; i < 3; ++i) Jr.col(i) = A.col(i).cross(u);
      J.leftCols<3>() = Lt;
      J.rightCols<3>() = Lt * Jr;
    }
    return true;
  }

 private:
  const NdtGrid& grid_;
  const PointCloud& input_;
  double unmatched_residual_;
  double max_distance_;
  double truncated_residual_;
  std::vector<Eigen::Matrix3d> sqrt_information_;  ///< Lᵀ per Gaussian of grid_
};

/// Records one trace row per Ceres iteration (the pose is updated in place every iteration).
class TraceCallback final : public ceres::IterationCallback {
 public:
  TraceCallback(const double* xi, int label, int offset, std::vector<IterationTrace>& trace)
      : xi_(xi), label_(label), offset_(offset), trace_(trace) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (summary.iteration == 0 || !summary.step_is_successful) return ceres::SOLVER_CONTINUE;
    IterationTrace row;
    row.iteration = offset_ + static_cast<int>(trace_.size()) + 1;
    row.layer = label_;
    row.score = 2.0 * summary.cost;
    row.step_norm = summary.step_norm;
    row.xi = Eigen::Map<const Vector6d>(xi_);
    trace_.push_back(row);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const double* xi_;
  int label_, offset_;
  std::vector<IterationTrace>& trace_;
};

}  // namespace

CeresStageOutcome solve_stage_with_ceres(const NdtGrid& grid, const PointCloud& input, const Vector6d& xi0,
                                         int max_iterations, double epsilon, double unmatched_penalty,
                                         double max_distance, const DofMask& dof, int label,
                                         int iteration_offset) {
  CeresStageOutcome out;
  out.xi = xi0;
  if (input.empty() || max_iterations <= 0) return out;
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  problem.AddResidualBlock(new MahalanobisCost(grid, input, unmatched_penalty, max_distance), nullptr,
                           out.xi.data());
  if (!dof.all()) {
    std::vector<int> fixed;
    for (int i = 0; i < 6; ++i)
      if (!dof.active[static_cast<std::size_t>(i)]) fixed.push_back(i);
    problem.SetManifold(out.xi.data(), new ceres::SubsetManifold(6, fixed));
  }
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = max_iterations;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.function_tolerance = 1e-12;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = epsilon / std::max(1.0, xi0.norm());  // Ceres' test is relative to ‖ξ‖
  options.update_state_every_iteration = true;
  TraceCallback callback(out.xi.data(), label, iteration_offset, out.trace);
  options.callbacks.push_back(&callback);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  out.iterations = static_cast<int>(out.trace.size());
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  out.failed = summary.termination_type == ceres::FAILURE;
  return out;
}

}  // namespace sextant
