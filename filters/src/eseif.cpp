#include "sextant/filters/eseif.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "information_ops.hpp"
#include "sextant/core/checked_settings.hpp"
#include "sextant/filters/covariance.hpp"
#include "step_checks.hpp"

namespace sextant {
namespace {

using detail::kPose;

bool contains(const std::vector<int>& set, int v) {
  return std::find(set.begin(), set.end(), v) != set.end();
}

/// Full rank up to a relative tolerance (the pose is determined).
bool determined(const Eigen::MatrixXd& A) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& l = eig.eigenvalues();
  return l.allFinite() && l.maxCoeff() > 0.0 && l.minCoeff() > 1e-10 * l.maxCoeff();
}

double log_det(const Eigen::MatrixXd& A) {
  const Eigen::LLT<Eigen::MatrixXd> llt(A);
  if (llt.info() != Eigen::Success) return -std::numeric_limits<double>::infinity();
  return 2.0 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
}

}  // namespace

Eigen::MatrixXd information_marginal(const BlockInformationMatrix& omega, const std::vector<int>& vars) {
  return detail::sparse_marginal(omega, vars);
}

bool EseifSettings::valid(std::string* why) const {
  if (max_active_landmarks < 0)
    return *why = "max_active_landmarks must be >= 0 (0 = no relocalization)", false;
  if (relocation_landmarks < 1) return *why = "relocation_landmarks must be >= 1", false;
  if (max_active_landmarks > 0 && relocation_landmarks > max_active_landmarks)
    return *why = "relocation_landmarks must be <= max_active_landmarks", false;
  for (double s : relocation_prior)
    if (!(s > 0.0) || !std::isfinite(s)) return *why = "relocation_prior: every sigma must be > 0", false;
  if (mean_recovery != "local" && mean_recovery != "exact")
    return *why = "mean_recovery must be 'local' or 'exact'", false;
  return true;
}

Eseif::Eseif(std::string name, std::shared_ptr<const SlamModel> model, EseifSettings settings)
    : name_(std::move(name)), model_(std::move(model)), s_(checked(std::move(settings), "eseif")) {
  if (!s_.relocation_prior.empty() && static_cast<int>(s_.relocation_prior.size()) != model_->pose_dim())
    throw std::invalid_argument("Eseif: relocation_prior needs one sigma per pose entry");
  const int p = model_->pose_dim();
  omega_.add_variable(p);
  omega_.set(kPose, kPose, Eigen::MatrixXd::Identity(p, p));
  xi_ = Eigen::VectorXd::Zero(p);
  mu_ = Eigen::VectorXd::Zero(p);
}

std::vector<int> Eseif::active_landmarks() const {
  std::vector<int> out;
  for (int j : omega_.neighbours(kPose)) out.push_back(j - 1);
  return out;
}

Eigen::MatrixXd Eseif::covariance() const {
  const Eigen::MatrixXd dense = omega_.dense();
  return dense.llt().solve(Eigen::MatrixXd::Identity(dense.rows(), dense.cols()));
}

FilterDiagnostics Eseif::diagnostics() const {
  FilterDiagnostics d;
  d.information = &omega_;
  d.relocations = relocations_;
  d.skipped_relocations = skipped_;
  return d;
}

Eigen::MatrixXd Eseif::joint_covariance(const std::vector<int>& landmarks) const {
  std::vector<int> vars{kPose};
  for (int j : landmarks) {
    if (j < 0 || j >= num_landmarks())
      throw std::out_of_range("joint_covariance: no landmark " + std::to_string(j));
    vars.push_back(j + 1);
  }
  Eigen::MatrixXd out = information_marginal(omega_, vars);
  if (out.size() == 0) {
    const Eigen::Index n =
        model_->pose_dim() + model_->landmark_dim() * static_cast<Eigen::Index>(landmarks.size());
    out.setConstant(n, n, std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

StepResult Eseif::finish(StepStatus status, double seconds) {
  last_touched_ = omega_.touched();
  omega_.reset_touched();
  if (status == StepStatus::kOk && !mu_.allFinite()) status = StepStatus::kNotPositiveDefinite;
  return record(status, seconds);
}

void Eseif::normalize(int var) {
  detail::normalize_variable(*model_, omega_, xi_, mu_, var);
}

StepResult Eseif::initialize(const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0) {
  detail::StepClock clock;
  omega_.reset_touched();
  if (!detail::valid_state(*model_, x0, P0)) return finish(StepStatus::kInvalidInput, clock.seconds());
  if (!detail::information_from_moments(*model_, x0, P0, omega_, xi_, mu_))
    return finish(StepStatus::kCholeskyFailed, clock.seconds());
  held_.clear();
  for (int v = 0; v < omega_.variables(); ++v) normalize(v);
  return finish(StepStatus::kOk, clock.seconds());
}

// The paper's time projection = thesis eq. (4.109), after a pending relocalization.
StepResult Eseif::predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) {
  detail::StepClock clock;
  omega_.reset_touched();
  if (!detail::valid_control(*model_, u, Q)) return finish(StepStatus::kInvalidInput, clock.seconds());
  if (!relocate()) return finish(StepStatus::kNotPositiveDefinite, clock.seconds());
  const StepStatus status = detail::information_motion_update(*model_, omega_, xi_, mu_, u, Q);
  if (status != StepStatus::kOk) return finish(status, clock.seconds());
  normalize(kPose);
  return finish(StepStatus::kOk, clock.seconds());
}

// The paper's measurement update (thesis eq. 4.107) with z_α; z_β held out when the active set
// would exceed Γ_a.
StepResult Eseif::update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                         const std::vector<int>& associations) {
  detail::StepClock clock;
  omega_.reset_touched();
  if (!detail::valid_observations(*model_, num_landmarks(), zs, R, associations))
    return finish(StepStatus::kInvalidInput, clock.seconds());
  if (!relocate()) return finish(StepStatus::kNotPositiveDefinite, clock.seconds());
  if (zs.empty()) return finish(StepStatus::kOk, clock.seconds());
  Eigen::LLT<Eigen::MatrixXd> llt(symmetrized(R));
  if (llt.info() != Eigen::Success) return finish(StepStatus::kSingularInnovation, clock.seconds());
  const Eigen::MatrixXd Rinv = llt.solve(Eigen::MatrixXd::Identity(R.rows(), R.cols()));
  std::vector<int> linked = omega_.neighbours(kPose);
  for (int a : associations)
    if (!contains(linked, a + 1)) linked.push_back(a + 1);
  std::vector<std::size_t> beta;
  if (s_.max_active_landmarks > 0 && static_cast<int>(linked.size()) > s_.max_active_landmarks) {
    beta = choose_relocation(zs, associations, Rinv);
    if (beta.empty()) ++skipped_;
  }
  std::vector<int> observed;
  for (std::size_t j = 0; j < zs.size(); ++j) {
    if (std::find(beta.begin(), beta.end(), j) != beta.end()) {
      held_.push_back({zs[j], associations[j]});
      continue;
    }
    detail::information_measurement(*model_, omega_, xi_, mu_, zs[j], Rinv, associations[j]);
    observed.push_back(associations[j] + 1);
  }
  held_R_ = R;
  if (!recover_mean(observed)) return finish(StepStatus::kNotPositiveDefinite, clock.seconds());
  if (s_.mean_recovery == "exact") {
    for (int v = 1; v < omega_.variables(); ++v) normalize(v);
  } else {
    for (int v : observed) normalize(v);
  }
  normalize(kPose);
  return finish(StepStatus::kOk, clock.seconds());
}

StepResult Eseif::augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) {
  detail::StepClock clock;
  omega_.reset_touched();
  if (!detail::valid_observation(*model_, z, R)) return finish(StepStatus::kInvalidInput, clock.seconds());
  const int var = detail::information_augment(*model_, omega_, xi_, mu_, z, R);
  if (var < 0) return finish(StepStatus::kSingularInnovation, clock.seconds());
  normalize(var);
  return finish(StepStatus::kOk, clock.seconds());
}

// Greedy choice of z_β: each step adds the measurement that most increases log det of the pose
// information A = Π + Σ H_xᵀ R⁻¹ H_x (Π: the relocation prior); relocation_landmarks of them, more
// (up to Γ_a) while A is singular without a prior.
std::vector<std::size_t> Eseif::choose_relocation(const std::vector<Eigen::VectorXd>& zs,
                                                  const std::vector<int>& associations,
                                                  const Eigen::MatrixXd& Rinv) const {
  const int p = model_->pose_dim();
  const Eigen::VectorXd pose = mu_.head(p);
  std::vector<Eigen::MatrixXd> info;
  double scale = 0.0;
  for (std::size_t j = 0; j < zs.size(); ++j) {
    const Eigen::VectorXd m = mu_.segment(omega_.offset(associations[j] + 1), model_->landmark_dim());
    const Eigen::MatrixXd Hx = model_->observe_jacobian_pose(pose, m);
    info.push_back(Hx.transpose() * Rinv * Hx);
    scale = std::max(scale, info.back().trace());
  }
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p, p);
  for (std::size_t i = 0; i < s_.relocation_prior.size(); ++i)
    A(i, i) = 1.0 / (s_.relocation_prior[i] * s_.relocation_prior[i]);
  const Eigen::MatrixXd ridge = 1e-9 * std::max(scale, 1e-12) * Eigen::MatrixXd::Identity(p, p);
  const std::size_t wanted = static_cast<std::size_t>(s_.relocation_landmarks);
  const std::size_t most = std::min(zs.size(), static_cast<std::size_t>(s_.max_active_landmarks));
  std::vector<std::size_t> chosen;
  while (chosen.size() < most && (chosen.size() < wanted || !determined(A))) {
    std::size_t best = zs.size();
    double best_value = -std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < zs.size(); ++j) {
      if (std::find(chosen.begin(), chosen.end(), j) != chosen.end()) continue;
      const double value = log_det(A + info[j] + ridge);
      if (best == zs.size() || value > best_value) best = j, best_value = value;
    }
    chosen.push_back(best);
    A += info[best];
  }
  if (!determined(A)) return {};
  return chosen;
}

bool Eseif::relocate() {
  if (held_.empty()) return true;
  const int p = model_->pose_dim(), l = model_->landmark_dim();
  // Marginalise the pose (the paper's marginalisation step) over the pose and its neighbours.
  const std::vector<int> vars = detail::pose_and_neighbours(omega_);
  const std::vector<int> active(vars.begin() + 1, vars.end());
  const Eigen::MatrixXd D = omega_.gather(vars);
  const Eigen::Index k = D.rows() - p;
  Eigen::LLT<Eigen::MatrixXd> lxx(D.topLeftCorner(p, p));
  if (lxx.info() != Eigen::Success) return false;
  const Eigen::MatrixXd Lax = D.bottomLeftCorner(k, p);
  const Eigen::MatrixXd Laa = symmetrized(D.bottomRightCorner(k, k) - Lax * lxx.solve(Lax.transpose()));
  const Eigen::VectorXd dxi = -Lax * lxx.solve(xi_.head(p));
  for (int j : active) omega_.erase(kPose, j);
  omega_.scatter(active, Laa);
  detail::scatter_add_vector(omega_, dxi, active, &xi_);
  const Eigen::VectorXd last_pose = mu_.head(p);

  // Relocalize, x = G(m_β, z_β) + v: Gauss–Newton for the least-squares pose from z_β (and the prior).
  Eigen::LLT<Eigen::MatrixXd> lr(symmetrized(held_R_));
  const Eigen::MatrixXd Rinv = lr.solve(Eigen::MatrixXd::Identity(held_R_.rows(), held_R_.cols()));
  Eigen::MatrixXd prior = Eigen::MatrixXd::Zero(p, p);
  for (std::size_t i = 0; i < s_.relocation_prior.size(); ++i)
    prior(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)) =
        1.0 / (s_.relocation_prior[i] * s_.relocation_prior[i]);
  std::vector<int> beta;  // distinct landmark variables of z_β
  for (const Held& h : held_)
    if (!contains(beta, h.landmark + 1)) beta.push_back(h.landmark + 1);
  const auto landmark = [&](int var) { return Eigen::VectorXd(mu_.segment(omega_.offset(var), l)); };
  Eigen::VectorXd x = last_pose;
  Eigen::MatrixXd A(p, p), C(p, l * static_cast<Eigen::Index>(beta.size()));
  for (int iteration = 0; iteration < 20; ++iteration) {
    A = prior;
    C.setZero();
    Eigen::VectorXd back = last_pose - x;
    wrap_entries(back, model_->pose_angles());
    Eigen::VectorXd g = prior * back;
    for (const Held& h : held_) {
      const Eigen::VectorXd m = landmark(h.landmark + 1);
      const Eigen::VectorXd predicted = model_->observe(x, m);
      Eigen::VectorXd r = model_->align_observation(h.z, predicted) - predicted;
      wrap_entries(r, model_->observation_angles());
      const Eigen::MatrixXd Hx = model_->observe_jacobian_pose(x, m);
      const Eigen::MatrixXd Hm = model_->observe_jacobian_landmark(x, m);
      A += Hx.transpose() * Rinv * Hx;
      g += Hx.transpose() * Rinv * r;
      const auto at = std::find(beta.begin(), beta.end(), h.landmark + 1) - beta.begin();
      C.middleCols(l * at, l) += Hx.transpose() * Rinv * Hm;
    }
    Eigen::LLT<Eigen::MatrixXd> la(symmetrized(A));
    if (la.info() != Eigen::Success) return false;
    const Eigen::VectorXd dx = la.solve(g);
    if (!dx.allFinite()) return false;
    x += dx;
    wrap_entries(x, model_->pose_angles());
    if (dx.norm() < 1e-12 * (1.0 + x.norm())) break;
  }
  // The factor of x = G(m_β) + v in information form (A, C, Cᵀ A⁻¹ C at x, μ_β) with ξ = Ω μ.
  Eigen::LLT<Eigen::MatrixXd> la(symmetrized(A));
  if (la.info() != Eigen::Success) return false;
  const Eigen::MatrixXd Lbb = symmetrized(C.transpose() * la.solve(C));
  const Eigen::VectorXd mu_beta = detail::gather_vector(omega_, mu_, beta);
  omega_.set(kPose, kPose, symmetrized(A));
  for (std::size_t a = 0; a < beta.size(); ++a) {
    omega_.set(kPose, beta[a], C.middleCols(l * static_cast<Eigen::Index>(a), l));
    for (std::size_t b = 0; b < beta.size(); ++b)
      if (a <= b)
        omega_.add(beta[a], beta[b],
                   Lbb.block(l * static_cast<Eigen::Index>(a), l * static_cast<Eigen::Index>(b), l, l));
  }
  xi_.head(p) = A * x + C * mu_beta;
  detail::scatter_add_vector(omega_, C.transpose() * x + Lbb * mu_beta, beta, &xi_);
  mu_.head(p) = x;
  held_.clear();
  ++relocations_;
  normalize(kPose);
  return true;
}

bool Eseif::recover_mean(const std::vector<int>& observed) {
  if (s_.mean_recovery == "exact") {
    Eigen::VectorXd mu;
    if (!detail::sparse_solve(omega_, xi_, &mu)) return false;
    mu_ = mu;
    return mu_.allFinite();
  }
  // Local: L = pose, its neighbours, the observed landmarks and their neighbours; the rest fixed.
  std::vector<int> L = detail::pose_and_neighbours(omega_);
  for (int v : observed) {
    if (!contains(L, v)) L.push_back(v);
    for (int n : omega_.neighbours(v))
      if (!contains(L, n)) L.push_back(n);
  }
  const Eigen::MatrixXd D = omega_.gather(L);
  Eigen::VectorXd rhs = detail::gather_vector(omega_, xi_, L);
  const auto off = detail::local_offsets(omega_, L);
  for (std::size_t i = 0; i < L.size(); ++i)
    for (int j : omega_.neighbours(L[i]))
      if (!contains(L, j))
        rhs.segment(off[i], omega_.dim(L[i])) -=
            omega_.block(L[i], j) * mu_.segment(omega_.offset(j), omega_.dim(j));
  Eigen::LLT<Eigen::MatrixXd> llt(D);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::VectorXd local = llt.solve(rhs);
  if (!local.allFinite()) return false;
  for (std::size_t i = 0; i < L.size(); ++i)
    mu_.segment(omega_.offset(L[i]), omega_.dim(L[i])) = local.segment(off[i], omega_.dim(L[i]));
  return true;
}

}  // namespace sextant
