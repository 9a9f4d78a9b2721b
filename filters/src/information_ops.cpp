#include "information_ops.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "sextant/filters/covariance.hpp"

namespace sextant::detail {
namespace {

Eigen::SparseMatrix<double> to_sparse(const BlockInformationMatrix& omega) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < omega.variables(); ++i) {
    const std::vector<int> row = [&] {
      std::vector<int> r = omega.neighbours(i);
      r.push_back(i);
      return r;
    }();
    for (int j : row) {
      const Eigen::MatrixXd M = omega.block(i, j);
      for (Eigen::Index a = 0; a < M.rows(); ++a)
        for (Eigen::Index b = 0; b < M.cols(); ++b)
          if (M(a, b) != 0.0) entries.emplace_back(omega.offset(i) + a, omega.offset(j) + b, M(a, b));
    }
  }
  Eigen::SparseMatrix<double> S(omega.size(), omega.size());
  S.setFromTriplets(entries.begin(), entries.end());
  return S;
}

}  // namespace

std::vector<Eigen::Index> local_offsets(const BlockInformationMatrix& omega, const std::vector<int>& vars) {
  std::vector<Eigen::Index> off(vars.size() + 1, 0);
  for (std::size_t i = 0; i < vars.size(); ++i) off[i + 1] = off[i] + omega.dim(vars[i]);
  return off;
}

Eigen::VectorXd gather_vector(const BlockInformationMatrix& omega, const Eigen::VectorXd& v,
                              const std::vector<int>& vars) {
  const auto off = local_offsets(omega, vars);
  Eigen::VectorXd out(off.back());
  for (std::size_t i = 0; i < vars.size(); ++i)
    out.segment(off[i], omega.dim(vars[i])) = v.segment(omega.offset(vars[i]), omega.dim(vars[i]));
  return out;
}

void scatter_add_vector(const BlockInformationMatrix& omega, const Eigen::VectorXd& local,
                        const std::vector<int>& vars, Eigen::VectorXd* v) {
  const auto off = local_offsets(omega, vars);
  for (std::size_t i = 0; i < vars.size(); ++i)
    v->segment(omega.offset(vars[i]), omega.dim(vars[i])) += local.segment(off[i], omega.dim(vars[i]));
}

std::vector<int> pose_and_neighbours(const BlockInformationMatrix& omega) {
  std::vector<int> vars{kPose};
  for (int j : omega.neighbours(kPose)) vars.push_back(j);
  return vars;
}

StepStatus information_motion_update(const SlamModel& model, BlockInformationMatrix& omega,
                                     Eigen::VectorXd& xi, Eigen::VectorXd& mu, const Eigen::VectorXd& u,
                                     const Eigen::MatrixXd& Q) {
  const int p = model.pose_dim();
  const Eigen::VectorXd pose = mu.head(p);
  const Eigen::MatrixXd F = model.process_jacobian_pose(pose, u);
  const Eigen::MatrixXd G = model.process_jacobian_control(pose, u);
  const Eigen::MatrixXd U = G * Q * G.transpose();
  Eigen::VectorXd delta = model.process(pose, u) - pose;
  wrap_entries(delta, model.pose_angles());
  Eigen::FullPivLU<Eigen::MatrixXd> lu(F);
  if (!lu.isInvertible()) return StepStatus::kCholeskyFailed;
  const Eigen::MatrixXd M = lu.inverse();

  const std::vector<int> vars = pose_and_neighbours(omega);
  const Eigen::MatrixXd dense = omega.gather(vars);
  const Eigen::Index k = dense.rows();
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(k, k);
  T.topLeftCorner(p, p) = M;
  const Eigen::MatrixXd phi = T.transpose() * dense * T;  // Φ = (I+A)⁻ᵀ Ω (I+A)⁻¹
  Eigen::MatrixXd inner = Eigen::MatrixXd::Identity(p, p) + phi.topLeftCorner(p, p) * U;
  Eigen::FullPivLU<Eigen::MatrixXd> inner_lu(inner);
  if (!inner_lu.isInvertible()) return StepStatus::kSingularInnovation;
  const Eigen::MatrixXd W = U * inner_lu.inverse();  // U (I + Φ_vv U)⁻¹
  const Eigen::MatrixXd omega_bar = symmetrized(phi - phi.leftCols(p) * W * phi.topRows(p));
  const Eigen::VectorXd mu_local = gather_vector(omega, mu, vars);
  const Eigen::VectorXd dxi = (omega_bar - dense) * mu_local + omega_bar.leftCols(p) * delta;
  omega.scatter(vars, omega_bar);
  scatter_add_vector(omega, dxi, vars, &xi);
  mu.head(p) += delta;
  return StepStatus::kOk;
}

void information_measurement(const SlamModel& model, BlockInformationMatrix& omega, Eigen::VectorXd& xi,
                             const Eigen::VectorXd& mu, const Eigen::VectorXd& z, const Eigen::MatrixXd& Rinv,
                             int landmark) {
  const int p = model.pose_dim(), l = model.landmark_dim(), var = landmark + 1;
  const Eigen::VectorXd pose = mu.head(p);
  const Eigen::VectorXd m = mu.segment(omega.offset(var), l);
  const Eigen::VectorXd predicted = model.observe(pose, m);
  Eigen::VectorXd nu = model.align_observation(z, predicted) - predicted;
  wrap_entries(nu, model.observation_angles());
  const Eigen::MatrixXd Hp = model.observe_jacobian_pose(pose, m);
  const Eigen::MatrixXd Hl = model.observe_jacobian_landmark(pose, m);
  const Eigen::VectorXd target = Rinv * (nu + Hp * pose + Hl * m);
  omega.add(kPose, kPose, Hp.transpose() * Rinv * Hp);
  omega.add(kPose, var, Hp.transpose() * Rinv * Hl);
  omega.add(var, var, Hl.transpose() * Rinv * Hl);
  xi.head(p) += Hp.transpose() * target;
  xi.segment(omega.offset(var), l) += Hl.transpose() * target;
}

int information_augment(const SlamModel& model, BlockInformationMatrix& omega, Eigen::VectorXd& xi,
                        Eigen::VectorXd& mu, const Eigen::VectorXd& z, const Eigen::MatrixXd& R) {
  const int p = model.pose_dim(), l = model.landmark_dim();
  const Eigen::VectorXd pose = mu.head(p);
  const Eigen::MatrixXd Gv = model.augment_jacobian_pose(pose, z);
  const Eigen::MatrixXd Gz = model.augment_jacobian_observation(pose, z);
  Eigen::LLT<Eigen::MatrixXd> llt(symmetrized(Gz * R * Gz.transpose()));
  if (llt.info() != Eigen::Success) return -1;
  const Eigen::MatrixXd Sinv = llt.solve(Eigen::MatrixXd::Identity(l, l));
  const Eigen::VectorXd m = model.augment(pose, z);
  const Eigen::VectorXd c = m - Gv * pose;
  const int var = omega.add_variable(l);
  omega.add(var, var, Sinv);
  omega.add(var, kPose, -Sinv * Gv);
  omega.add(kPose, kPose, Gv.transpose() * Sinv * Gv);
  xi.conservativeResize(omega.size());
  mu.conservativeResize(omega.size());
  xi.tail(l) = Sinv * c;
  xi.head(p) -= Gv.transpose() * Sinv * c;
  mu.tail(l) = m;
  return var;
}

void shift_mean(const BlockInformationMatrix& omega, Eigen::VectorXd& xi, Eigen::VectorXd& mu, int var,
                const Eigen::VectorXd& delta) {
  if (delta.isZero(0.0)) return;
  mu.segment(omega.offset(var), omega.dim(var)) += delta;
  xi.segment(omega.offset(var), omega.dim(var)) += omega.block(var, var) * delta;
  for (int j : omega.neighbours(var))
    xi.segment(omega.offset(j), omega.dim(j)) += omega.block(j, var) * delta;
}

void normalize_variable(const SlamModel& model, const BlockInformationMatrix& omega, Eigen::VectorXd& xi,
                        Eigen::VectorXd& mu, int var) {
  Eigen::VectorXd value = mu.segment(omega.offset(var), omega.dim(var));
  const Eigen::VectorXd before = value;
  if (var == kPose)
    wrap_entries(value, model.pose_angles());
  else
    model.normalize_landmark(value);
  shift_mean(omega, xi, mu, var, value - before);
}

bool information_from_moments(const SlamModel& model, const Eigen::VectorXd& x0, const Eigen::MatrixXd& P0,
                              BlockInformationMatrix& omega, Eigen::VectorXd& xi, Eigen::VectorXd& mu) {
  Eigen::LLT<Eigen::MatrixXd> llt(symmetrized(P0));
  if (llt.info() != Eigen::Success) return false;
  const Eigen::MatrixXd info = llt.solve(Eigen::MatrixXd::Identity(P0.rows(), P0.cols()));
  omega = BlockInformationMatrix();
  omega.add_variable(model.pose_dim());
  for (int i = 0; i < landmark_count(model, x0.size()); ++i) omega.add_variable(model.landmark_dim());
  for (int i = 0; i < omega.variables(); ++i)
    for (int j = i; j < omega.variables(); ++j) {
      const Eigen::MatrixXd M = info.block(omega.offset(i), omega.offset(j), omega.dim(i), omega.dim(j));
      if (i == j || !M.isZero(0.0)) omega.set(i, j, M);
    }
  mu = x0;
  xi = info * x0;
  return true;
}

bool sparse_solve(const BlockInformationMatrix& omega, const Eigen::VectorXd& b, Eigen::VectorXd* x) {
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(to_sparse(omega));
  if (llt.info() != Eigen::Success) return false;
  *x = llt.solve(b);
  return llt.info() == Eigen::Success && x->allFinite();
}

Eigen::MatrixXd sparse_marginal(const BlockInformationMatrix& omega, const std::vector<int>& vars) {
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(to_sparse(omega));
  if (llt.info() != Eigen::Success) return {};
  const auto off = local_offsets(omega, vars);
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(omega.size(), off.back());
  for (std::size_t i = 0; i < vars.size(); ++i)
    E.block(omega.offset(vars[i]), off[i], omega.dim(vars[i]), omega.dim(vars[i])).setIdentity();
  const Eigen::MatrixXd X = llt.solve(E);
  Eigen::MatrixXd out(off.back(), off.back());
  for (std::size_t i = 0; i < vars.size(); ++i)
    out.middleRows(off[i], omega.dim(vars[i])) = X.middleRows(omega.offset(vars[i]), omega.dim(vars[i]));
  if (!out.allFinite()) return {};
  return symmetrized(out);
}

}  // namespace sextant::detail
