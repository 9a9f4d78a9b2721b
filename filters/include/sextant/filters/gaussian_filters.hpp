#pragma once
// Covariance-form SLAM filters: the EKF (eqs. 4.62–4.68) and one sigma-point filter that is the
// UKF (Tables 4.2–4.3), the CKF (eqs. 4.73–4.81) or the RSPKF (eqs. 4.88–4.103) depending on its
// SigmaPointRule. Sigma-point prediction augments the state with the control (eq. 4.73),
// augmentation with the observation (eq. 4.103 / Table 4.3).
#include <cstdint>
#include <memory>
#include <string>

#include "sextant/filters/filter.hpp"
#include "sextant/filters/sigma_points.hpp"

namespace sextant {

struct GaussianFilterSettings {
  bool joseph_form = false;  ///< EKF: P⁺ = (I−KH)P(I−KH)ᵀ + KRKᵀ (O(n³)) instead of P − KSKᵀ
  bool symmetrize = true;    ///< P ← (P + Pᵀ)/2 after every step
  /// LLᵀ test of P after every step (O(n³); off for benchmarks). The EKF's predict and augment
  /// test only the block they add (P stays PD exactly when it does), so its steps stay O(n²).
  bool check_covariance = true;
  bool valid(std::string* why) const;
};

/// What the EKF and the sigma-point filters share: the model, the settings and the moments
/// (x, P), their initialisation and the end-of-step normalisation and checks.
class MomentFilter : public Filter {
 public:
  const SlamModel& model() const override { return *model_; }
  StepResult initialize(const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) override;
  Eigen::VectorXd mean() const override { return x_; }
  Eigen::MatrixXd covariance() const override { return P_; }
  Eigen::MatrixXd joint_covariance(const std::vector<int>& landmarks) const override {
    return joint_block(*model_, P_, landmarks);
  }
  int num_landmarks() const override;

 protected:
  MomentFilter(std::shared_ptr<const SlamModel> model, GaussianFilterSettings settings);
  /// Wraps angles, normalises landmarks, symmetrises P (when the settings and `symmetrize` say
  /// so) and checks it (step_checks.hpp): the whole P, or, given `changed_block`, only that block
  /// (for steps that keep P positive definite exactly when the block is).
  StepStatus finish_step(bool symmetrize = true, const Eigen::MatrixXd* changed_block = nullptr);

  std::shared_ptr<const SlamModel> model_;
  GaussianFilterSettings s_;
  Eigen::VectorXd x_;
  Eigen::MatrixXd P_;
};

class Ekf final : public MomentFilter {
 public:
  Ekf(std::shared_ptr<const SlamModel> model, GaussianFilterSettings settings = {});
  std::string name() const override { return "ekf"; }
  StepResult predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) override;
  StepResult update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                    const std::vector<int>& associations) override;
  StepResult augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) override;
};

class SigmaPointFilter final : public MomentFilter {
 public:
  SigmaPointFilter(std::string name, std::shared_ptr<const SlamModel> model,
                   std::unique_ptr<SigmaPointRule> rule, GaussianFilterSettings settings = {},
                   std::uint64_t seed = 1);
  std::string name() const override { return name_; }
  std::string approximation() const override { return rule_->parameters(); }
  StepResult predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) override;
  StepResult update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                    const std::vector<int>& associations) override;
  StepResult augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) override;

 private:
  std::string name_;
  std::unique_ptr<SigmaPointRule> rule_;
  Rng rng_;
};

}  // namespace sextant
