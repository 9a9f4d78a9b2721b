// E11 (§5.2, figs 5.21–5.25, table 5.10) on the synthetic campus: one run = one scan pair
// (scan i, scan i + 1) of the sweep axis `scan`. Plane extraction (cells, RANSAC, merging,
// ground removal, eqs. (3.23)–(3.28), §4.1) of both scans, each drawn from its own
// Rng(seed, scan) so a scan gives the same features in every run; extraction precision and recall
// of scan i against the campus' true planes; semantic association (§4.2.5: C_o, C_t, C_p with
// relaxed thresholds) of scan i + 1's features into scan i's frame with no pose (identity), the
// predicted pose (odometry) and the true pose; a match is correct when the inlier majorities of
// both features hit the same true plane.
//
//   params:
//     study: extraction
//     extraction: {PlaneExtractionSettings keys}
//     association: {search_radius, orientation_deg, translation, closeness, min_variance}
//     turn_scan: 3                # table 5.10: the pair 3 → 4 (the 51.5° turn on the spot)
//     figure_scans: [0, 1]        # figs 5.22–5.23: merged features drawn
//     first_scans: 5              # extraction table rows
//     min_visible_points: 300     # recall counts true planes with this many points in the scan
//     normal_tolerance_deg: 3     # a detected plane is true within 3° and 5 cm of a true plane
//     distance_tolerance: 0.05
//   sweep: {scan: {from: 0, to: 23}}
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "kit/dataset_source.hpp"
#include "plane_features/extraction.hpp"
#include "plane_features/layouts/layouts.hpp"
#include "plane_features/row_keys.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"
#include "sextant/features/yaml.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant {

ExtractionStudyParams read_extraction_study_params(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  std::string study;
  in.read("study", study);
  ExtractionStudyParams p;
  p.extraction = read_plane_extraction_settings(in.child("extraction"), config.file);
  p.association = read_association_settings(in.child("association"), config.file);
  in.read("turn_scan", p.turn_scan);
  in.read("figure_scans", p.figure_scans);
  in.read("first_scans", p.first_scans);
  in.read("min_visible_points", p.min_visible_points);
  in.read("normal_tolerance_deg", p.normal_tolerance_deg);
  in.read("distance_tolerance", p.distance_tolerance);
  in.finish();
  if (!(p.normal_tolerance_deg > 0) || !(p.distance_tolerance > 0))
    in.fail("normal_tolerance_deg", "key 'normal_tolerance_deg' and 'distance_tolerance' must be > 0");
  return p;
}

namespace {

/// The id most of the feature's inliers hit in `ids` (true landmark or primitive), or −1.
int majority(const PlaneLandmark& plane, const std::vector<std::int32_t>& ids) {
  std::map<int, std::size_t> votes;
  for (std::size_t i : plane.inliers) ++votes[ids[i]];
  for (const auto& [id, n] : votes)
    if (id >= 0 && 2 * n > plane.inliers.size()) return id;
  return -1;
}

struct ScanFeatures {
  synth::SimulatedScan sim;
  PlaneExtraction extraction;
  std::vector<int> truth;  ///< per feature: majority true landmark or −1
};

std::uint64_t scan_seed(std::uint64_t seed, std::size_t scan) {
  return seed * 0x9E3779B97F4A7C15ULL + 0x632BE59BD9B4E019ULL * (static_cast<std::uint64_t>(scan) + 1);
}

class ExtractionSession : public KindSession {
 public:
  ExtractionSession(const ExperimentConfig& config, ExtractionStudyParams p)
      : p_(std::move(p)), seed_(config.seed), dataset_(open_experiment_dataset(config, "plane_features")) {
    const auto* campus = dynamic_cast<const synth::CampusDataset*>(dataset_.get());
    if (!campus)
      throw InputError(config.file, "", "key 'dataset': the extraction study needs source: synthetic");
    campus_ = &campus->campus();
  }

  void run(const RunSpec& run, RunRow& row) const override {
    const std::size_t i = static_cast<std::size_t>(std::stoul(run.point.at("scan")));
    if (i + 1 >= campus_->size())
      throw std::runtime_error("scan " + std::to_string(i + 1) + " is past the campus");
    const ScanFeatures a = features(i), b = features(i + 1);
    const ExtractionStatistics& st = a.extraction.stats;
    row.values[keys::kPoints] = static_cast<double>(st.points);
    row.values[keys::kCellPlanes] = static_cast<double>(st.cell_planes);
    row.values[keys::kMergedPlanes] = static_cast<double>(st.merged_planes);
    row.values[keys::kHorizontalRemoved] = static_cast<double>(st.horizontal_removed);
    row.values[keys::kTooSmallRemoved] = static_cast<double>(st.too_small_removed);
    row.values[keys::kLandmarks] = static_cast<double>(st.landmarks);
    row.values["extraction_seconds"] = st.seconds;

    // Extraction precision (features on a true plane within the tolerances) and recall (true
    // planes with ≥ min_visible_points points that some feature recovers).
    std::set<int> found;
    std::size_t tp = 0;
    for (std::size_t j = 0; j < a.extraction.landmarks.size(); ++j) {
      const int id = a.truth[j];
      if (id >= 0 && matches_true_plane(a.extraction.landmarks[j], id, campus_->ground_truth[i]))
        ++tp, found.insert(id);
    }
    std::size_t visible = 0, recalled = 0;
    for (const synth::LandmarkVisibility& v : a.sim.visible) {
      if (v.points < p_.min_visible_points) continue;
      ++visible;
      recalled += found.count(v.landmark);
    }
    row.values[keys::kTruePositives] = static_cast<double>(tp);
    row.values[keys::kVisibleTruePlanes] = static_cast<double>(visible);
    row.values[keys::kRecalledTruePlanes] = static_cast<double>(recalled);

    const Eigen::Isometry3d truth = campus_->ground_truth[i].inverse() * campus_->ground_truth[i + 1];
    const Eigen::Isometry3d odometry = campus_->odometry[i].inverse() * campus_->odometry[i + 1];
    row.values[keys::kTrueYawDeg] = std::atan2(truth.rotation()(1, 0), truth.rotation()(0, 0)) * 180.0 / kPi;
    row.values[keys::kTrueTranslationM] = truth.translation().norm();
    std::set<int> in_map(a.truth.begin(), a.truth.end());
    std::size_t possible = 0;  // features of scan i + 1 whose true plane scan i also has
    for (int id : b.truth) possible += id >= 0 && in_map.count(id) ? 1 : 0;
    row.values[keys::kAssociationPossible] = static_cast<double>(possible);
    const std::map<std::string, Eigen::Isometry3d> poses{
        {"none", Eigen::Isometry3d::Identity()}, {"odometry", odometry}, {"truth", truth}};
    AssociationResult predicted;  // fig. 5.24
    for (const std::string& name : association_poses()) {
      const AssociationResult r =
          associate_landmarks(transform_landmarks(b.extraction.landmarks, poses.at(name)),
                              a.extraction.landmarks, p_.association);
      std::size_t true_plane = 0, correct = 0;
      std::vector<double> co, ct, cp, ok;
      for (const LandmarkMatch& m : r.matches) {
        const int x = b.truth[m.observed], y = a.truth[m.map];
        true_plane += x >= 0 || y >= 0 ? 1 : 0;
        correct += x >= 0 && x == y ? 1 : 0;
        co.push_back(m.criteria.orientation_deg), ct.push_back(m.criteria.translation);
        cp.push_back(m.criteria.closeness), ok.push_back(x >= 0 && x == y ? 1.0 : 0.0);
      }
      row.values["assoc_" + name + "_matches"] = static_cast<double>(r.matches.size());
      row.values["assoc_" + name + "_true_plane"] = static_cast<double>(true_plane);
      row.values["assoc_" + name + "_correct"] = static_cast<double>(correct);
      row.series["crit_" + name + "_co"] = co, row.series["crit_" + name + "_ct"] = ct;
      row.series["crit_" + name + "_cp"] = cp, row.series["crit_" + name + "_correct"] = ok;
      if (name == "odometry") predicted = r;
    }
    record_figures(i, a, b, odometry, predicted, row);
  }

 private:
  /// The outlines of figs 5.21–5.25 (plane_features/extraction_figures.cpp draws them).
  void record_figures(std::size_t i, const ScanFeatures& a, const ScanFeatures& b,
                      const Eigen::Isometry3d& odometry, const AssociationResult& predicted,
                      RunRow& row) const {
    const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
    if (!p_.figure_scans.empty() && i == p_.figure_scans.front()) {  // fig. 5.21: cell segments
      std::vector<PlaneLandmark> ground, other;
      for (const PlaneLandmark& l : a.extraction.cell_planes)
        (tilt_from_horizontal_deg(l.plane) < p_.extraction.horizontal_max_tilt_deg ? ground : other)
            .push_back(l);
      store_hulls(ground, identity, "cell_ground_hull", row);
      store_hulls(other, identity, "cell_hull", row);
    }
    if (std::find(p_.figure_scans.begin(), p_.figure_scans.end(), i) != p_.figure_scans.end())
      store_hulls(a.extraction.landmarks, identity, "hull", row);  // figs 5.22–5.23
    if (i == p_.turn_scan) {                                       // fig. 5.24
      const std::vector<PlaneLandmark> moved = transform_landmarks(b.extraction.landmarks, odometry);
      store_hulls(a.extraction.landmarks, identity, "turn_map_hull", row);
      store_hulls(moved, identity, "turn_obs_hull", row);
      std::vector<double>&lx = row.series["turn_links_x"], &ly = row.series["turn_links_y"];
      const auto correct = [&](const LandmarkMatch& m) {
        return b.truth[m.observed] >= 0 && b.truth[m.observed] == a.truth[m.map];
      };
      const LandmarkMatch* shown = nullptr;  // the first correct pair, else the first pair
      for (const LandmarkMatch& m : predicted.matches) {
        const Eigen::Vector3d c = moved[m.observed].centroid, d = a.extraction.landmarks[m.map].centroid;
        lx.insert(lx.end(), {c.x(), d.x(), NAN}), ly.insert(ly.end(), {c.y(), d.y(), NAN});
        if (!shown || (correct(m) && !correct(*shown))) shown = &m;
      }
      if (shown) {
        store_hulls({a.extraction.landmarks[shown->map]}, identity, "turn_pair_map", row);
        store_hulls({moved[shown->observed]}, identity, "turn_pair_obs", row);
      }
    }
    const Eigen::Isometry3d& pose = campus_->ground_truth[i];  // fig. 5.25
    store_hulls(a.extraction.landmarks, pose, "world_hull", row);
    row.values[keys::kPoseX] = pose.translation().x(), row.values[keys::kPoseY] = pose.translation().y();
  }

  ScanFeatures features(std::size_t scan) const {
    ScanFeatures f;
    f.sim = campus_->scan(scan);
    Rng rng(scan_seed(seed_, scan));
    f.extraction = extract_planes(f.sim.cloud, p_.extraction, rng);
    for (const PlaneLandmark& l : f.extraction.landmarks) f.truth.push_back(majority(l, f.sim.landmark));
    return f;
  }

  /// The detected plane (sensor frame) against true landmark `id` seen from the true pose: normals
  /// within the angle tolerance (either orientation) and d within the distance tolerance.
  bool matches_true_plane(const PlaneLandmark& detected, int id,
                          const Eigen::Isometry3d& world_from_sensor) const {
    const synth::Landmark& l = campus_->world->landmarks[static_cast<std::size_t>(id)];
    const Plane truth = Plane{l.normal, l.d}.transformed(world_from_sensor.inverse());
    const double dot = detected.plane.normal.dot(truth.normal);
    const double angle = std::acos(std::min(1.0, std::abs(dot))) * 180.0 / kPi;
    const double d = dot < 0 ? -detected.plane.d : detected.plane.d;
    return angle < p_.normal_tolerance_deg && std::abs(d - truth.d) < p_.distance_tolerance;
  }

  ExtractionStudyParams p_;
  std::uint64_t seed_;
  std::unique_ptr<Dataset> dataset_;
  const synth::Campus* campus_ = nullptr;  ///< owned by dataset_
};

}  // namespace

void validate_extraction_study(const ExperimentConfig& config) {
  (void)read_extraction_study_params(config);
  if (config.dataset.source != DatasetSource::kSynthetic)
    throw InputError(config.file, "",
                     "key 'dataset': the extraction study needs source: synthetic (true planes)");
  check_experiment_dataset(config, "plane_features");
  if (config.sweep.size() != 1 || config.sweep[0].name != "scan")
    throw InputError(config.file, "", "key 'sweep': the extraction study needs exactly one axis 'scan'");
  for (const auto& v : config.sweep[0].values)
    if (!v.IsScalar() || v.as<long long>(-1) < 0)
      throw InputError(config.file, at_line(yaml_line(v)), "key 'scan': scan indices are integers >= 0");
  for (const auto& m : config.methods) {
    SettingsReader in(m.node, config.file);
    std::string name;
    in.require("name", name);
    in.finish();
  }
  if (config.methods.size() != 1)
    throw InputError(config.file, "", "key 'methods': the extraction study takes one method");
  SettingsReader ref(config.reference, config.file);
  double x = 0;
  ref.read("first_scan_features", x);
  ref.read("second_scan_associated", x);
  ref.read("feature_band_factor", x);
  ref.read("association_precision_floor", x);
  ref.read("trivial_motion_m", x);
  std::vector<std::vector<double>> table;
  ref.read("table_5_10", table);
  ref.finish();
}

std::unique_ptr<KindSession> prepare_extraction_study(const ExperimentConfig& config) {
  return std::make_unique<ExtractionSession>(config, read_extraction_study_params(config));
}

ReportSection extraction_study_report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                                      const std::vector<const RunRow*>& rows) {
  return extraction_report(config, read_extraction_study_params(config), runs, rows);
}

}  // namespace sextant
