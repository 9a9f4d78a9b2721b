// Layout (thesis §7.2 future work; docs/experiments.md, "Extensions beyond the thesis"):
// ATE, Wulf and Kümmerle of the chained scan-matching odometry, the pose graph with loop
// closures, the graph with an injected false closure (with and without the robust loss) and the
// plane-SLAM filters; the loop closures found, accepted and rejected; the cost of the graph solve;
// figures and claims.
#include "pose_graph/report.hpp"

#include <algorithm>
#include <cmath>

#include "kit/number_format.hpp"
#include "kit/row_codec.hpp"
#include "kit/row_keys.hpp"
#include "pose_graph/row_keys.hpp"
#include "sextant/core/units.hpp"

namespace sextant {
namespace {

Table metrics_header(const std::string& caption, const std::string& label, const std::string& note) {
  Table t;
  t.caption = caption;
  t.label = label;
  t.note = note;
  t.add_column("trajectory")
      .add_number_column("scans", 0)
      .add_number_column("ATE m", 3)
      .add_number_column("Wulf σ_T m", 3)
      .add_number_column("Wulf σ_R deg", 3)
      .add_number_column("Kümmerle σ_T m", 3)
      .add_number_column("Kümmerle σ_R deg", 3);
  return t;
}

const char* const kMetricKeys[] = {keys::kAteM, keys::kWulfTranslationM, keys::kWulfRotationDeg,
                                   keys::kKummerleTranslationM, keys::kKummerleRotationDeg};

void add_metric_row(Table& t, const std::string& label, const std::vector<const RunRow*>& rows,
                    const std::string& prefix) {
  std::vector<Cell> cells{Cell::text(label),
                          number_or_missing(median_finite(row_values(rows, keys::kScans)), 0)};
  for (const char* key : kMetricKeys)
    cells.push_back(number_or_missing(median_finite(row_values(rows, prefix + key)), 3));
  t.add_row(cells);
}

/// The metrics of the first `n` poses of a stored trajectory (medians over the rows).
void add_prefix_row(Table& t, const std::string& label, const std::vector<const RunRow*>& rows,
                    const std::string& prefix, std::size_t n) {
  std::vector<std::vector<double>> v(5);
  for (const RunRow* r : rows) {
    const PoseList all = series_to_poses(series_or_empty(*r, prefix + keys::kTrajectory));
    const PoseList truth_all = series_to_poses(series_or_empty(*r, keys::kTruth));
    if (all.size() < n || truth_all.size() < n || n < 2) continue;
    const PoseList est(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(n));
    const PoseList truth(truth_all.begin(), truth_all.begin() + static_cast<std::ptrdiff_t>(n));
    const AteResult ate = absolute_trajectory_error(est, truth, Alignment::se3);
    const WulfResult w = wulf_metric(est, truth);
    const KummerleResult k = kummerle_metric(est, truth);
    v[0].push_back(ate.status.ok ? ate.translation.rms : NAN);
    v[1].push_back(w.status.ok ? w.position_rms : NAN);
    v[2].push_back(w.status.ok ? w.orientation_rms * kDegPerRad : NAN);
    v[3].push_back(k.status.ok ? k.translation_rms : NAN);
    v[4].push_back(k.status.ok ? k.rotation_rms * kDegPerRad : NAN);
  }
  std::vector<Cell> cells{Cell::text(label), Cell::number(static_cast<double>(n), 0)};
  for (const auto& x : v) cells.push_back(number_or_missing(median_finite(x), 3));
  t.add_row(cells);
}

Table closure_table(const MethodRows& odometry) {
  Table t;
  t.caption = "Loop closures and the cost of the graph, per repetition";
  t.label = "loop_closures";
  t.note =
      "Candidates: the estimated trajectory (chain, then graph) comes back within the radius of a pose "
      "passed "
      "earlier; each is registered from the estimate's relative guess. Rejected by: n.c. = not "
      "converged, score = mean score per matched point, corr. = correction of the guess too large "
      "(matched fraction and a singular Hessian are the other tests). Weight: the Cauchy/Huber weight "
      "an accepted closure ended with (median, min); false: the injected false closure's. Times in "
      "seconds (single-thread sums of the registrations; the graph: Ceres' total).";
  t.add_column("repetition")
      .add_number_column("candidates", 0)
      .add_number_column("accepted", 0)
      .add_number_column("n.c.", 0)
      .add_number_column("score", 0)
      .add_number_column("corr.", 0)
      .add_column("weight median (min)")
      .add_number_column("false weight", 4)
      .add_number_column("registrations s", 1)
      .add_number_column("closures s", 1)
      .add_number_column("graph s", 3)
      .add_number_column("graph iterations", 0)
      .add_number_column("inflation", 1);
  for (std::size_t k = 0; k < odometry.rows.size(); ++k) {
    const RunRow& r = *odometry.rows[k];
    const std::vector<double>& why = series_or_empty(r, keys::kClosureRejection);
    const auto count = [&](ClosureRejection c) {
      return static_cast<double>(std::count(why.begin(), why.end(), static_cast<double>(c)));
    };
    std::vector<double> w;
    for (double x : series_or_empty(r, keys::kClosureWeight))
      if (std::isfinite(x)) w.push_back(x);
    const double lowest = w.empty() ? NAN : *std::min_element(w.begin(), w.end());
    const std::vector<double>& fw = series_or_empty(r, keys::kFalseWeight);
    t.add_row(
        {Cell::text(std::to_string(k + 1)), number_or_missing(r.value(keys::kCandidates), 0),
         number_or_missing(r.value(keys::kAccepted), 0),
         number_or_missing(count(ClosureRejection::not_converged), 0),
         number_or_missing(count(ClosureRejection::score), 0),
         number_or_missing(count(ClosureRejection::correction), 0),
         Cell::text(format_number(median_finite(w), 3, "–") + " (" + format_number(lowest, 3, "–") + ")"),
         number_or_missing(fw.empty() ? NAN : fw.front(), 4),
         number_or_missing(r.value(keys::kRegistrationSeconds), 1),
         number_or_missing(r.value(keys::kClosureSeconds), 1),
         number_or_missing(r.value(keys::kGraphSolveSeconds), 3),
         number_or_missing(r.value(keys::kGraphSolveIterations), 0),
         number_or_missing(r.value(keys::kInformationInflation), 1)});
  }
  return t;
}

}  // namespace

double median_finite(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

std::vector<TrajectoryKind> graph_trajectories(const std::string& matcher_name) {
  return {{"chained_", matcher_name + " chained (odometry)", "#e07b00"},
          {"graph_", "pose graph + loop closures", "#1f60c0"},
          {"false_robust_", "pose graph + a false closure, robust loss", "#2a9d3a"},
          {"false_plain_", "pose graph + a false closure, no robust loss", "#c0392b"}};
}

ReportSection pose_graph_report(const ExperimentConfig& config, const PoseGraphParams& params,
                                const std::vector<PoseGraphMethod>& methods, const std::vector<RunSpec>& runs,
                                const std::vector<const RunRow*>& rows) {
  MethodRows odometry;
  std::vector<MethodRows> filters;
  std::vector<MethodRows> groups = group_by_method(config, runs, rows);
  for (std::size_t m = 0; m < methods.size(); ++m) {
    if (methods[m].is_filter)
      filters.push_back(std::move(groups.at(m)));
    else
      odometry = std::move(groups.at(m));
  }
  const PoseGraphMethod* matcher = nullptr;
  for (const PoseGraphMethod& m : methods)
    if (!m.is_filter) matcher = &m;

  ReportSection section;
  const std::string loss = to_string(params.graph.loss);
  section.notes =
      "An extension beyond the thesis (§7.2 future work: globally consistent n-scan registration after Lu "
      "and Milios). The first " +
      (params.scans ? std::to_string(params.scans) : std::string("(all)")) +
      " scans of the synthetic campus; " + odometry.name + " (" +
      (matcher ? matcher->odometry.matcher.name() : "") + " on a " +
      (matcher ? matcher->odometry.sampler.name() : "") +
      " sample) registers each scan onto the previous one from the odometry increment and the relative poses "
      "are chained from the true first pose (run_odometry). The pose graph has one node per scan, one edge "
      "per "
      "registration and one per accepted loop closure; each edge's information is the registration's Hessian "
      "(R = H⁻¹, eq. 3.50) carried from the Pose6 parameters to the factor's log-map error; loop closures go "
      "through a " +
      loss + " loss (scale " + format_number(params.graph.loss_scale, 1, "–") +
      " in Mahalanobis units); the first pose is held fixed; Ceres, Levenberg–Marquardt, sparse normal "
      "Cholesky. Loop-closure candidates: within " +
      format_number(params.loop_closure.radius, 1, "–") + " m of a pose ≥ " +
      std::to_string(params.loop_closure.min_index_gap) + " scans and ≥ " +
      format_number(params.loop_closure.min_path_gap, 0, "–") + " m of path earlier, one every " +
      std::to_string(params.loop_closure.stride) +
      " scans; accepted when converged, mean score per point ≤ " +
      format_number(params.loop_closure.max_mean_score, 1, "–") + ", matched fraction ≥ " +
      format_number(params.loop_closure.min_matched_fraction, 2, "–") + " and correction ≤ " +
      format_number(params.loop_closure.max_correction_m, 1, "–") + " m / " +
      format_number(params.loop_closure.max_correction_deg, 0, "–") + "°; " +
      std::to_string(params.closure_rounds) +
      " round(s) of candidates, the first along the chain, the next along the graph solved with the closures "
      "accepted so far (better guesses), each pair tried once; the closure registrations may use their own "
      "matcher settings (closure_settings, e.g. ML-NDT's wide basin). R = H⁻¹ is far too confident for the "
      "chain: " +
      (params.calibrate_information ? std::string("the odometry edges' and the closures' information are "
                                                  "rescaled by their variance components "
                                                  "(Helmert / Förstner: σ²_g = v_gᵀW_g v_g / r_g per edge "
                                                  "group, iterated; the redundancies from "
                                                  "the chain's accumulated covariance) — from the residuals, "
                                                  "not from the ground truth (table: "
                                                  "inflation = σ²_odometry); ")
                                    : std::string("no calibration (calibrate_information: false); ")) +
      "the graph is solved first without the robust loss from the chain (a true closure's error there is far "
      "outside the loss' scale and would be switched off at once), then with it. Robustness check: " +
      std::to_string(params.false_closures) +
      " false closure(s) (\"same place\", identity, with the median accepted closure's information) between "
      "poses truly ≥ " +
      format_number(params.false_closure_min_distance, 0, "–") +
      " m apart are added to the solved map and the graph solved again with and without the robust loss. The "
      "plane-SLAM "
      "filters "
      "(the plane_slam kind's run, E19's settings) see the same odometry draw and true plane landmarks. ATE: "
      "RMS position error after SE(3) Umeyama alignment; Wulf: eqs. 6.1–6.3 (no alignment); Kümmerle: eq. "
      "6.6 "
      "over consecutive scans. " +
      std::to_string(odometry.rows.size()) +
      " repetition(s); tables give medians. Deviations: no thesis numbers exist for this extension; the "
      "filters that stop early (UKF, CKF: O(n³) per step) are compared on their prefix in a second table; "
      "registrations whose Hessian gives no positive-definite information get the median step information "
      "(counted: " +
      format_number(odometry.rows.empty() ? NAN : odometry.rows.front()->value(keys::kFallbackInformation), 0,
                    "–") +
      " in repetition 1).";

  Table whole = metrics_header("ATE, Wulf and Kümmerle over the route, per trajectory", "metrics",
                               "Medians over the repetitions; a filter that stops early is scored on its own "
                               "scans (see the next table).");
  for (const TrajectoryKind& k : graph_trajectories(odometry.name))
    add_metric_row(whole, k.label, odometry.rows, k.prefix);
  for (const MethodRows& f : filters) add_metric_row(whole, f.name + " (plane SLAM)", f.rows, "filter_");
  section.tables.push_back(whole);

  std::vector<std::size_t> shorter;
  const double full = median_finite(row_values(odometry.rows, keys::kScans));
  for (const MethodRows& f : filters) {
    const double n = median_finite(row_values(f.rows, keys::kScans));
    if (std::isfinite(n) && n < full &&
        std::find(shorter.begin(), shorter.end(), std::size_t(n)) == shorter.end())
      shorter.push_back(static_cast<std::size_t>(n));
  }
  for (std::size_t n : shorter) {
    Table t = metrics_header("The same over the first " + std::to_string(n) + " scans",
                             "metrics_" + std::to_string(n),
                             "The chained odometry and the pose graphs cut to the first scans (re-aligned), "
                             "beside the filters that ran this far.");
    for (const TrajectoryKind& k : graph_trajectories(odometry.name))
      if (k.prefix == "chained_" || k.prefix == "graph_")
        add_prefix_row(t, k.label, odometry.rows, k.prefix, n);
    for (const MethodRows& f : filters)
      if (std::size_t(median_finite(row_values(f.rows, keys::kScans))) == n)
        add_prefix_row(t, f.name + " (plane SLAM)", f.rows, "filter_", n);
    section.tables.push_back(t);
  }
  if (!odometry.rows.empty()) section.tables.push_back(closure_table(odometry));
  if (!odometry.rows.empty()) section.figures = pose_graph_figures(odometry, filters);
  section.claims = pose_graph_claims(config, params, odometry);
  if (!odometry.rows.empty()) {
    const RunRow& first = *odometry.rows.front();
    for (const auto& [prefix, name] :
         std::vector<std::pair<std::string, std::string>>{{"truth", "ground truth"},
                                                          {"chained_trajectory", "chained"},
                                                          {"graph_trajectory", "pose graph"}}) {
      ReportTrajectory file;
      file.id =
          "trajectory_" + (prefix == "truth" ? std::string("truth") : prefix.substr(0, prefix.find('_')));
      file.caption = name + " (repetition 1; stamp = scan index)";
      const PoseList poses = series_to_poses(series_or_empty(first, prefix));
      for (std::size_t k = 0; k < poses.size(); ++k) file.poses.push_back({static_cast<double>(k), poses[k]});
      section.trajectories.push_back(std::move(file));
    }
  }
  return section;
}

}  // namespace sextant
