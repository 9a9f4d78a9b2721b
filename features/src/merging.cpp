#include "sextant/features/merging.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "sextant/core/units.hpp"

namespace sextant {

namespace {

double orientation_deg(const PlaneLandmark& a, const PlaneLandmark& b) {
  return std::acos(std::clamp(a.plane.normal.dot(b.plane.normal), -1.0, 1.0)) * kDegPerRad;
}

// C_t uses the normal of the plane with more inliers (the better estimate), so the test is symmetric.
double translation(const PlaneLandmark& a, const PlaneLandmark& b) {
  const Eigen::Vector3d& n = a.inlier_count >= b.inlier_count ? a.plane.normal : b.plane.normal;
  return std::abs(n.dot(a.centroid - b.centroid));
}

// sqrt((cᵢ − cⱼ)ᵀ Σ_p⁻¹ (cᵢ − cⱼ)) with Σ_p of eq. (4.53), regularised by min_variance·I.
double closeness(const PlaneLandmark& a, const PlaneLandmark& b, double min_variance) {
  const double ka = static_cast<double>(a.inlier_count), kb = static_cast<double>(b.inlier_count);
  const double wa = ka + kb > 0.0 ? ka / (ka + kb) : 0.5;
  Eigen::Matrix3d pooled = wa * a.covariance + (1.0 - wa) * b.covariance;  // eq. (4.53)
  pooled.diagonal().array() += min_variance;
  const Eigen::Vector3d delta = a.centroid - b.centroid;
  const Eigen::LDLT<Eigen::Matrix3d> ldlt(pooled);
  const double q = delta.dot(ldlt.solve(delta));
  return std::isfinite(q) ? std::sqrt(std::max(0.0, q)) : std::numeric_limits<double>::infinity();
}

// a's centroid, covariance and count become those of a ∪ b (exact, from the moments).
void absorb_moments(PlaneLandmark& a, const PlaneLandmark& b) {
  const PointMoments m = PointMoments::combine(a.moments(), b.moments());
  a.centroid = m.centroid;
  a.covariance = m.covariance();
  a.inlier_count = m.count;
}

void absorb_outline(PlaneLandmark& a, const PlaneLandmark& b, const Eigen::Vector3d& origin,
                    const Eigen::Vector3d& major_axis) {
  std::vector<Eigen::Vector3d> vertices = a.hull;
  vertices.insert(vertices.end(), b.hull.begin(), b.hull.end());
  const PlaneOutline outline = compute_outline(vertices, principal_frame(origin, a.plane.normal, major_axis));
  a.hull = outline.hull;
  a.rectangle = outline.rectangle;
  a.area = outline.area;
}

Eigen::Vector3d major_axis(const Eigen::Matrix3d& covariance) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);
  return eig.eigenvectors().col(2);
}

// a ← a ∪ b, refitting the plane from the combined moments (§4.1).
void absorb(PlaneLandmark& a, const PlaneLandmark& b) {
  const Eigen::Vector3d side = a.plane.normal;
  absorb_moments(a, b);
  const PlaneFit fit = fit_plane_pca(a.moments());
  if (fit.ok) {
    a.plane.normal = fit.plane.normal.dot(side) < 0.0 ? Eigen::Vector3d(-fit.plane.normal) : fit.plane.normal;
    a.plane.d = a.plane.normal.dot(a.centroid);
  }
  absorb_outline(a, b, a.centroid, fit.ok ? Eigen::Vector3d(fit.axes.col(2)) : major_axis(a.covariance));
  a.inliers.insert(a.inliers.end(), b.inliers.begin(), b.inliers.end());
}

}  // namespace

bool MergeThresholds::valid(std::string* why) const {
  auto fail = [&](const char* text) {
    if (why) *why = text;
    return false;
  };
  if (!(orientation_deg > 0.0 && orientation_deg <= 180.0))
    return fail("orientation_deg must be in (0, 180]");
  if (!(translation > 0.0 && std::isfinite(translation))) return fail("translation must be positive");
  if (!(closeness > 0.0 && std::isfinite(closeness))) return fail("closeness must be positive");
  if (!(min_variance >= 0.0 && std::isfinite(min_variance))) return fail("min_variance must be ≥ 0");
  return true;
}

MergeCriteria merge_criteria(const PlaneLandmark& a, const PlaneLandmark& b, double min_variance) {
  MergeCriteria c;
  c.orientation_deg = orientation_deg(a, b);
  c.translation = translation(a, b);
  c.closeness = closeness(a, b, min_variance);
  c.centre_distance = (a.centroid - b.centroid).norm();
  return c;
}

bool merge_test(const PlaneLandmark& a, const PlaneLandmark& b, const MergeThresholds& t,
                MergeCriteria* out) {
  MergeCriteria c;
  c.centre_distance = (a.centroid - b.centroid).norm();
  bool pass = false;
  c.orientation_deg = orientation_deg(a, b);
  if (c.orientation_deg < t.orientation_deg) {
    c.translation = translation(a, b);
    if (c.translation < t.translation) {
      c.closeness = closeness(a, b, t.min_variance);
      pass = c.closeness < t.closeness;
    }
  }
  if (out) *out = c;
  return pass;
}

PlaneLandmark merge_landmarks(const PlaneLandmark& a, const PlaneLandmark& b) {
  PlaneLandmark out = a;
  absorb(out, b);
  return out;
}

PlaneLandmark merge_landmark_semantics(const PlaneLandmark& map_landmark,
                                       const PlaneLandmark& observed_in_world) {
  PlaneLandmark out = map_landmark;
  absorb_moments(out, observed_in_world);
  const Eigen::Vector3d& n = out.plane.normal;
  const Eigen::Vector3d origin = out.centroid - n * out.plane.signed_distance(out.centroid);
  absorb_outline(out, observed_in_world, origin, major_axis(out.covariance));
  out.inliers.clear();  // indices of different scans do not mix
  return out;
}

MergeResult merge_planes(const std::vector<PlaneLandmark>& planes, const MergeThresholds& thresholds) {
  MergeResult result;
  std::vector<std::size_t> order(planes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    return planes[i].inlier_count > planes[j].inlier_count;
  });

  // Phase 1: region growing from seeds in decreasing size.
  std::vector<bool> alive(planes.size(), true);
  for (std::size_t seed : order) {
    if (!alive[seed]) continue;
    alive[seed] = false;
    PlaneLandmark grown = planes[seed];
    std::vector<std::size_t> members{seed};
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t j : order) {
        if (!alive[j]) continue;
        ++result.tests;
        if (!merge_test(grown, planes[j], thresholds)) continue;
        absorb(grown, planes[j]);
        alive[j] = false;
        members.push_back(j);
        ++result.merges;
        changed = true;
      }
    }
    result.planes.push_back(std::move(grown));
    result.members.push_back(std::move(members));
  }

  // Phase 2: grown planes merge among themselves until no pair passes.
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < result.planes.size(); ++i) {
      for (std::size_t j = i + 1; j < result.planes.size();) {
        ++result.tests;
        if (!merge_test(result.planes[i], result.planes[j], thresholds)) {
          ++j;
          continue;
        }
        absorb(result.planes[i], result.planes[j]);
        auto& mi = result.members[i];
        mi.insert(mi.end(), result.members[j].begin(), result.members[j].end());
        result.planes.erase(result.planes.begin() + static_cast<std::ptrdiff_t>(j));
        result.members.erase(result.members.begin() + static_cast<std::ptrdiff_t>(j));
        ++result.merges;
        changed = true;
      }
    }
  }

  std::vector<std::size_t> by_size(result.planes.size());
  std::iota(by_size.begin(), by_size.end(), std::size_t{0});
  std::stable_sort(by_size.begin(), by_size.end(), [&](std::size_t i, std::size_t j) {
    return result.planes[i].inlier_count > result.planes[j].inlier_count;
  });
  MergeResult sorted;
  sorted.merges = result.merges;
  sorted.tests = result.tests;
  for (std::size_t i : by_size) {
    sorted.planes.push_back(std::move(result.planes[i]));
    std::sort(result.members[i].begin(), result.members[i].end());
    sorted.members.push_back(std::move(result.members[i]));
  }
  return sorted;
}

}  // namespace sextant
