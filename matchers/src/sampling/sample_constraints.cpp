#include "sextant/matchers/sample_constraints.hpp"

#include <cmath>
#include <cstdio>

#include <Eigen/Eigenvalues>

namespace sextant {
namespace {

std::string share(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", value);
  return buf;
}

}  // namespace

bool ConstraintThresholds::valid(std::string* why) const {
  const auto fail = [why](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(min_normal_spread >= 0.0 && min_normal_spread <= 1.0 / 3.0))
    return fail("min_normal_spread must lie in [0, 1/3]");
  if (!(min_information_ratio >= 0.0 && min_information_ratio <= 1.0))
    return fail("min_information_ratio must lie in [0, 1]");
  return true;
}

ConstraintCheck check_plane_constraints(const std::vector<PlaneLandmark>& planes, const PointCloud& cloud,
                                        const ConstraintThresholds& thresholds) {
  ConstraintCheck check;
  check.planes = planes.size();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  Eigen::Matrix3d normals = Eigen::Matrix3d::Zero();
  for (const PlaneLandmark& plane : planes) {
    for (std::size_t i : plane.inliers) {
      if (i >= cloud.size()) continue;
      centroid += cloud[i].cast<double>();
      normals += plane.plane.normal * plane.plane.normal.transpose();
      ++check.inliers;
    }
  }
  if (check.inliers == 0) {
    check.reason = "no plane inliers";
    return check;
  }
  const double n = static_cast<double>(check.inliers);
  centroid /= n;
  check.normal_spread = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(normals / n).eigenvalues();

  double radius2 = 0.0;
  for (const PlaneLandmark& plane : planes)
    for (std::size_t i : plane.inliers)
      if (i < cloud.size()) radius2 += (cloud[i].cast<double>() - centroid).squaredNorm();
  const double radius = std::max(std::sqrt(radius2 / n), 1e-6);

  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  for (const PlaneLandmark& plane : planes) {
    const Eigen::Vector3d& normal = plane.plane.normal;
    for (std::size_t i : plane.inliers) {
      if (i >= cloud.size()) continue;
      Eigen::Matrix<double, 6, 1> J;
      J << normal, (cloud[i].cast<double>() - centroid).cross(normal) / radius;
      A.noalias() += J * J.transpose();
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(A / n);
  const double largest = eig.eigenvalues()[5];
  check.information_ratio = largest > 0.0 ? std::max(0.0, eig.eigenvalues()[0]) / largest : 0.0;
  check.weakest_direction = eig.eigenvectors().col(0);

  if (check.planes < thresholds.min_planes) {
    check.reason =
        std::to_string(check.planes) + " planes (fewer than " + std::to_string(thresholds.min_planes) + ")";
  } else if (check.inliers < thresholds.min_inliers) {
    check.reason = std::to_string(check.inliers) + " plane inliers (fewer than " +
                   std::to_string(thresholds.min_inliers) + ")";
  } else if (check.normal_spread[0] < thresholds.min_normal_spread) {
    check.reason =
        "normals span fewer than three directions (smallest share " + share(check.normal_spread[0]) + ")";
  } else if (check.information_ratio < thresholds.min_information_ratio) {
    check.reason =
        "a pose direction is nearly unconstrained (information ratio " + share(check.information_ratio) + ")";
  } else {
    check.constrains_all = true;
  }
  return check;
}

}  // namespace sextant
