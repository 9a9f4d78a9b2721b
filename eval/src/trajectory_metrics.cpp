#include "sextant/eval/trajectory_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sextant/core/pose.hpp"
#include "sextant/eval/alignment_roll.hpp"

namespace sextant {

namespace {

MetricStatus failure(const std::string& message) {
  return {false, message};
}

bool all_finite(const PoseList& poses) {
  for (const Eigen::Isometry3d& T : poses)
    if (!is_finite(T)) return false;
  return true;
}

/// Common checks: same length, at least `min_poses`, finite.
MetricStatus check_pair(const PoseList& estimate, const PoseList& reference, std::size_t min_poses) {
  if (estimate.size() != reference.size())
    return failure("estimate has " + std::to_string(estimate.size()) + " poses, reference " +
                   std::to_string(reference.size()));
  if (estimate.size() < min_poses) return failure("needs at least " + std::to_string(min_poses) + " poses");
  if (!all_finite(estimate)) return failure("estimate has non-finite poses");
  if (!all_finite(reference)) return failure("reference has non-finite poses");
  return {};
}

/// The settings' own check, then check_pair.
template <class Settings>
MetricStatus check_inputs(const Settings& settings, const PoseList& estimate, const PoseList& reference,
                          std::size_t min_poses) {
  std::string why;
  if (!settings.valid(&why)) return failure(why);
  return check_pair(estimate, reference, min_poses);
}

/// Per axis: the mean of `values` and its standard error (sample SD / √N; 0 for one value).
void mean_and_standard_error(const std::vector<Eigen::Vector3d>& values, Eigen::Vector3d& mean,
                             Eigen::Vector3d& standard_error) {
  const auto n = static_cast<double>(values.size());
  mean.setZero();
  for (const Eigen::Vector3d& v : values) mean += v;
  mean /= n;
  Eigen::Vector3d squares = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : values) squares += (v - mean).cwiseAbs2();
  standard_error.setZero();
  if (values.size() > 1) standard_error = (squares / (n - 1.0) / n).cwiseSqrt();
}

/// E = (ref_i⁻¹ ref_j)⁻¹ (est_i⁻¹ est_j), the relative error used by RPE and KITTI.
Eigen::Isometry3d relative_error(const PoseList& estimate, const PoseList& reference, std::size_t i,
                                 std::size_t j) {
  return relative(relative(reference[i], reference[j]), relative(estimate[i], estimate[j]));
}

}  // namespace

PoseList poses_of(const Trajectory& trajectory) {
  PoseList poses;
  poses.reserve(trajectory.size());
  for (const StampedPose& p : trajectory) poses.push_back(p.pose);
  return poses;
}

std::vector<double> path_distances(const PoseList& poses) {
  std::vector<double> d(poses.size(), 0.0);
  for (std::size_t i = 1; i < poses.size(); ++i)
    d[i] = d[i - 1] + (poses[i].translation() - poses[i - 1].translation()).norm();
  return d;
}

WulfResult wulf_metric(const PoseList& estimate, const PoseList& reference) {
  WulfResult r;
  r.status = check_pair(estimate, reference, 1);
  if (!r.status.ok) return r;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    // eq. (6.2)
    r.position_errors.push_back((estimate[i].translation() - reference[i].translation()).norm());
    // eq. (6.3), angle differences wrapped so that 359° vs 1° counts as 2°
    const Pose6 a = to_pose6(estimate[i]), b = to_pose6(reference[i]);
    const Eigen::Vector3d d(wrap_angle(a.alpha - b.alpha), wrap_angle(a.beta - b.beta),
                            wrap_angle(a.gamma - b.gamma));
    r.orientation_errors.push_back(d.norm());
  }
  r.position_rms = rms(r.position_errors);  // eq. (6.1)
  r.orientation_rms = rms(r.orientation_errors);
  return r;
}

std::vector<PoseRelation> consecutive_relations(std::size_t pose_count) {
  std::vector<PoseRelation> relations;
  for (std::size_t i = 0; i + 1 < pose_count; ++i) relations.push_back({i, i + 1, false, {}});
  return relations;
}

KummerleResult kummerle_metric(const PoseList& estimate, const PoseList& reference,
                               const std::vector<PoseRelation>& relations) {
  KummerleResult r;
  if (relations.empty()) {
    r.status = failure("no relations");
    return r;
  }
  if (!all_finite(estimate)) {
    r.status = failure("estimate has non-finite poses");
    return r;
  }
  for (const PoseRelation& rel : relations) {
    if (rel.i >= estimate.size() || rel.j >= estimate.size()) {
      r.status = failure("relation (" + std::to_string(rel.i) + ", " + std::to_string(rel.j) +
                         ") outside the estimate's " + std::to_string(estimate.size()) + " poses");
      return r;
    }
    if (!rel.has_reference_motion && (rel.i >= reference.size() || rel.j >= reference.size())) {
      r.status = failure("relation (" + std::to_string(rel.i) + ", " + std::to_string(rel.j) +
                         ") has no reference motion and lies outside the reference's poses");
      return r;
    }
    const Eigen::Isometry3d reference_motion =
        rel.has_reference_motion ? rel.reference_motion : relative(reference[rel.i], reference[rel.j]);
    if (!is_finite(reference_motion)) {
      r.status = failure("non-finite reference motion");
      return r;
    }
    const Eigen::Isometry3d motion = relative(estimate[rel.i], estimate[rel.j]);  // δ_ij = x_j ⊖ x_i
    const Eigen::Isometry3d error = relative(reference_motion, motion);           // δ_ij ⊖ δ*_ij
    r.translation_errors.push_back(translation_norm(error));
    r.rotation_errors.push_back(rotation_angle(error));
  }
  // eq. (6.6), trans and rot evaluated individually
  r.translation_rms = rms(r.translation_errors);
  r.rotation_rms = rms(r.rotation_errors);
  return r;
}

KummerleResult kummerle_metric(const PoseList& estimate, const PoseList& reference) {
  KummerleResult r;
  r.status = check_pair(estimate, reference, 2);
  if (!r.status.ok) return r;
  return kummerle_metric(estimate, reference, consecutive_relations(estimate.size()));
}

AteResult absolute_trajectory_error(const PoseList& estimate, const PoseList& reference,
                                    Alignment alignment) {
  AteResult r;
  r.status =
      check_pair(estimate, reference, alignment == Alignment::se3 || alignment == Alignment::sim3 ? 2 : 1);
  if (!r.status.ok) return r;
  if (alignment == Alignment::origin) {
    const Eigen::Isometry3d T = reference.front() * estimate.front().inverse();
    r.alignment.rotation = T.linear();
    r.alignment.translation = T.translation();
  } else if (alignment != Alignment::none) {
    std::vector<Eigen::Vector3d> src, dst;
    for (std::size_t i = 0; i < estimate.size(); ++i) {
      src.push_back(estimate[i].translation());
      dst.push_back(reference[i].translation());
    }
    r.alignment = umeyama_alignment(src, dst, alignment == Alignment::sim3);
    if (!r.alignment.ok) {
      r.status = failure("alignment failed (coincident positions)");
      return r;
    }
    r.alignment = resolve_roll_about_trajectory(r.alignment, estimate, reference, &r.roll_from_orientations);
  }
  std::vector<double> rotation_errors;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const Eigen::Vector3d p = r.alignment.apply(estimate[i].translation());
    r.translation_errors.push_back((reference[i].translation() - p).norm());
    Eigen::Isometry3d rot_error = Eigen::Isometry3d::Identity();
    rot_error.linear() = reference[i].linear().transpose() * r.alignment.rotation * estimate[i].linear();
    rotation_errors.push_back(rotation_angle(rot_error));
  }
  r.translation = summarize(r.translation_errors);
  r.rotation = summarize(rotation_errors);
  return r;
}

bool RpeSettings::valid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (!(delta > 0.0) || !std::isfinite(delta)) return fail("delta must be a finite number > 0");
  if (unit == Unit::frames && std::floor(delta) != delta) return fail("delta in frames must be an integer");
  // Past 2⁵³ a double no longer holds every integer (and no trajectory has that many poses).
  if (unit == Unit::frames && delta > 9007199254740992.0) return fail("delta in frames must be at most 2^53");
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance)) return fail("tolerance must be a finite number >= 0");
  return true;
}

std::vector<std::pair<std::size_t, std::size_t>> rpe_pairs(const PoseList& reference,
                                                           const RpeSettings& settings) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  const std::size_t n = reference.size();
  if (n < 2 || !settings.valid(nullptr)) return pairs;
  if (settings.unit == RpeSettings::Unit::frames) {
    const auto step = static_cast<std::size_t>(settings.delta);
    if (step >= n) return pairs;  // (i + step would wrap around for a step near 2⁶⁴)
    for (std::size_t i = 0; i < n - step; i += settings.all_pairs ? 1 : step) pairs.emplace_back(i, i + step);
    return pairs;
  }
  const std::vector<double> distance = path_distances(reference);
  if (settings.all_pairs) {
    // evo: from every pose, the later pose whose path distance is closest to delta (the first
    // such pose on ties), within tolerance. Distances never decrease, so search by bisection.
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const double target = distance[i] + settings.delta;
      const auto begin = distance.begin() + static_cast<std::ptrdiff_t>(i + 1);
      const auto above = std::lower_bound(begin, distance.end(), target);
      auto best = above;
      if (above != begin && (above == distance.end() || target - *(above - 1) <= *above - target))
        best = std::lower_bound(begin, above, *(above - 1));  // first pose at that distance
      if (std::abs(*best - target) <= settings.tolerance)
        pairs.emplace_back(i, static_cast<std::size_t>(best - distance.begin()));
    }
    return pairs;
  }
  // evo: mark a pose each time the path since the last mark reaches delta; pair consecutive marks.
  std::vector<std::size_t> marks;
  double path = 0.0;
  for (std::size_t i = 1; i < n; ++i) {
    path += distance[i] - distance[i - 1];
    if (path >= settings.delta) {
      marks.push_back(i);
      path = 0.0;
    }
  }
  for (std::size_t k = 0; k + 1 < marks.size(); ++k) pairs.emplace_back(marks[k], marks[k + 1]);
  return pairs;
}

RpeResult relative_pose_error(const PoseList& estimate, const PoseList& reference,
                              const RpeSettings& settings) {
  RpeResult r;
  r.status = check_inputs(settings, estimate, reference, 2);
  if (!r.status.ok) return r;
  r.pairs = rpe_pairs(reference, settings);
  if (r.pairs.empty()) {
    r.status = failure("no pose pairs for this delta");
    return r;
  }
  std::vector<Eigen::Vector3d> rotation_vectors, translations;
  std::vector<double> along;  // the scale error's terms [m]
  double path = 0.0;          // the reference's motion over those pairs [m]
  for (const auto& [i, j] : r.pairs) {
    const Eigen::Vector3d moved = relative(reference[i], reference[j]).translation();
    const double length = moved.norm();
    if (length >= kScaleMinMotion) {
      along.push_back((relative(estimate[i], estimate[j]).translation() - moved).dot(moved) / length);
      path += length;
    }
    const Eigen::Isometry3d E = relative_error(estimate, reference, i, j);
    r.translation_errors.push_back(translation_norm(E));
    r.rotation_errors.push_back(rotation_angle(E));
    const Eigen::AngleAxisd rotation(E.rotation());
    rotation_vectors.push_back(rotation.angle() * rotation.axis());
    translations.push_back(E.translation());
  }
  r.translation = summarize(r.translation_errors);
  r.rotation = summarize(r.rotation_errors);
  mean_and_standard_error(rotation_vectors, r.mean_rotation_vector, r.rotation_vector_standard_error);
  mean_and_standard_error(translations, r.mean_translation, r.translation_standard_error);
  r.scale_pairs = along.size();
  r.scale_error = r.scale_standard_error = std::numeric_limits<double>::quiet_NaN();
  if (!along.empty()) {
    const SampleStats a = summarize(along);  // its SD: 0 for one pair
    const auto n = static_cast<double>(a.count);
    r.scale_error = a.mean * n / path;
    r.scale_standard_error = a.std * std::sqrt(n) / path;
  }
  return r;
}

bool KittiDriftSettings::valid(std::string* why) const {
  auto fail = [why](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (segment_lengths.empty()) return fail("segment_lengths must not be empty");
  for (double l : segment_lengths)
    if (!(l > 0.0) || !std::isfinite(l)) return fail("segment_lengths must all be > 0");
  if (step == 0) return fail("step must be >= 1");
  return true;
}

KittiDriftResult kitti_drift(const PoseList& estimate, const PoseList& reference,
                             const KittiDriftSettings& settings) {
  KittiDriftResult r;
  r.status = check_inputs(settings, estimate, reference, 2);
  if (!r.status.ok) return r;
  const std::vector<double> distance = path_distances(reference);
  double sum_t = 0.0, sum_r = 0.0;
  for (double length : settings.segment_lengths) {
    KittiSegmentDrift seg;
    seg.length = length;
    for (std::size_t first = 0; first < reference.size(); first += settings.step) {
      // KITTI devkit lastFrameFromSegmentLength: first frame with dist > dist[first] + len.
      const auto it = std::upper_bound(distance.begin() + static_cast<std::ptrdiff_t>(first), distance.end(),
                                       distance[first] + length);
      if (it == distance.end()) break;  // distances only grow: later starts fail too
      const auto last = static_cast<std::size_t>(it - distance.begin());
      const Eigen::Isometry3d E = relative_error(estimate, reference, first, last);
      const double t = translation_norm(E) / length, a = rotation_angle(E) / length;
      seg.translation += t;
      seg.rotation += a;
      ++seg.segments;
      sum_t += t;
      sum_r += a;
    }
    r.segments += seg.segments;
    if (seg.segments > 0) {
      seg.translation /= static_cast<double>(seg.segments);
      seg.rotation /= static_cast<double>(seg.segments);
    }
    r.per_length.push_back(seg);
  }
  if (r.segments == 0) {
    r.status = failure("trajectory shorter than the shortest segment length");
    return r;
  }
  r.translation = sum_t / static_cast<double>(r.segments);
  r.rotation = sum_r / static_cast<double>(r.segments);
  return r;
}

}  // namespace sextant
