#include "sextant/features/landmark.hpp"

#include <cmath>

namespace sextant {

PlaneLandmark PlaneLandmark::transformed(const Eigen::Isometry3d& T) const {
  const Eigen::Matrix3d R = T.linear();
  const Eigen::Vector3d t = T.translation();
  PlaneLandmark out = *this;
  out.plane = plane.transformed(T);                 // eqs. (4.57)–(4.58)
  out.covariance = R * covariance * R.transpose();  // eq. (4.59), with the Rᵀ
  out.centroid = R * centroid + t;                  // eq. (4.60)
  for (auto& p : out.hull) p = R * p + t;           // eq. (4.61)
  for (auto& p : out.rectangle) p = R * p + t;
  return out;
}

std::vector<PlaneLandmark> transform_landmarks(const std::vector<PlaneLandmark>& landmarks,
                                               const Eigen::Isometry3d& T) {
  std::vector<PlaneLandmark> out;
  out.reserve(landmarks.size());
  for (const auto& l : landmarks) out.push_back(l.transformed(T));
  return out;
}

PlaneLandmark make_landmark(PointsView points, std::vector<std::size_t> inliers, const PlaneFit& fit,
                            const Eigen::Vector3d& viewpoint) {
  PlaneLandmark l;
  l.plane = fit.plane;
  orient_towards(l.plane, viewpoint);
  l.centroid = fit.moments.centroid;
  l.covariance = fit.moments.covariance();
  l.inlier_count = fit.moments.count;
  std::vector<Eigen::Vector3d> inlier_points;
  inlier_points.reserve(inliers.size());
  for (std::size_t i : inliers) inlier_points.push_back(points[i].cast<double>());
  const PlaneOutline outline =
      compute_outline(inlier_points, principal_frame(l.centroid, l.plane.normal, fit.axes.col(2)));
  l.hull = outline.hull;
  l.rectangle = outline.rectangle;
  l.area = outline.area;
  l.inliers = std::move(inliers);
  return l;
}

double tilt_from_horizontal_deg(const Plane& plane) {
  const double c = std::min(1.0, std::abs(plane.normal.z()));
  return std::acos(c) * 180.0 / M_PI;
}

}  // namespace sextant
