// The shared optimiser loop (Table 3.1's registration process) with Newton, LM and Ceres steps.
#include "optim/optimizer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "ndt/ndt_score.hpp"
#include "optim/ceres_stage.hpp"
#include "optim/more_thuente.hpp"

namespace sextant {

namespace {

constexpr int kMaxLmTries = 12;

/// The rows/columns of the active parameters.
struct Masked {
  std::vector<int> index;
  explicit Masked(const DofMask& dof) {
    for (int i = 0; i < 6; ++i)
      if (dof.active[static_cast<std::size_t>(i)]) index.push_back(i);
  }
  Eigen::MatrixXd matrix(const Matrix6d& M) const {
    Eigen::MatrixXd out(index.size(), index.size());
    for (std::size_t i = 0; i < index.size(); ++i)
      for (std::size_t j = 0; j < index.size(); ++j) out(i, j) = M(index[i], index[j]);
    return out;
  }
  Eigen::VectorXd vector(const Vector6d& v) const {
    Eigen::VectorXd out(index.size());
    for (std::size_t i = 0; i < index.size(); ++i) out(i) = v(index[i]);
    return out;
  }
  Vector6d expand(const Eigen::VectorXd& v) const {
    Vector6d out = Vector6d::Zero();
    for (std::size_t i = 0; i < index.size(); ++i) out(index[i]) = v(static_cast<Eigen::Index>(i));
    return out;
  }
};

/// γ that makes H safely positive definite (0 when it is); false when H has no scale.
bool newton_shift(const Eigen::MatrixXd& H, double& gamma) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(H);
  const Eigen::VectorXd l = eig.eigenvalues();
  const double largest = l.cwiseAbs().maxCoeff();
  if (!(largest > 0.0)) return false;
  const double wanted = 1e-6 * largest;  // "safely" positive definite
  gamma = l.minCoeff() < wanted ? wanted - l.minCoeff() + 1e-3 * largest : 0.0;
  return true;
}

/// Solves (H + (γ + extra)·I)·Δ = −g with γ = 0 when H is safely positive definite (eq. 3.16 and
/// the text after eq. 3.18); `extra` is the trust region's damping. False when no finite step exists.
bool newton_step(const Eigen::MatrixXd& H, const Eigen::VectorXd& g, double extra, Eigen::VectorXd& step) {
  if (!H.allFinite() || !g.allFinite()) return false;
  double gamma = 0.0;
  if (!newton_shift(H, gamma)) return false;
  const Eigen::MatrixXd damped = H + (gamma + extra) * Eigen::MatrixXd::Identity(H.rows(), H.cols());
  step = -damped.ldlt().solve(g);
  return step.allFinite();
}

Eigen::Isometry3d to_transform(const Vector6d& xi) {
  return to_isometry(Pose6::from_vector(xi));
}

class Loop {
 public:
  Loop(const StagedObjective& objective, const OptimizerSettings& settings)
      : objective_(objective), settings_(settings), mask_(settings.dof) {}

  RegistrationResult run(const Eigen::Isometry3d& initial) {
    const auto start = std::chrono::steady_clock::now();
    result_.input_points = objective_.input().size();
    result_.free = settings_.dof;
    if (is_finite(initial)) result_.T = initial;
    if (!is_finite(initial)) {
      finish(Termination::kNonFiniteInput);
    } else if (objective_.input().empty() || objective_.stages() == 0) {
      finish(Termination::kEmptyInput);
    } else {
      xi_ = to_pose6(initial).vector();
      run_stages();
    }
    result_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result_;
  }

 private:
  void run_stages() {
    const int stages = objective_.stages();
    for (int stage = 0; stage < stages; ++stage) {
      const bool last = stage == stages - 1;
      const int budget =
          last ? settings_.max_iterations - iterations_
               : std::min(settings_.iterations_per_stage, settings_.max_iterations - iterations_);
      bool done = false;
      if (settings_.solver == SolverKind::kCeres)
        done = ceres_stage(stage, budget, last);
      else
        done = own_stage(stage, budget, last);
      if (done) return;
    }
    finish(Termination::kMaxIterations, stages - 1);
  }

  /// Newton or LM iterations on one stage; true when the registration has ended.
  bool own_stage(int stage, int budget, bool last) {
    double lambda = -1.0;  // LM damping, reset per stage (the matrix scale changes with the layer)
    trust_ = 0.0;          // trust-region damping (relative to mean |diag H|), reset per stage
    for (int k = 0; k < budget; ++k) {
      const ScoreEvaluation at = with_hessian(stage, xi_);
      if (at.matched < settings_.min_matched) return finish(Termination::kTooFewCorrespondences, stage);
      const Eigen::VectorXd g = mask_.vector(at.gradient);
      Eigen::VectorXd step;
      double score = at.score;
      if (settings_.solver == SolverKind::kNewton && damped_stage(last)) {
        if (!trust_region_step(stage, at, mask_.matrix(at.hessian), g, trust_, step, score))
          return finish(Termination::kSolverFailure, stage);
        xi_ += mask_.expand(step);
      } else if (settings_.solver == SolverKind::kNewton) {
        if (!newton_step(mask_.matrix(at.hessian), g, 0.0, step))
          return finish(Termination::kSolverFailure, stage);
        Vector6d full = mask_.expand(step);
        if (settings_.step_control == StepControl::kLineSearch)
          full = backtrack(stage, at, full, score);
        else if (settings_.step_control == StepControl::kMoreThuente)
          full = more_thuente_step(stage, at, full, score);
        else  // eq. (3.16) as printed: the full step, whatever it does to the score
          score = objective_.evaluate(stage, xi_ + full, Derivatives::kScore).score;
        xi_ += full;
        step = mask_.vector(full);
      } else {
        // eq. (3.21) on Σ‖Lᵀe‖² (the same minimum as eq. 3.11): Δ = −(JᵀJ + λI)⁻¹·Jᵀr, with
        // JᵀJ = ½·gauss_newton and Jᵀr = ½·gradient. λ₀ = 10⁻³·mean(diag JᵀJ), ÷10 on success, ×10 otherwise.
        // A step shorter than ε, or one whose predicted decrease is below function_tolerance × the
        // score, is not tried: the stage is at its minimum.
        const Eigen::MatrixXd JtJ =
            0.5 * mask_.matrix(objective_.mahalanobis_grid(stage) ? at.gauss_newton : at.hessian);
        if (lambda < 0) lambda = 1e-3 * JtJ.diagonal().mean();
        bool accepted = false;
        for (int attempt = 0; attempt < kMaxLmTries && !accepted; ++attempt) {
          const Eigen::MatrixXd damped = JtJ + lambda * Eigen::MatrixXd::Identity(JtJ.rows(), JtJ.cols());
          step = -damped.ldlt().solve(0.5 * g);
          if (!step.allFinite()) return finish(Termination::kSolverFailure, stage);
          const double predicted_decrease = -(g.dot(step) + step.dot(JtJ * step));
          if (at_minimum(step) || predicted_decrease < settings_.function_tolerance * std::abs(at.score))
            break;
          const ScoreEvaluation& trial = with_hessian(stage, xi_ + mask_.expand(step));
          if (trial.matched >= settings_.min_matched && trial.score < at.score) {
            accepted = true;
            score = trial.score;
            lambda /= 10.0;
          } else {
            lambda *= 10.0;
          }
        }
        if (!accepted) {  // no decrease at any damping, or none worth a try: a minimum of this stage
          record(stage, at.score, 0.0, at.matched);
          return last ? finish(Termination::kConverged, stage) : false;
        }
        xi_ += mask_.expand(step);
      }
      if (!xi_.allFinite()) return finish(Termination::kDiverged, stage);
      record(stage, score, step.norm(), at.matched);
      if (last && step.norm() < settings_.epsilon) return finish(Termination::kConverged, stage);
    }
    return false;
  }

  /// A damped step shorter than ε could only end the registration (‖Δξ‖ < ε) at a pose within ε of
  /// this one, and a larger damping only shortens it: the stage is at its minimum, and the step is
  /// not worth an evaluation.
  bool at_minimum(const Eigen::VectorXd& step) const { return step.norm() < settings_.epsilon; }

  /// Whether this stage's Newton steps go through the trust region.
  bool damped_stage(bool last) const {
    return settings_.step_control == StepControl::kTrustRegion ||
           (settings_.step_control == StepControl::kTrustRegionLast && last);
  }

  /// Damped Newton (StepControl::kTrustRegion): tries (H + γI + λ·d̄·I)Δ = −g from the current λ,
  /// ×10 until the score drops (at most kMaxLmTries), then λ ÷ 10 for the next iteration. No
  /// decrease at any damping gives Δ = 0 (a minimum of this stage). False on a non-finite step.
  bool trust_region_step(int stage, const ScoreEvaluation& at, const Eigen::MatrixXd& H,
                         const Eigen::VectorXd& g, double& lambda, Eigen::VectorXd& step, double& score) {
    const double scale = H.diagonal().cwiseAbs().mean();
    for (int attempt = 0; attempt < kMaxLmTries; ++attempt) {
      if (!newton_step(H, g, lambda * scale, step)) return false;
      if (at_minimum(step)) break;
      const ScoreEvaluation& trial = with_hessian(stage, xi_ + mask_.expand(step));
      if (trial.matched >= settings_.min_matched && trial.score < at.score) {
        score = trial.score;
        lambda /= 10.0;
        if (lambda < 1e-6) lambda = 0.0;
        return true;
      }
      lambda = lambda > 0.0 ? 10.0 * lambda : 1e-3;
    }
    step.setZero();
    score = at.score;
    return true;
  }

  /// Armijo backtracking along a Newton direction; returns the accepted step.
  Vector6d backtrack(int stage, const ScoreEvaluation& at, const Vector6d& direction, double& score) const {
    const double slope = at.gradient.dot(direction);
    double t = 1.0;
    for (int i = 0; i < 20; ++i, t *= 0.5) {
      const ScoreEvaluation trial = objective_.evaluate(stage, xi_ + t * direction, Derivatives::kScore);
      if (trial.matched >= settings_.min_matched &&
          trial.score <= at.score + 1e-4 * t * std::min(slope, 0.0)) {
        score = trial.score;
        return t * direction;
      }
    }
    score = at.score;
    return Vector6d::Zero();
  }

  /// Moré–Thuente along the Newton direction Δ: φ(α) = f(ξ + α·Δ), φ'(α) = ∇f·Δ; α ∈ [0, α_max]
  /// with α_max = max_step / ‖Δ‖, first trial min(1, α_max). A trial with too few matched points
  /// has no value (the search shortens the step). Returns the accepted step α·Δ.
  Vector6d more_thuente_step(int stage, const ScoreEvaluation& at, const Vector6d& direction,
                             double& score) const {
    const MoreThuenteSettings& mt = settings_.line_search;
    const double alpha_max = mt.max_step / direction.norm();
    const auto phi = [&](double alpha) {
      const ScoreEvaluation e = objective_.evaluate(stage, xi_ + alpha * direction, Derivatives::kGradient);
      return LineSearchSample{e.score, e.gradient.dot(direction), e.matched >= settings_.min_matched};
    };
    const LineSearchSample origin{at.score, at.gradient.dot(direction), true};
    const LineSearchResult r = std::isfinite(alpha_max)
                                   ? more_thuente(phi, origin, std::min(1.0, alpha_max), 0.0, alpha_max, mt)
                                   : LineSearchResult{};
    score = r.step > 0.0 ? r.at.value : at.score;
    return r.step * direction;
  }

  bool ceres_stage(int stage, int budget, bool last) {
    const NdtGrid* grid = objective_.mahalanobis_grid(stage);
    if (!grid) return finish(Termination::kSolverFailure, stage);
    const ScoreEvaluation at = objective_.evaluate(stage, xi_, Derivatives::kScore);
    if (at.matched < settings_.min_matched) return finish(Termination::kTooFewCorrespondences, stage);
    const CeresStageOutcome out = solve_stage_with_ceres(
        *grid, objective_.input(), xi_, budget, settings_.epsilon, objective_.unmatched_penalty(),
        objective_.max_distance(stage), settings_.dof, objective_.stage_label(stage), iterations_);
    if (!out.xi.allFinite()) return finish(Termination::kDiverged, stage);
    xi_ = out.xi;
    iterations_ += out.iterations;
    result_.trace.insert(result_.trace.end(), out.trace.begin(), out.trace.end());
    if (!last) return false;
    if (out.failed) return finish(Termination::kSolverFailure, stage);
    return finish(out.converged ? Termination::kConverged : Termination::kMaxIterations, stage);
  }

  /// The score with its derivatives at ξ, remembered: a damped step's trial, once accepted, is the
  /// next iteration's linearisation point (and the final pose's Hessian), so the trial is evaluated
  /// with its derivatives once instead of its score now and its derivatives again after.
  const ScoreEvaluation& with_hessian(int stage, const Vector6d& xi) {
    if (!(last_.stage == stage && last_.xi == xi)) {
      last_.evaluation = objective_.evaluate(stage, xi, Derivatives::kHessian);
      last_.stage = stage;
      last_.xi = xi;
    }
    return last_.evaluation;
  }

  void record(int stage, double score, double step_norm, std::size_t matched) {
    ++iterations_;
    IterationTrace row;
    row.iteration = iterations_;
    row.layer = objective_.stage_label(stage);
    row.score = score;
    row.step_norm = step_norm;
    row.xi = xi_;
    row.matched_points = matched;
    result_.trace.push_back(row);
  }

  /// Fills the result; returns true (the registration has ended).
  bool finish(Termination why, int stage = -1) {
    result_.why = why;
    result_.iterations = iterations_;
    result_.converged = why == Termination::kConverged;
    if (stage >= 0 && xi_.allFinite()) {
      const ScoreEvaluation at = with_hessian(stage, xi_);
      result_.T = to_transform(xi_);
      result_.H = at.hessian;
      result_.score = at.score;
      result_.matched_points = at.matched;
      result_.predicted_matched_score = objective_.predicted_matched_score();
      if (at.matched > 0) result_.mean_matched_score = at.matched_score / static_cast<double>(at.matched);
      if (result_.converged && at.matched < settings_.min_matched) {
        result_.converged = false;
        result_.why = Termination::kTooFewCorrespondences;
      }
    }
    if (!is_finite(result_.T)) result_.T = Eigen::Isometry3d::Identity();
    return true;
  }

  const StagedObjective& objective_;
  const OptimizerSettings& settings_;
  Masked mask_;
  Vector6d xi_ = Vector6d::Zero();
  int iterations_ = 0;
  double trust_ = 0.0;  ///< trust-region damping λ of the current stage
  struct Evaluated {
    int stage = -1;
    Vector6d xi = Vector6d::Constant(std::numeric_limits<double>::quiet_NaN());
    ScoreEvaluation evaluation;
  } last_;  ///< the last with_hessian()
  RegistrationResult result_;
};

}  // namespace

bool from_string(const std::string& text, SolverKind* out) {
  return from_name(kSolverNames, text, out);
}

bool from_string(const std::string& text, StepControl* out) {
  return from_name(kStepControlNames, text, out);
}

std::string to_string(StepControl control) {
  return name_of(kStepControlNames, control);
}

std::string to_string(SolverKind kind) {
  return name_of(kSolverNames, kind);
}

bool OptimizerSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (iterations_per_stage < 1)
    problem = "iterations per layer must be at least 1";
  else if (max_iterations < 1)
    problem = "max_iterations must be at least 1";
  else if (!(epsilon > 0.0))
    problem = "epsilon must be positive";
  else if (!(function_tolerance >= 0.0 && function_tolerance < 1.0))
    problem = "function_tolerance must lie in [0, 1) (0: off)";
  if (problem && why) *why = problem;
  if (problem) return false;
  return line_search.valid(why) && dof.valid(why);
}

RegistrationResult optimize(const StagedObjective& objective, const Eigen::Isometry3d& initial,
                            const OptimizerSettings& settings) {
  return Loop(objective, settings).run(initial);
}

}  // namespace sextant
