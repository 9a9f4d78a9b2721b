#include "sextant/features/plane_fit.hpp"

#include <Eigen/Eigenvalues>

namespace sextant {

Eigen::Matrix3d PointMoments::covariance() const {
  if (count < 2) return Eigen::Matrix3d::Zero();
  return scatter / static_cast<double>(count - 1);  // eq. (3.28)
}

void PointMoments::add(const Eigen::Vector3d& p) {
  ++count;
  const Eigen::Vector3d delta = p - centroid;
  centroid += delta / static_cast<double>(count);
  scatter += delta * (p - centroid).transpose();
}

PointMoments PointMoments::combine(const PointMoments& a, const PointMoments& b) {
  if (a.count == 0) return b;
  if (b.count == 0) return a;
  PointMoments out;
  out.count = a.count + b.count;
  const double ka = static_cast<double>(a.count), kb = static_cast<double>(b.count);
  const Eigen::Vector3d delta = b.centroid - a.centroid;
  out.centroid = a.centroid + delta * (kb / (ka + kb));
  out.scatter = a.scatter + b.scatter + delta * delta.transpose() * (ka * kb / (ka + kb));
  return out;
}

PointMoments PointMoments::from_covariance(std::size_t count, const Eigen::Vector3d& centroid,
                                           const Eigen::Matrix3d& covariance) {
  PointMoments out;
  out.count = count;
  out.centroid = centroid;
  out.scatter =
      count < 2 ? Eigen::Matrix3d::Zero() : Eigen::Matrix3d(covariance * static_cast<double>(count - 1));
  return out;
}

PointMoments compute_moments(PointsView points, const std::vector<std::size_t>& indices) {
  PointMoments m;
  if (indices.empty()) return m;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t i : indices) sum += points[i].cast<double>();
  m.count = indices.size();
  m.centroid = sum / static_cast<double>(m.count);
  for (std::size_t i : indices) {
    const Eigen::Vector3d q = points[i].cast<double>() - m.centroid;
    m.scatter.noalias() += q * q.transpose();
  }
  return m;
}

PointMoments compute_moments(const std::vector<Eigen::Vector3d>& points) {
  PointMoments m;
  for (const auto& p : points) m.add(p);
  return m;
}

bool from_string(const std::string& text, PlaneRefit* out) {
  return from_name(kPlaneRefitNames, text, out);
}

std::string to_string(PlaneRefit refit) {
  return name_of(kPlaneRefitNames, refit);
}

PlaneFit fit_plane_pca(const PointMoments& moments) {
  PlaneFit fit;
  fit.moments = moments;
  if (moments.count < 3 || !moments.scatter.allFinite()) return fit;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(moments.covariance());
  if (eig.info() != Eigen::Success) return fit;
  fit.eigenvalues = eig.eigenvalues();
  fit.axes = eig.eigenvectors();
  // A second eigenvalue of zero: the points lie on a line (or coincide); the plane is undefined.
  if (!(fit.eigenvalues(1) > 1e-12 * std::max(1.0, fit.eigenvalues(2)))) return fit;
  fit.plane.normal = fit.axes.col(0).normalized();  // smallest principal axis (§3.3.1.1)
  fit.plane.d = fit.plane.normal.dot(moments.centroid);
  fit.ok = true;
  return fit;
}

namespace {

// eqs. (3.23)–(3.25): β = right-singular vector of A = [x y z 1] for the smallest singular value,
// taken as the eigenvector of AᵀA (same vectors). β_a x + β_b y + β_c z + β_d = 0, eq. (3.22).
bool fit_plane_svd(PointsView points, const std::vector<std::size_t>& indices, Plane* plane) {
  Eigen::Matrix4d AtA = Eigen::Matrix4d::Zero();
  for (std::size_t i : indices) {
    const Eigen::Vector4d a(points[i].x(), points[i].y(), points[i].z(), 1.0);
    AtA.noalias() += a * a.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(AtA);
  if (eig.info() != Eigen::Success) return false;
  const Eigen::Vector4d beta = eig.eigenvectors().col(0);
  const double norm = beta.head<3>().norm();
  if (!(norm > 1e-12)) return false;
  plane->normal = beta.head<3>() / norm;
  plane->d = -beta(3) / norm;  // our form n·x = d
  return true;
}

}  // namespace

PlaneFit fit_plane(PointsView points, const std::vector<std::size_t>& indices, PlaneRefit method) {
  PlaneFit fit = fit_plane_pca(compute_moments(points, indices));
  if (!fit.ok || method == PlaneRefit::pca) return fit;
  Plane svd_plane;
  if (!fit_plane_svd(points, indices, &svd_plane)) {
    fit.ok = false;
    return fit;
  }
  fit.plane = svd_plane;
  return fit;
}

void orient_towards(Plane& plane, const Eigen::Vector3d& viewpoint) {
  // With n·x = d, the viewpoint is on the normal's side when n·v − d ≥ 0.
  if (plane.signed_distance(viewpoint) < 0.0) {
    plane.normal = -plane.normal;
    plane.d = -plane.d;
  }
}

}  // namespace sextant
