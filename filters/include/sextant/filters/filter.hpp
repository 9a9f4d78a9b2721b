#pragma once
// One interface for every SLAM filter (EKF, UKF, CKF, RSPKF, SEIF/EIF), generic over a SlamModel:
//
//   auto filter = std::make_unique<Ekf>(model, settings);   // or default_filter("ukf")(model); by name
//                                                           // with YAML settings: filters/yaml.hpp
//   filter->initialize(x0, P0);                     // x0 = [pose; landmarks…]
//   filter->predict(u, Q);                          // Q: covariance of the control u
//   filter->update(zs, R, associations);            // zs[i] observes landmark associations[i]
//   filter->augment(z, R);                          // appends a new landmark
//
// A numerical failure (not positive definite, failed Cholesky, singular innovation) is the
// step's status and is counted in summary(); it never throws and never crashes.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sextant/filters/slam_model.hpp"

namespace sextant {

enum class StepStatus {
  kOk,
  kNotPositiveDefinite,  ///< the covariance after the step is not positive definite
  kCholeskyFailed,       ///< a square root (Cholesky) of a covariance failed before the step
  kSingularInnovation,   ///< the innovation covariance could not be inverted
  kInvalidInput,         ///< wrong sizes, NaN/Inf, unknown landmark index; the state is unchanged
};

std::string to_string(StepStatus status);

struct StepResult {
  StepStatus status = StepStatus::kOk;
  double seconds = 0.0;  ///< wall time of the step
  bool ok() const { return status == StepStatus::kOk; }
};

/// Counts over a filter's life (or a run): every step's status.
struct FilterSummary {
  std::size_t steps = 0;
  std::size_t not_positive_definite = 0;
  std::size_t cholesky_failures = 0;
  std::size_t singular_innovations = 0;
  std::size_t invalid_inputs = 0;
  void add(StepStatus status);
  std::size_t failures() const {
    return not_positive_definite + cholesky_failures + singular_innovations + invalid_inputs;
  }
};

class BlockInformationMatrix;  // seif.hpp

/// What a filter reports beyond its moments (Filter::diagnostics), so that a caller records it
/// without knowing the filter's type. The information filters report their sparse information
/// matrix Ω — its pattern shows SEIF's sparsification (eqs. 4.110–4.114) and ESEIF's
/// marginalisation and relocation (eseif.hpp) — and ESEIF its relocation counts.
struct FilterDiagnostics {
  /// Ω (variable 0 = pose, k = landmark k−1; SEIF, EIF, ESEIF), valid until the filter's next
  /// step; null for the moment filters and FastSLAM.
  const BlockInformationMatrix* information = nullptr;
  /// joint_covariance() is the Markov-blanket covariance (SEIF and the EIF, seif.hpp), not the
  /// marginal of Ω⁻¹ (information_marginal, eseif.hpp, gives that one).
  bool approximate_covariance = false;
  std::size_t relocations = 0;          ///< ESEIF: relocalizations done
  std::size_t skipped_relocations = 0;  ///< ESEIF: skipped because z_β did not determine the pose
};

class Filter {
 public:
  virtual ~Filter() = default;
  virtual std::string name() const = 0;
  virtual const SlamModel& model() const = 0;

  /// Sets the state (its size fixes the number of landmarks) and its covariance.
  virtual StepResult initialize(const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) = 0;
  /// Motion update with control u and its noise covariance Q (control_dim × control_dim).
  virtual StepResult predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) = 0;
  /// Measurement update: zs[i] observes landmark associations[i] (0-based); R is the noise of
  /// one observation (observation_dim × observation_dim).
  virtual StepResult update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                            const std::vector<int>& associations) = 0;
  /// Appends the landmark observed as z (noise R); it gets index num_landmarks() − 1.
  virtual StepResult augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) = 0;

  /// Current mean [pose; landmarks] (SEIF: its recovered, possibly approximate, mean).
  virtual Eigen::VectorXd mean() const = 0;
  /// Current covariance (SEIF/EIF: the inverse of the information matrix, O(n³), for inspection).
  virtual Eigen::MatrixXd covariance() const = 0;
  /// Covariance of [pose; landmark landmarks[0]; …] (0-based indices), the joint marginal an
  /// association gate needs. Default: read from covariance(). SEIF: its Markov-blanket
  /// approximation (seif.hpp). Unknown indices throw std::out_of_range.
  virtual Eigen::MatrixXd joint_covariance(const std::vector<int>& landmarks) const;
  virtual int num_landmarks() const = 0;
  /// How the filter carries the Gaussian through the nonlinear models, with its free parameters
  /// (the reports print it per method). Default: linearised by Jacobians, no sigma points (EKF,
  /// SEIF, EIF, ESEIF); the sigma-point filters name their rule (sigma_points.hpp).
  virtual std::string approximation() const;
  /// What the filter reports beyond its moments (FilterDiagnostics). Default: nothing.
  virtual FilterDiagnostics diagnostics() const;

  Eigen::VectorXd pose() const { return mean().head(model().pose_dim()); }
  const FilterSummary& summary() const { return summary_; }

 protected:
  /// Records a finished step in the summary and returns it.
  StepResult record(StepStatus status, double seconds);
  FilterSummary summary_;
};

/// The rows and columns of the pose and of `landmarks` (0-based) in a full state covariance P,
/// in that order (Filter::joint_covariance of the moment filters). Throws std::out_of_range.
Eigen::MatrixXd joint_block(const SlamModel& model, const Eigen::MatrixXd& P,
                            const std::vector<int>& landmarks);

/// Builds a filter on a model.
using FilterFactory = std::function<std::unique_ptr<Filter>(std::shared_ptr<const SlamModel>)>;

/// The built-in filter `name` (ekf, ukf, ckf, rspkf, seif, eif, eseif) with its default settings;
/// an empty factory for an unknown name. The filters with their own settings: construct them
/// (gaussian_filters.hpp, seif.hpp, eseif.hpp), or read them from YAML (filters/yaml.hpp).
FilterFactory default_filter(const std::string& name);

}  // namespace sextant
