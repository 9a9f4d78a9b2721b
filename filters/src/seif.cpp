#include "sextant/filters/seif.hpp"

#include <algorithm>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "information_ops.hpp"
#include "sextant/core/checked_settings.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/filters/covariance.hpp"
#include "step_checks.hpp"

namespace sextant {
namespace {

using detail::gather_vector;
using detail::kPose;
using detail::local_offsets;
using detail::scatter_add_vector;

// Selection of the rows of a gathered block that belong to `subset` (a subset of vars).
std::vector<Eigen::Index> rows_of(const BlockInformationMatrix& omega, const std::vector<int>& vars,
                                  const std::vector<int>& subset) {
  const auto off = local_offsets(omega, vars);
  std::vector<Eigen::Index> rows;
  for (int s : subset) {
    const auto it = std::find(vars.begin(), vars.end(), s);
    const Eigen::Index base = off[static_cast<std::size_t>(it - vars.begin())];
    for (int k = 0; k < omega.dim(s); ++k) rows.push_back(base + k);
  }
  return rows;
}

// M S (Sᵀ M S)⁻¹ Sᵀ M for the selection S given by `rows`; false when the block is singular.
bool marginal_term(const Eigen::MatrixXd& M, const std::vector<Eigen::Index>& rows, Eigen::MatrixXd* out) {
  const Eigen::Index k = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd cols(M.rows(), k), inner(k, k);
  for (Eigen::Index a = 0; a < k; ++a) {
    cols.col(a) = M.col(rows[a]);
    for (Eigen::Index b = 0; b < k; ++b) inner(a, b) = M(rows[a], rows[b]);
  }
  Eigen::LLT<Eigen::MatrixXd> llt(inner);
  if (llt.info() != Eigen::Success) return false;
  *out = cols * llt.solve(cols.transpose());
  return true;
}

}  // namespace

bool SeifSettings::valid(std::string* why) const {
  if (max_active_landmarks < 0)
    return *why = "max_active_landmarks must be >= 0 (0 = no sparsification)", false;
  if (mean_recovery != "relaxation" && mean_recovery != "exact")
    return *why = "mean_recovery must be 'relaxation' or 'exact'", false;
  if (relaxation_iterations < 1) return *why = "relaxation_iterations must be >= 1", false;
  return true;
}

// ---- BlockInformationMatrix ----

int BlockInformationMatrix::add_variable(int dim) {
  dims_.push_back(dim);
  offsets_.push_back(total_);
  total_ += dim;
  rows_.emplace_back();
  return variables() - 1;
}

Eigen::MatrixXd BlockInformationMatrix::block(int i, int j) const {
  const auto it = rows_[i].find(j);
  if (it == rows_[i].end()) return Eigen::MatrixXd::Zero(dims_[i], dims_[j]);
  touched_ += static_cast<std::size_t>(it->second.size());
  return it->second;
}

bool BlockInformationMatrix::linked(int i, int j) const {
  return rows_[i].count(j) > 0;
}

void BlockInformationMatrix::set(int i, int j, const Eigen::MatrixXd& M) {
  touched_ += static_cast<std::size_t>(M.size());
  rows_[i][j] = M;
  if (i != j) rows_[j][i] = M.transpose();
}

void BlockInformationMatrix::add(int i, int j, const Eigen::MatrixXd& M) {
  touched_ += static_cast<std::size_t>(M.size());
  auto& a = rows_[i].try_emplace(j, Eigen::MatrixXd::Zero(dims_[i], dims_[j])).first->second;
  a += M;
  if (i != j) {
    auto& b = rows_[j].try_emplace(i, Eigen::MatrixXd::Zero(dims_[j], dims_[i])).first->second;
    b += M.transpose();
  }
}

void BlockInformationMatrix::erase(int i, int j) {
  rows_[i].erase(j);
  rows_[j].erase(i);
}

std::vector<int> BlockInformationMatrix::neighbours(int i) const {
  std::vector<int> out;
  for (const auto& [j, M] : rows_[i])
    if (j != i) out.push_back(j);
  return out;
}

Eigen::MatrixXd BlockInformationMatrix::gather(const std::vector<int>& vars, bool count) const {
  const auto off = local_offsets(*this, vars);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(off.back(), off.back());
  for (std::size_t a = 0; a < vars.size(); ++a)
    for (std::size_t b = 0; b < vars.size(); ++b) {
      const auto it = rows_[vars[a]].find(vars[b]);
      if (it == rows_[vars[a]].end()) continue;
      if (count) touched_ += static_cast<std::size_t>(it->second.size());
      out.block(off[a], off[b], dims_[vars[a]], dims_[vars[b]]) = it->second;
    }
  return out;
}

void BlockInformationMatrix::scatter(const std::vector<int>& vars, const Eigen::MatrixXd& dense) {
  const auto off = local_offsets(*this, vars);
  for (std::size_t a = 0; a < vars.size(); ++a)
    for (std::size_t b = a; b < vars.size(); ++b) {
      const Eigen::MatrixXd M = dense.block(off[a], off[b], dims_[vars[a]], dims_[vars[b]]);
      if (a != b && M.isZero(0.0) && !linked(vars[a], vars[b])) continue;
      set(vars[a], vars[b], M);
    }
}

Eigen::MatrixXd BlockInformationMatrix::dense() const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(total_, total_);
  for (int i = 0; i < variables(); ++i)
    for (const auto& [j, M] : rows_[i]) out.block(offsets_[i], offsets_[j], dims_[i], dims_[j]) = M;
  return out;
}

std::size_t BlockInformationMatrix::blocks() const {
  std::size_t count = 0;
  for (const auto& row : rows_) count += row.size();
  return count;
}

// ---- Seif ----

Seif::Seif(std::string name, std::shared_ptr<const SlamModel> model, SeifSettings settings)
    : name_(std::move(name)), model_(std::move(model)), s_(checked(std::move(settings), "seif")) {
  const int p = model_->pose_dim();
  omega_.add_variable(p);
  omega_.set(kPose, kPose, Eigen::MatrixXd::Identity(p, p));
  xi_ = Eigen::VectorXd::Zero(p);
  mu_ = Eigen::VectorXd::Zero(p);
}

Eigen::MatrixXd Seif::covariance() const {
  const Eigen::MatrixXd dense = omega_.dense();
  return dense.llt().solve(Eigen::MatrixXd::Identity(dense.rows(), dense.cols()));
}

StepResult Seif::finish(StepStatus status, double seconds) {
  last_touched_ = omega_.touched();
  omega_.reset_touched();
  if (status == StepStatus::kOk && !mu_.allFinite()) status = StepStatus::kNotPositiveDefinite;
  return record(status, seconds);
}

void Seif::activate(int landmark) {
  active_.erase(std::remove(active_.begin(), active_.end(), landmark), active_.end());
  active_.push_back(landmark);
}

void Seif::shift_mean(int var, const Eigen::VectorXd& delta) {
  detail::shift_mean(omega_, xi_, mu_, var, delta);
}

void Seif::normalize_variable(int var) {
  detail::normalize_variable(*model_, omega_, xi_, mu_, var);
}

StepResult Seif::initialize(const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) {
  detail::StepClock clock;
  if (!detail::valid_state(*model_, x0, P0)) return finish(StepStatus::kInvalidInput, clock.seconds());
  if (!detail::information_from_moments(*model_, x0, P0, omega_, xi_, mu_))
    return finish(StepStatus::kCholeskyFailed, clock.seconds());
  active_.clear();
  for (int j : omega_.neighbours(kPose)) active_.push_back(j - 1);
  for (int v = 0; v < omega_.variables(); ++v) normalize_variable(v);
  if (!sparsify()) return finish(StepStatus::kSingularInnovation, clock.seconds());
  return finish(StepStatus::kOk, clock.seconds());
}

// eq. (4.109) in the constant-time form of the header comment (information_ops.hpp).
StepResult Seif::predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) {
  detail::StepClock clock;
  if (!detail::valid_control(*model_, u, Q)) return finish(StepStatus::kInvalidInput, clock.seconds());
  const StepStatus status = detail::information_motion_update(*model_, omega_, xi_, mu_, u, Q);
  if (status != StepStatus::kOk) return finish(status, clock.seconds());
  normalize_variable(kPose);
  return finish(StepStatus::kOk, clock.seconds());
}

// eq. (4.107), one observation at a time (all linearised at the prior mean, like the EKF batch).
StepResult Seif::update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                        const std::vector<int>& associations) {
  detail::StepClock clock;
  if (!detail::valid_observations(*model_, num_landmarks(), zs, R, associations))
    return finish(StepStatus::kInvalidInput, clock.seconds());
  if (zs.empty()) return finish(StepStatus::kOk, clock.seconds());
  Eigen::LLT<Eigen::MatrixXd> llt(symmetrized(R));
  if (llt.info() != Eigen::Success) return finish(StepStatus::kSingularInnovation, clock.seconds());
  const Eigen::MatrixXd Rinv = llt.solve(Eigen::MatrixXd::Identity(R.rows(), R.cols()));
  for (std::size_t j = 0; j < zs.size(); ++j) {
    detail::information_measurement(*model_, omega_, xi_, mu_, zs[j], Rinv, associations[j]);
    activate(associations[j]);
  }
  if (!recover_mean()) return finish(StepStatus::kNotPositiveDefinite, clock.seconds());
  if (s_.mean_recovery == "exact") {  // every mean moved: renormalise all, like the EKF
    for (int v = 1; v < omega_.variables(); ++v) normalize_variable(v);
  } else {
    for (int a : associations) normalize_variable(a + 1);
  }
  if (!sparsify()) return finish(StepStatus::kSingularInnovation, clock.seconds());
  return finish(StepStatus::kOk, clock.seconds());
}

StepResult Seif::augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) {
  detail::StepClock clock;
  if (!detail::valid_observation(*model_, z, R)) return finish(StepStatus::kInvalidInput, clock.seconds());
  const int var = detail::information_augment(*model_, omega_, xi_, mu_, z, R);
  if (var < 0) return finish(StepStatus::kSingularInnovation, clock.seconds());
  activate(var - 1);
  normalize_variable(var);
  if (!sparsify()) return finish(StepStatus::kSingularInnovation, clock.seconds());
  return finish(StepStatus::kOk, clock.seconds());
}

// eqs. (4.113)–(4.114).
bool Seif::sparsify() {
  const int limit = s_.max_active_landmarks;
  if (limit <= 0 || static_cast<int>(active_.size()) <= limit) return true;
  const std::size_t drop = active_.size() - static_cast<std::size_t>(limit);
  std::vector<int> y0;
  for (std::size_t i = 0; i < drop; ++i) y0.push_back(active_[i] + 1);
  std::vector<int> vars{kPose};
  for (int j : omega_.neighbours(kPose)) vars.push_back(j);
  for (int v : y0)
    if (std::find(vars.begin(), vars.end(), v) == vars.end()) vars.push_back(v);
  const Eigen::MatrixXd omega0 = omega_.gather(vars);  // Ω⁰: x, y⁺, y⁰ with y⁻ = 0
  std::vector<int> x_y0{kPose};
  x_y0.insert(x_y0.end(), y0.begin(), y0.end());
  Eigen::MatrixXd t1, t2, t3;
  if (!marginal_term(omega0, rows_of(omega_, vars, y0), &t1) ||
      !marginal_term(omega0, rows_of(omega_, vars, x_y0), &t2) ||
      !marginal_term(omega0, rows_of(omega_, vars, {kPose}), &t3))
    return false;
  const Eigen::MatrixXd omega_tilde = symmetrized(omega0 - t1 + t2 - t3);
  const Eigen::VectorXd dxi = (omega_tilde - omega0) * gather_vector(omega_, mu_, vars);
  omega_.scatter(vars, omega_tilde);
  for (int v : y0) omega_.erase(kPose, v);  // the pose–y⁰ links are zero by construction
  scatter_add_vector(omega_, dxi, vars, &xi_);
  active_.erase(active_.begin(), active_.begin() + static_cast<std::ptrdiff_t>(drop));
  return true;
}

bool Seif::recover_mean() {
  if (s_.mean_recovery == "exact") {
    Eigen::LLT<Eigen::MatrixXd> llt(omega_.dense());
    if (llt.info() != Eigen::Success) return false;
    mu_ = llt.solve(xi_);
  } else {
    std::vector<int> vars;
    for (int a : active_) vars.push_back(a + 1);
    vars.push_back(kPose);
    for (int sweep = 0; sweep < s_.relaxation_iterations; ++sweep)
      for (int i : vars) {  // Gauss–Seidel: μᵢ = Ωᵢᵢ⁻¹ (ξᵢ − Σⱼ Ωᵢⱼ μⱼ)
        Eigen::VectorXd rhs = xi_.segment(omega_.offset(i), omega_.dim(i));
        for (int j : omega_.neighbours(i))
          rhs -= omega_.block(i, j) * mu_.segment(omega_.offset(j), omega_.dim(j));
        Eigen::LLT<Eigen::MatrixXd> llt(omega_.block(i, i));
        if (llt.info() != Eigen::Success) return false;
        mu_.segment(omega_.offset(i), omega_.dim(i)) = llt.solve(rhs);
      }
  }
  normalize_variable(kPose);
  return mu_.allFinite();
}

}  // namespace sextant
