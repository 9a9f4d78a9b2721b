#include <functional>

#include <Eigen/Cholesky>

#include "sextant/filters/covariance.hpp"
#include "sextant/filters/gaussian_filters.hpp"
#include "step_checks.hpp"

namespace sextant {
namespace {

using Function = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

struct Transformed {
  Eigen::VectorXd mean;   ///< ȳ
  Eigen::MatrixXd cov;    ///< P_yy (noise not included)
  Eigen::MatrixXd cross;  ///< P_xy
};

// The sigma-point transform shared by prediction, update and augmentation (ukf_calc of
// Table 4.2; eqs. 4.74–4.76, 4.91, 4.93). Output angles are averaged through residuals to
// y(x̄) so that points on both sides of ±π average correctly. False when chol(P) fails.
bool transform(const Eigen::VectorXd& mean, const Eigen::MatrixXd& P, const SigmaPoints& sp,
               const Function& g, const std::vector<int>& output_angles, int angle_period, Transformed* out) {
  Eigen::MatrixXd L;
  if (!cholesky_lower(P, &L)) return false;
  const Eigen::MatrixXd offsets = L * sp.xi;  // χᵢ − x̄
  const Eigen::VectorXd reference = g(mean);
  const Eigen::Index m = reference.size(), count = sp.xi.cols();
  auto wrap_residual = [&](Eigen::Ref<Eigen::VectorXd> r) {
    for (Eigen::Index block = 0; angle_period > 0 && block + angle_period <= m; block += angle_period)
      wrap_entries(r, output_angles, block);
    if (angle_period == 0) wrap_entries(r, output_angles);
  };
  Eigen::MatrixXd residuals(m, count);
  for (Eigen::Index i = 0; i < count; ++i) {
    residuals.col(i) = g(mean + offsets.col(i)) - reference;
    wrap_residual(residuals.col(i));
  }
  const Eigen::VectorXd shift = residuals * sp.wm;
  out->mean = reference + shift;
  residuals.colwise() -= shift;
  for (Eigen::Index i = 0; i < count; ++i) wrap_residual(residuals.col(i));
  const Eigen::MatrixXd weighted = residuals * sp.wc.asDiagonal();
  out->cov = weighted * residuals.transpose();
  out->cross = offsets * weighted.transpose();
  return out->mean.allFinite() && out->cov.allFinite();
}

Eigen::MatrixXd block_join(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(A.rows() + B.rows(), A.cols() + B.cols());
  J.topLeftCorner(A.rows(), A.cols()) = A;
  J.bottomRightCorner(B.rows(), B.cols()) = B;
  return J;
}

}  // namespace

SigmaPointFilter::SigmaPointFilter(std::string name, std::shared_ptr<const SlamModel> model,
                                   std::unique_ptr<SigmaPointRule> rule, GaussianFilterSettings settings,
                                   std::uint64_t seed)
    : MomentFilter(std::move(model), settings), name_(std::move(name)), rule_(std::move(rule)), rng_(seed) {}

// Table 4.2 prediction / eqs. (4.73)–(4.76) / (4.99)–(4.100): the state is augmented with u.
StepResult SigmaPointFilter::predict(const Eigen::VectorXd& u, const Eigen::MatrixXd& Q) {
  detail::StepClock clock;
  if (!detail::valid_control(*model_, u, Q)) return record(StepStatus::kInvalidInput, clock.seconds());
  const int p = model_->pose_dim(), c = model_->control_dim();
  const Eigen::Index n = x_.size();
  Eigen::VectorXd joint(n + c);
  joint << x_, u;
  const Function g = [&](const Eigen::VectorXd& a) {
    Eigen::VectorXd y = a.head(n);
    y.head(p) = model_->process(a.head(p), a.tail(c));
    return y;
  };
  Transformed t;
  if (!transform(joint, block_join(P_, Q), rule_->generate(static_cast<int>(n + c), rng_), g,
                 model_->pose_angles(), 0, &t))
    return record(StepStatus::kCholeskyFailed, clock.seconds());
  x_ = t.mean;
  P_ = t.cov;
  return record(finish_step(), clock.seconds());
}

// Table 4.2 measurement update / eqs. (4.77)–(4.81) / (4.92)–(4.95).
StepResult SigmaPointFilter::update(const std::vector<Eigen::VectorXd>& zs, const Eigen::MatrixXd& R,
                                    const std::vector<int>& associations) {
  detail::StepClock clock;
  if (!detail::valid_observations(*model_, num_landmarks(), zs, R, associations))
    return record(StepStatus::kInvalidInput, clock.seconds());
  if (zs.empty()) return record(StepStatus::kOk, clock.seconds());
  const int p = model_->pose_dim(), l = model_->landmark_dim(), od = model_->observation_dim();
  const int count = static_cast<int>(zs.size());
  const Function h = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd z(static_cast<Eigen::Index>(count) * od);
    for (int j = 0; j < count; ++j)
      z.segment(j * od, od) =
          model_->observe(x.head(p), x.segment(landmark_offset(*model_, associations[j]), l));
    return z;
  };
  Transformed t;
  if (!transform(x_, P_, rule_->generate(static_cast<int>(x_.size()), rng_), h, model_->observation_angles(),
                 od, &t))
    return record(StepStatus::kCholeskyFailed, clock.seconds());
  Eigen::VectorXd innovation(t.mean.size());
  for (int j = 0; j < count; ++j) {
    const Eigen::VectorXd predicted = t.mean.segment(j * od, od);
    Eigen::VectorXd nu = model_->align_observation(zs[j], predicted) - predicted;
    wrap_entries(nu, model_->observation_angles());
    innovation.segment(j * od, od) = nu;
  }
  const Eigen::MatrixXd Pzz = symmetrized(t.cov + block_diagonal(R, count));
  Eigen::LLT<Eigen::MatrixXd> llt(Pzz);
  if (llt.info() != Eigen::Success) return record(StepStatus::kSingularInnovation, clock.seconds());
  const Eigen::MatrixXd K = llt.solve(t.cross.transpose()).transpose();  // K = P_xz P_zz⁻¹
  x_ += K * innovation;
  P_ -= K * Pzz * K.transpose();
  return record(finish_step(), clock.seconds());
}

// Table 4.3 / eq. (4.103): the state is augmented with z and passed through g^a = [x; g(x_v, z)].
StepResult SigmaPointFilter::augment(const Eigen::VectorXd& z, const Eigen::MatrixXd& R) {
  detail::StepClock clock;
  if (!detail::valid_observation(*model_, z, R)) return record(StepStatus::kInvalidInput, clock.seconds());
  const int p = model_->pose_dim(), l = model_->landmark_dim(), od = model_->observation_dim();
  const Eigen::Index n = x_.size();
  Eigen::VectorXd joint(n + od);
  joint << x_, z;
  const Function g = [&](const Eigen::VectorXd& a) {
    Eigen::VectorXd y(n + l);
    y << a.head(n), model_->augment(a.head(p), a.tail(od));
    return y;
  };
  Transformed t;
  if (!transform(joint, block_join(P_, R), rule_->generate(static_cast<int>(n + od), rng_), g,
                 model_->pose_angles(), 0, &t))
    return record(StepStatus::kCholeskyFailed, clock.seconds());
  x_ = t.mean;
  P_ = t.cov;
  return record(finish_step(), clock.seconds());
}

}  // namespace sextant
