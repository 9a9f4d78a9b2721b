#pragma once
// Exactly Sparse Extended Information Filter (ESEIF; M. R. Walter, R. M. Eustice, J. J. Leonard,
// "Exactly Sparse Extended Information Filters for Feature-based SLAM", IJRR 26(4), 2007) over
// any SlamModel — not in the thesis; an extension beside its SEIF (seif.hpp, §4.2.4).
//
// Same information form (Ω, ξ, μ) and block-sparse storage as SEIF (variable 0 = pose, k =
// landmark k−1); the measurement update (the paper's EIF measurement update, thesis eq. 4.107),
// the time projection (the paper's "augment x_{t+1}, marginalise x_t", which is thesis eq. 4.109)
// and the augmentation are SEIF's. What differs is sparsification: SEIF cuts pose–landmark links
// by an approximation that is overconfident; ESEIF keeps the active set (landmarks linked to the
// pose) at most Γ_a = max_active_landmarks by *relocalization* ("kidnapping" the robot):
//   1. when a scan's update would leave more than Γ_a landmarks linked to the pose, its
//      measurements are split: z_β (up to relocation_landmarks of them, chosen greedily to
//      maximise log det of the pose information they give) is held out, z_α updates as usual;
//   2. before the next motion (or measurement) update the pose is marginalised out — the paper's
//      marginalisation, Λ̌ = Λ_MM − Λ_Mx Λ_xx⁻¹ Λ_xM, η̌ = η_M − Λ_Mx Λ_xx⁻¹ η_x — which links only
//      the active landmarks among themselves (landmarks augmented in the scan included);
//   3. the robot is relocated from z_β alone, the paper's relocalization model
//      x_t = G(m_β, z_β) + v: G is the least-squares pose from z_β (Gauss–Newton from the last
//      pose mean), G_m = −A⁻¹ H_xᵀ R̄⁻¹ H_m and v ~ N(0, A⁻¹) with A = H_xᵀ R̄⁻¹ H_x (R̄ = R per
//      measurement), so that Λ_xx = A, Λ_xβ = −A G_m, Λ_ββ += G_mᵀ A G_m, η such that ξ = Ω μ
//      with μ_x = G(μ_β, z_β) (the paper's relocalization equations in information form).
// Every step is exact inference on a problem that drops the link between the kidnapped pose
// and the relocated one, so Ω stays exactly sparse and the covariance is conservative against
// the exact filter (linear-Gaussian: Σ_eseif − Σ_exact ⪰ 0; tests/filters/eseif_test.cpp).
// Deviation: when z_β does not determine the whole pose (planes with coplanar normals), the
// relocation needs a prior; relocation_prior gives σ per pose entry of a prior at the pose's
// last mean (information the exact filter does not have, so weak by choice; empty = none, and
// the relocation is skipped until a scan's measurements determine the pose). Mean recovery:
// "local" solves Ω_LL μ_L = ξ_L − Ω_LB μ_B exactly over L = pose, active landmarks and the
// landmarks just observed with their neighbours (the paper's partial mean recovery), "exact"
// solves Ω μ = ξ by a sparse Cholesky factorisation of the whole Ω.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sextant/filters/filter.hpp"
#include "sextant/filters/seif.hpp"

namespace sextant {

struct EseifSettings {
  int max_active_landmarks = 8;          ///< Γ_a; 0 disables relocalization (the EIF)
  int relocation_landmarks = 3;          ///< measurements held out for relocation (|z_β| ≤ Γ_a)
  std::vector<double> relocation_prior;  ///< σ per pose entry of the relocation prior (empty: none)
  std::string mean_recovery = "local";   ///< "local" or "exact"
  bool valid(std::string* why) const;
};

class Eseif final : public Filter {
 public:
  Eseif(std::string name, std::shared_ptr<const SlamModel> model, EseifSettings settings = {});
  std::string name() const override { return name_; }
  const SlamModel& model() const override { return *model_; }
  StepResult initialize(const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) override;
  StepResult predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) override;
  StepResult update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                    const std::vector<int>& associations) override;
  StepResult augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) override;
  Eigen::VectorXd mean() const override { return mu_; }
  /// The inverse of Ω (dense, O(n³); tests).
  Eigen::MatrixXd covariance() const override;
  /// The exact marginal of ESEIF's own distribution, (Ω⁻¹) over the pose and the landmarks
  /// asked for, from a sparse Cholesky factorisation of Ω. Unknown indices throw.
  Eigen::MatrixXd joint_covariance(const std::vector<int>& landmarks) const override;
  int num_landmarks() const override { return omega_.variables() - 1; }
  /// Ω and the relocation counts.
  FilterDiagnostics diagnostics() const override;

  const BlockInformationMatrix& information() const { return omega_; }
  const Eigen::VectorXd& information_vector() const { return xi_; }
  /// Landmarks (0-based) linked to the pose.
  std::vector<int> active_landmarks() const;
  /// Relocalizations done, and relocalizations skipped because z_β did not determine the pose.
  std::size_t relocations() const { return relocations_; }
  std::size_t skipped_relocations() const { return skipped_; }
  /// True while held-out measurements wait for the relocation (before the next predict/update).
  bool relocation_pending() const { return !held_.empty(); }
  /// Information-matrix entries read or written by the last step (its cost).
  std::size_t last_step_touched() const { return last_touched_; }

 private:
  struct Held {
    Eigen::VectorXd z;
    int landmark = 0;
  };
  StepResult finish(StepStatus status, double seconds);
  void normalize(int var);
  /// Indices into zs of z_β, or empty when the pose cannot be determined.
  std::vector<std::size_t> choose_relocation(const std::vector<Eigen::VectorXd>& zs,
                                             const std::vector<int>& associations,
                                             const Eigen::MatrixXd& Rinv) const;
  /// Steps 2–3 of the header with the held-out measurements; false on a numerical failure.
  bool relocate();
  bool recover_mean(const std::vector<int>& observed);

  std::string name_;
  std::shared_ptr<const SlamModel> model_;
  EseifSettings s_;
  BlockInformationMatrix omega_;
  Eigen::VectorXd xi_, mu_;
  std::vector<Held> held_;
  Eigen::MatrixXd held_R_;
  std::size_t relocations_ = 0, skipped_ = 0, last_touched_ = 0;
};

/// (Ω⁻¹) over the given variables (0 = pose, k = landmark k−1) by a sparse Cholesky factorisation:
/// the exact marginal covariance of an information filter (SEIF or ESEIF). Empty when Ω is not
/// positive definite.
Eigen::MatrixXd information_marginal(const BlockInformationMatrix& omega, const std::vector<int>& vars);

}  // namespace sextant
