// Issue 5, "Done when", on the built-in synthetic campus (default campus and default 20k-point
// sensor, seed 11, first kScans scans): plane extraction recovers the true façade planes
// (normal within 3°, d within 5 cm, majority of the inliers on that landmark) with a measured
// precision and recall, and semantic association between consecutive scans, given the true
// relative pose, pairs landmarks of the same true plane with precision ≥ 0.95.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <vector>

#include "sextant/core/rng.hpp"
#include "sextant/features/association.hpp"
#include "sextant/features/extraction.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant {
namespace {

constexpr std::size_t kScans = 24;
constexpr double kNormalTolDeg = 3.0;
constexpr double kDistanceTol = 0.05;  // [m]
// Recall counts the true landmarks a scan has at least this many points on (≈ 1.5 % of a
// default scan): fewer points are a sliver or a far, sparse patch that no 2 m cell can fit.
constexpr std::size_t kMinVisiblePoints = 300;

struct Scan {
  synth::SimulatedScan sim;
  std::vector<PlaneLandmark> landmarks;  // sensor frame
  std::vector<int> truth;                // per landmark: majority true id, or −1
};

/// The true landmark most of a plane's inliers hit, or −1 when no landmark holds a majority.
int majority_landmark(const PlaneLandmark& plane, const synth::SimulatedScan& scan) {
  std::map<int, std::size_t> votes;
  for (std::size_t i : plane.inliers) ++votes[scan.landmark[i]];
  for (const auto& [id, n] : votes)
    if (id >= 0 && 2 * n > plane.inliers.size()) return id;
  return -1;
}

const synth::Campus& campus() {
  static const synth::Campus c = synth::generate_campus(synth::CampusSettings{}, 11);
  return c;
}

const std::vector<Scan>& scans() {
  static const std::vector<Scan> all = [] {
    std::vector<Scan> out;
    Rng rng(5);
    for (std::size_t i = 0; i < kScans; ++i) {
      Scan s;
      s.sim = campus().scan(i);
      s.landmarks = extract_planes(s.sim.cloud, PlaneExtractionSettings{}, rng).landmarks;
      for (const PlaneLandmark& l : s.landmarks) s.truth.push_back(majority_landmark(l, s.sim));
      out.push_back(std::move(s));
    }
    return out;
  }();
  return all;
}

/// True when the plane of `detected` (sensor frame) matches the true landmark `id` seen from the
/// true pose `world_from_sensor`: normals within 3° (either orientation) and d within 5 cm.
bool matches_true_plane(const PlaneLandmark& detected, int id, const Eigen::Isometry3d& world_from_sensor) {
  const synth::Landmark& l = campus().world->landmarks[static_cast<std::size_t>(id)];
  const Plane truth = Plane{l.normal, l.d}.transformed(world_from_sensor.inverse());
  const double dot = detected.plane.normal.dot(truth.normal);
  const double angle = std::acos(std::min(1.0, std::abs(dot))) * 180.0 / M_PI;
  const double d = dot < 0 ? -detected.plane.d : detected.plane.d;
  return angle < kNormalTolDeg && std::abs(d - truth.d) < kDistanceTol;
}

// Measured (default campus and sensor, seed 11, scans 0–23, extraction rng seed 5, default
// extraction settings): precision 0.665 (169/254), recall 0.845 (109/129 true landmarks with
// ≥ 300 points). Of the 85 false positives 54 have no landmark holding a majority of their
// inliers (planes on cars, kerbs and other non-landmark objects, or mixed cells); the other 31
// have a majority landmark but miss it by more than 3° or 5 cm (not diagnosed further). Asserted
// floors, below the measurement so that the test catches regressions and not the last digit:
// precision ≥ 0.55, recall ≥ 0.75.
TEST(CampusExtraction, RecoversTheTrueFacadePlanes) {
  std::size_t detected = 0, true_positive = 0, eligible = 0, recalled = 0;
  std::size_t no_majority = 0;  // false positives whose inliers no true landmark holds a majority of
  for (std::size_t i = 0; i < kScans; ++i) {
    const Scan& s = scans()[i];
    std::set<int> found;
    std::size_t tp = 0;
    for (std::size_t j = 0; j < s.landmarks.size(); ++j) {
      const int id = s.truth[j];
      if (id < 0) ++no_majority;
      if (id >= 0 && matches_true_plane(s.landmarks[j], id, campus().ground_truth[i])) ++tp, found.insert(id);
    }
    std::size_t visible = 0, hit = 0;
    for (const synth::LandmarkVisibility& v : s.sim.visible) {
      if (v.points < kMinVisiblePoints) continue;
      ++visible;
      if (found.count(v.landmark)) ++hit;
    }
    std::printf(
        "[campus-extraction] scan %zu: %zu points, %zu landmarks, %zu true positives (precision %.3f), "
        "%zu of %zu true landmarks with >= %zu points recovered (recall %.3f)\n",
        i, s.sim.cloud.size(), s.landmarks.size(), tp,
        s.landmarks.empty() ? 0.0 : double(tp) / double(s.landmarks.size()), hit, visible, kMinVisiblePoints,
        visible ? double(hit) / double(visible) : 0.0);
    detected += s.landmarks.size();
    true_positive += tp;
    eligible += visible;
    recalled += hit;
  }
  const double precision = detected ? double(true_positive) / double(detected) : 0.0;
  const double recall = eligible ? double(recalled) / double(eligible) : 0.0;
  std::printf(
      "[campus-extraction] total over %zu scans: precision %.3f (%zu/%zu; of the %zu false positives %zu "
      "have no "
      "majority landmark, the rest miss 3 deg / 5 cm), recall %.3f (%zu/%zu)\n",
      kScans, precision, true_positive, detected, detected - true_positive, no_majority, recall, recalled,
      eligible);
  EXPECT_GE(precision, 0.55);
  EXPECT_GE(recall, 0.75);
}

struct AssociationScore {
  std::size_t matches = 0;
  std::size_t true_plane = 0, correct = 0;    // matches with a true landmark on either side; same landmark
  std::size_t clutter = 0, clutter_same = 0;  // neither side a landmark; same majority primitive
  double precision() const { return true_plane ? double(correct) / double(true_plane) : 0.0; }
};

/// The world primitive most of a plane's inliers hit (cars, kerbs, … that are not landmarks), or −1.
int majority_primitive(const PlaneLandmark& plane, const synth::SimulatedScan& scan) {
  std::map<int, std::size_t> votes;
  for (std::size_t i : plane.inliers) ++votes[scan.primitive[i]];
  for (const auto& [id, n] : votes)
    if (id >= 0 && 2 * n > plane.inliers.size()) return id;
  return -1;
}

/// Scan i+1's landmarks moved into scan i's frame with the true relative pose, associated against
/// scan i's; a match is correct when both sides' inlier majorities hit the same true landmark.
AssociationScore associate_consecutive(const AssociationSettings& settings) {
  AssociationScore score;
  for (std::size_t i = 0; i + 1 < kScans; ++i) {
    const Scan &map = scans()[i], &next = scans()[i + 1];
    const Eigen::Isometry3d relative = campus().ground_truth[i].inverse() * campus().ground_truth[i + 1];
    const AssociationResult r =
        associate_landmarks(transform_landmarks(next.landmarks, relative), map.landmarks, settings);
    EXPECT_EQ(r.matches.size() + r.new_landmarks.size(), next.landmarks.size());
    for (const LandmarkMatch& m : r.matches) {
      const int a = next.truth[m.observed], b = map.truth[m.map];
      ++score.matches;
      if (a >= 0 || b >= 0) {
        ++score.true_plane;
        if (a == b) ++score.correct;
      } else {
        ++score.clutter;
        const int pa = majority_primitive(next.landmarks[m.observed], next.sim);
        if (pa >= 0 && pa == majority_primitive(map.landmarks[m.map], map.sim)) ++score.clutter_same;
      }
    }
  }
  return score;
}

// Precision counts the matches with a true landmark on either side (a landmark paired with a
// different landmark or with clutter is wrong); clutter–clutter pairs are reported apart, judged
// by their majority primitive. Measured over 23 pairs: defaults (20°, 1 m) 0.963 (155/161),
// tight (5°, 0.5 m, as the plane-SLAM campus test uses) 0.975 (153/157); 24 of 28 (27)
// clutter–clutter matches join the same primitive. Both settings must reach 0.95 (issue 5) with
// at least 120 true-landmark matches.
TEST(CampusAssociation, ConsecutiveScansWithTruePoseMatchTheSameTruePlanes) {
  const AssociationSettings defaults;
  AssociationSettings tight;
  tight.thresholds.orientation_deg = 5.0;
  tight.thresholds.translation = 0.5;
  for (const auto& [name, settings] :
       {std::pair{"defaults (20 deg, 1 m)", defaults}, std::pair{"tight (5 deg, 0.5 m)", tight}}) {
    const AssociationScore s = associate_consecutive(settings);
    std::printf(
        "[campus-association] %s over %zu scan pairs: %zu matches; %zu involve a true landmark, %zu of them "
        "correct (precision %.3f); %zu pair two non-landmark planes, %zu of those on the same primitive\n",
        name, kScans - 1, s.matches, s.true_plane, s.correct, s.precision(), s.clutter, s.clutter_same);
    EXPECT_GE(s.true_plane, 120u) << name;
    EXPECT_GE(s.precision(), 0.95) << name;
  }
}

}  // namespace
}  // namespace sextant
