#pragma once
// Sparse Extended Information Filter (§4.2.4, eqs. 4.104–4.114) over any SlamModel, and the EIF
// as its special case (no sparsification, exact mean recovery).
//
// The information matrix Ω is stored block-sparse (variable 0 = pose, variable k = landmark
// k−1), so every step touches only the pose, the active landmarks (those linked to the pose)
// and the landmark being observed:
//   measurement update (eq. 4.107): Ω += Hᵀ R⁻¹ H, ξ += Hᵀ R⁻¹ (z − h(μ) + H μ) — constant time;
//   motion update (eq. 4.109) in the form Ω̄ = Φ − Φ_{:,v} U (I + Φ_vv U)⁻¹ Φ_{v,:} with
//     Φ = (I+A)⁻ᵀ Ω (I+A)⁻¹ and ξ̄ = ξ + (Ω̄ − Ω) μ + Ω̄_{:,v} Δ — constant time given μ of the
//     active set (Lemma 3);
//   augmentation: the factor m = g(μ_v, z) + G_v (x_v − μ_v) + e, e ~ N(0, G_z R G_zᵀ) — exact
//     information-form counterpart of eq. (4.68);
//   sparsification (eqs. 4.110–4.114): when more than max_active_landmarks are linked to the
//     pose, the least recently observed ones (y⁰) are deactivated.
// What is approximate in SEIF mode: (1) sparsification drops the dependence of the pose on y⁰
// (eq. 4.112), (2) the mean is recovered by a few Gauss–Seidel sweeps of Ω μ = ξ over the pose
// and the active landmarks only, so passive landmarks keep their last mean and the linearisation
// points may lag, (3) renormalising a plane's normal changes the mean but not Ω (as in the EKF).
// (4) joint_covariance() — what an association gate needs — is the covariance of the pose and
// the landmarks conditioned on their Markov blanket's complement at its mean: (Ω_BB)⁻¹ over the
// blanket B = pose, active landmarks, each landmark with its neighbours, and a shortest path in
// the information graph joining a landmark not yet linked to that set. Conditioning only removes
// uncertainty, so this is never larger than the exact marginal (it equals it when B holds every
// variable, as in the EIF), and its cost depends on the blanket, not on the map size.
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sextant/filters/filter.hpp"

namespace sextant {

struct SeifSettings {
  int max_active_landmarks = 8;              ///< bound of the active set; 0 disables sparsification (EIF)
  std::string mean_recovery = "relaxation";  ///< "relaxation" (active set) or "exact" (O(n³) solve)
  int relaxation_iterations = 3;             ///< Gauss–Seidel sweeps per step in relaxation mode
  bool valid(std::string* why) const;
};

/// A symmetric block-sparse matrix over variables of given sizes; counts the entries it reads
/// and writes so tests can show that a step's cost does not depend on the map size.
class BlockInformationMatrix {
 public:
  int add_variable(int dim);
  int variables() const { return static_cast<int>(dims_.size()); }
  int dim(int i) const { return dims_[i]; }
  Eigen::Index offset(int i) const { return offsets_[i]; }
  Eigen::Index size() const { return total_; }

  /// Ω_ij (zero block when absent).
  Eigen::MatrixXd block(int i, int j) const;
  bool linked(int i, int j) const;
  /// Ω_ij = M (and Ω_ji = Mᵀ).
  void set(int i, int j, const Eigen::MatrixXd& M);
  /// Ω_ij += M (and Ω_ji += Mᵀ when i ≠ j).
  void add(int i, int j, const Eigen::MatrixXd& M);
  void erase(int i, int j);
  /// Variables linked to i (excluding i), ascending.
  std::vector<int> neighbours(int i) const;
  /// Dense gather/scatter over a variable subset (order as given). A gather outside a filter
  /// step (count = false: the association gate) is not counted in touched().
  Eigen::MatrixXd gather(const std::vector<int>& vars, bool count = true) const;
  void scatter(const std::vector<int>& vars, const Eigen::MatrixXd& dense);
  /// The whole matrix, dense (tests, covariance()).
  Eigen::MatrixXd dense() const;
  std::size_t blocks() const;

  std::size_t touched() const { return touched_; }
  void reset_touched() { touched_ = 0; }

 private:
  std::vector<int> dims_;
  std::vector<Eigen::Index> offsets_;
  Eigen::Index total_ = 0;
  std::vector<std::map<int, Eigen::MatrixXd>> rows_;
  mutable std::size_t touched_ = 0;
};

class Seif final : public Filter {
 public:
  Seif(std::string name, std::shared_ptr<const SlamModel> model, SeifSettings settings = {});
  std::string name() const override { return name_; }
  const SlamModel& model() const override { return *model_; }
  StepResult initialize(const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) override;
  StepResult predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) override;
  StepResult update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                    const std::vector<int>& associations) override;
  StepResult augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) override;
  Eigen::VectorXd mean() const override { return mu_; }
  Eigen::MatrixXd covariance() const override;
  Eigen::MatrixXd joint_covariance(const std::vector<int>& landmarks) const override;
  int num_landmarks() const override { return omega_.variables() - 1; }
  /// Ω; joint_covariance() is the Markov-blanket covariance (approximate_covariance).
  FilterDiagnostics diagnostics() const override;
  /// Variables (0 = pose, k = landmark k−1) of the Markov blanket used by joint_covariance(),
  /// starting with the pose and then the landmarks asked for.
  std::vector<int> markov_blanket(const std::vector<int>& landmarks) const;

  const BlockInformationMatrix& information() const { return omega_; }
  const Eigen::VectorXd& information_vector() const { return xi_; }
  /// Landmarks (0-based) linked to the pose, least recently observed first.
  const std::vector<int>& active_landmarks() const { return active_; }
  /// Information-matrix entries read or written by the last step (its cost).
  std::size_t last_step_touched() const { return last_touched_; }

 private:
  StepResult finish(StepStatus status, double seconds);
  void activate(int landmark);
  bool sparsify();
  bool recover_mean();
  /// μ_i ← μ_i + δ keeping ξ = Ω μ (used for angle wrapping and normal renormalisation).
  void shift_mean(int var, const Eigen::VectorXd& delta);
  void normalize_variable(int var);

  std::string name_;
  std::shared_ptr<const SlamModel> model_;
  SeifSettings s_;
  BlockInformationMatrix omega_;
  Eigen::VectorXd xi_, mu_;
  std::vector<int> active_;
  std::size_t last_touched_ = 0;
};

}  // namespace sextant
