// run_view: the page holds the run (the map decoded back point by point, every pose, the steps'
// verdicts, reasons and errors as written in), marks every untrusted, not converged and recovered
// step, keeps the map under its cap, decimates a line only where it stays within its tolerance, escapes
// every text, is well-formed, loads nothing from the network, and refuses inconsistent views.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "sextant/core/error.hpp"
#include "sextant/eval/run_view.hpp"
#include "sextant/eval/trajectory_evaluation.hpp"
#include "sextant_test/run_view_page.hpp"
#include "xml_check.hpp"

namespace sextant {
namespace {

Eigen::Isometry3d at(double x, double y, double z) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(x, y, z);
  return T;
}

/// 30 poses on an arc, the reference 0.5 m beside them, a map of 1000 points, 29 steps: step 4
/// untrusted, step 9 not converged, step 12 recovered, step 20 without an error.
RunView sample_view() {
  RunView view;
  view.title = "sample run";
  for (int i = 0; i < 1000; ++i)
    view.map.push_back(
        Eigen::Vector3f(0.1f * static_cast<float>(i), std::sin(0.01f * static_cast<float>(i)), 0.5f));
  for (int i = 0; i < 30; ++i) {
    view.estimate.push_back(at(2.0 * i, 0.01 * i * i, 0.1 * i));
    view.reference.push_back(at(2.0 * i, 0.01 * i * i + 0.5, 0.1 * i));
  }
  for (std::size_t i = 0; i + 1 < 30; ++i) {
    RunViewStep s;
    s.number = i;
    s.pose = i + 1;
    s.from_scan = 100 + i;
    s.to_scan = 101 + i;
    s.stamp = 1565943695.228028 + 0.1 * static_cast<double>(i);
    s.trust = s.first_trust = "ok";
    s.status = "converged";
    s.error_m = 0.01 * static_cast<double>(i);
    s.error_deg = 0.1 * static_cast<double>(i);
    view.steps.push_back(s);
  }
  RunViewStep& untrusted = view.steps[4];
  untrusted.trusted = false;
  untrusted.trust = untrusted.first_trust = "low_overlap";
  untrusted.recovery = "last_motion";
  untrusted.reason = "overlap 0.31 below 0.5";
  RunViewStep& diverged = view.steps[9];
  diverged.trusted = diverged.converged = false;
  diverged.trust = "not_converged";
  diverged.reason = "no convergence in 100 iterations";
  RunViewStep& recovered = view.steps[12];
  recovered.recovered = true;
  recovered.first_trust = "suspect";
  recovered.recovery = "wide_basin";
  view.steps[20].error_m = view.steps[20].error_deg = NAN;
  return view;
}

TEST(RunView, PageHoldsTheRunAndMarksEveryUntrustedStep) {
  const RunView view = sample_view();
  const std::string page = render_run_view(view);
  const nlohmann::json data = test::page_data(page);
  ASSERT_TRUE(data.is_object());
  const Eigen::Vector3d origin(data["origin"][0], data["origin"][1], data["origin"][2]);
  // The map, point by point (relative to the scene's centre, float32).
  ASSERT_EQ(data["map"]["count"], 1000);
  const std::vector<Eigen::Vector3f> map = test::page_points(data["map"]["points"]);
  ASSERT_EQ(map.size(), 1000u);
  for (std::size_t i = 0; i < map.size(); ++i)
    ASSERT_LT((map[i].cast<double>() + origin - view.map[i].cast<double>()).norm(), 1e-5) << i;
  // Every pose of the estimate, and the reference's line.
  ASSERT_EQ(data["estimate"]["count"], 30);
  const std::vector<Eigen::Vector3f> poses = test::page_points(data["estimate"]["points"]);
  ASSERT_EQ(poses.size(), 30u);
  for (std::size_t i = 0; i < 30; ++i)
    EXPECT_LT((poses[i].cast<double>() + origin - view.estimate[i].translation()).norm(), 1e-5) << i;
  EXPECT_GE(test::page_points(data["reference"]["points"]).size(), 2u);
  // The line keeps the marked steps' poses (5, 10, 13), and its ends.
  const std::vector<std::size_t> line = data["estimate"]["line"];
  for (const std::size_t pose : {0u, 5u, 10u, 13u, 29u})
    EXPECT_NE(std::find(line.begin(), line.end(), pose), line.end()) << pose;
  // The steps, field by field.
  const nlohmann::json& steps = data["steps"];
  ASSERT_EQ(steps["count"], 29);
  for (const char* field : {"number", "pose", "from", "to", "stamp", "verdict", "converged", "error_m",
                            "error_deg", "trust", "first_trust", "recovery", "reason", "status"})
    ASSERT_EQ(steps[field].size(), 29u) << field;
  const auto text = [&](const char* field, std::size_t i) {
    return steps["texts"][steps[field][i].get<int>()];
  };
  for (std::size_t i = 0; i < 29; ++i) {
    const RunViewStep& s = view.steps[i];
    EXPECT_EQ(steps["verdict"][i], static_cast<int>(verdict_of(s))) << i;
    EXPECT_EQ(steps["pose"][i], s.pose);
    EXPECT_EQ(steps["to"][i], s.to_scan);
    EXPECT_DOUBLE_EQ(steps["stamp"][i].get<double>(), s.stamp);
    EXPECT_EQ(text("trust", i), s.trust);
    EXPECT_EQ(text("reason", i), s.reason);
    EXPECT_EQ(text("recovery", i), s.recovery);
    if (std::isnan(s.error_m)) {
      EXPECT_TRUE(steps["error_m"][i].is_null()) << i;
    } else {
      EXPECT_NEAR(steps["error_m"][i].get<double>(), s.error_m, 1e-6 * (1.0 + s.error_m)) << i;
    }
  }
  EXPECT_EQ(steps["verdict"][4], static_cast<int>(StepVerdict::untrusted));
  EXPECT_EQ(steps["verdict"][9], static_cast<int>(StepVerdict::not_converged));
  EXPECT_EQ(steps["verdict"][12], static_cast<int>(StepVerdict::recovered));
  // The legend counts each marker once.
  EXPECT_NE(page.find("untrusted <span class=\"sx-count\">1 step</span>"), std::string::npos);
  EXPECT_NE(page.find("not converged <span class=\"sx-count\">1 step</span>"), std::string::npos);
  EXPECT_NE(page.find("recovered <span class=\"sx-count\">1 step</span>"), std::string::npos);
  // The error scale is the 95th percentile of the finite errors (28 of them, 0 … 0.28 without 0.20).
  EXPECT_NEAR(data["error_scale"].get<double>(), 0.26, 1e-12);
}

TEST(RunView, MapIsCappedEvenlyAndItsNonFinitePointsDropped) {
  RunView view = sample_view();
  view.map = PointCloud();
  for (int i = 0; i < 10000; ++i)
    view.map.push_back(Eigen::Vector3f(0.01f * static_cast<float>(i), 1.0f, 2.0f));
  view.map[7].x() = NAN, view.map[70].y() = INFINITY, view.map[700].z() = -INFINITY;
  view.max_map_points = 1000;
  const std::string page = render_run_view(view);
  const nlohmann::json data = test::page_data(page);
  const Eigen::Vector3d origin(data["origin"][0], data["origin"][1], data["origin"][2]);
  std::vector<Eigen::Vector3f> finite;
  for (const Eigen::Vector3f& p : view.map.points())
    if (p.allFinite()) finite.push_back(p);
  ASSERT_EQ(finite.size(), 9997u);
  const std::vector<Eigen::Vector3f> map = test::page_points(data["map"]["points"]);
  ASSERT_EQ(map.size(), 1000u);
  for (std::size_t i = 0; i < map.size(); ++i)  // point ⌊i·9997/1000⌋ of the finite ones
    ASSERT_LT((map[i].cast<double>() + origin - finite[i * 9997 / 1000].cast<double>()).norm(), 1e-5) << i;
  EXPECT_NE(page.find("1\u2009000 of 9\u2009997 points"), std::string::npos);
}

/// The largest distance of a dropped vertex from the kept polyline's segment over it.
double worst_dropped(const std::vector<Eigen::Vector3d>& points, const std::vector<std::size_t>& kept) {
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < kept.size(); ++k)
    for (std::size_t i = kept[k] + 1; i < kept[k + 1]; ++i) {
      const Eigen::Vector3d a = points[kept[k]], d = points[kept[k + 1]] - a;
      const double t = std::clamp((points[i] - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
      worst = std::max(worst, (a + t * d - points[i]).norm());
    }
  return worst;
}

TEST(RunView, DecimationKeepsTheShapeTheMarkedStepsAndTheColourChanges) {
  std::vector<Eigen::Vector3d> straight;
  for (int i = 0; i < 1000; ++i) straight.emplace_back(0.1 * i, 0.0, 0.0);
  EXPECT_EQ(decimate_polyline(straight, {}, 1e-3, 0.0, {}), (std::vector<std::size_t>{0, 999}));
  std::vector<bool> keep(1000, false);
  keep[500] = keep[501] = true;
  EXPECT_EQ(decimate_polyline(straight, {}, 1e-3, 0.0, keep), (std::vector<std::size_t>{0, 500, 501, 999}));
  // A right angle keeps its corner (vertex 500, (50, 0)); a sideways bump below the tolerance is
  // dropped, above it kept.
  std::vector<Eigen::Vector3d> corner = straight;
  for (int i = 500; i < 1000; ++i)
    corner[static_cast<std::size_t>(i)] = Eigen::Vector3d(50.0, 0.1 * (i - 500), 0.0);
  EXPECT_EQ(decimate_polyline(corner, {}, 1e-3, 0.0, {}), (std::vector<std::size_t>{0, 500, 999}));
  std::vector<Eigen::Vector3d> bump = straight;
  bump[300].y() = 0.0009;
  EXPECT_EQ(decimate_polyline(bump, {}, 1e-3, 0.0, {}).size(), 2u);
  bump[300].y() = 0.0011;
  EXPECT_EQ(decimate_polyline(bump, {}, 1e-3, 0.0, {}), (std::vector<std::size_t>{0, 299, 300, 301, 999}));
  // The colour: a jump in value keeps the vertices on both sides; a linear ramp needs only the ends;
  // NaN runs keep their edges.
  std::vector<double> values(1000, 1.0);
  for (std::size_t i = 600; i < 1000; ++i) values[i] = 2.0;
  EXPECT_EQ(decimate_polyline(straight, values, 1e-3, 0.05, {}),
            (std::vector<std::size_t>{0, 599, 600, 999}));
  for (std::size_t i = 0; i < 1000; ++i) values[i] = 0.001 * static_cast<double>(i);
  EXPECT_EQ(decimate_polyline(straight, values, 1e-3, 0.05, {}), (std::vector<std::size_t>{0, 999}));
  std::fill(values.begin(), values.begin() + 100, std::nan(""));
  EXPECT_EQ(decimate_polyline(straight, values, 1e-3, 0.05, {}), (std::vector<std::size_t>{0, 99, 100, 999}));
  std::fill(values.begin() + 900, values.end(), std::nan(""));
  EXPECT_EQ(decimate_polyline(straight, values, 1e-3, 0.05, {}),
            (std::vector<std::size_t>{0, 99, 100, 899, 900, 999}));
  // Non-finite vertices are left out; a wandering path's dropped vertices all lie within the tolerance.
  straight[10].x() = NAN;
  EXPECT_EQ(decimate_polyline(straight, {}, 1e-3, 0.0, {}), (std::vector<std::size_t>{0, 999}));
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<Eigen::Vector3d> walk{Eigen::Vector3d::Zero()};
  double heading = 0.0;
  for (int i = 1; i < 20000; ++i) {  // 1 m steps, the heading a random walk of 0.3° a step
    heading += 0.005 * noise(rng);
    walk.push_back(walk.back() + Eigen::Vector3d(std::cos(heading), std::sin(heading), 0.01 * noise(rng)));
  }
  const std::vector<std::size_t> kept = decimate_polyline(walk, {}, 0.05, 0.0, {});
  EXPECT_LE(worst_dropped(walk, kept), 0.05);
  EXPECT_LT(kept.size(), walk.size() / 2);  // and it did drop some
  EXPECT_EQ(kept.front(), 0u);
  EXPECT_EQ(kept.back(), walk.size() - 1);
}

TEST(RunView, VerdictsComeFromTheFlagsInOrder) {
  RunViewStep s;
  EXPECT_EQ(verdict_of(s), StepVerdict::trusted);
  s.recovered = true;
  EXPECT_EQ(verdict_of(s), StepVerdict::recovered);
  s.trusted = false;
  EXPECT_EQ(verdict_of(s), StepVerdict::untrusted);
  s.trust = "not_converged";
  EXPECT_EQ(verdict_of(s), StepVerdict::not_converged);
  s.trust = "suspect", s.converged = false;
  EXPECT_EQ(verdict_of(s), StepVerdict::not_converged);
  s.assessed = false;
  EXPECT_EQ(verdict_of(s), StepVerdict::unassessed);
  EXPECT_EQ(to_string(StepVerdict::not_converged), "not converged");
}

TEST(RunView, PageIsWellFormedEscapedAndOffline) {
  RunView view = sample_view();
  const std::string evil = "</script><b onload=\"x\">&'q'";
  view.title = "T " + evil;
  view.caption = "C " + evil;
  view.estimate_name = "E " + evil;
  view.steps[4].reason = "R " + evil;
  const std::string page = render_run_view(view);
  EXPECT_EQ(page.find("<b onload"), std::string::npos);
  const std::string escaped = "&lt;/script&gt;&lt;b onload=&quot;x&quot;&gt;&amp;&#39;q&#39;";
  EXPECT_NE(page.find("<title>T " + escaped + "</title>"), std::string::npos);
  EXPECT_NE(page.find("C " + escaped), std::string::npos);
  EXPECT_NE(page.find("E " + escaped), std::string::npos);
  // In the JSON the reason keeps its text, with '<', '>' and '&' as \u escapes.
  EXPECT_NE(page.find("\"R \\u003c/script\\u003e\\u003cb onload=\\\"x\\\"\\u003e\\u0026'q'\""),
            std::string::npos);
  EXPECT_EQ(test::page_data(page)["steps"]["texts"][test::page_data(page)["steps"]["reason"][4].get<int>()],
            "R " + evil);
  // Eight scripts (three.js, its five line scripts, the data, the viewer); the markup around them is XML.
  EXPECT_EQ(testing::occurrences(page, "<script"), 8);
  const testing::XmlCheck xml = testing::check_xml(test::page_markup(page));
  EXPECT_TRUE(xml.ok) << xml.error;
  EXPECT_EQ(xml.elements.at("canvas"), 1);
  // Nothing of ours names a URL or requests anything (the libraries' own comments name their authors).
  std::string ours = page;
  for (std::size_t a = ours.find("<script>\n"); a != std::string::npos; a = ours.find("<script>\n", a + 1)) {
    const std::size_t b = ours.find("</script>", a);
    const std::string body = ours.substr(a, b - a);
    if (body.find("sxRunPanel") == std::string::npos) ours.erase(a + 9, b - a - 9);  // a library
  }
  for (const std::string request :
       {"http://", "https://", " src=", "href=", "fetch(", "XMLHttpRequest", "import("})
    EXPECT_EQ(testing::occurrences(ours, request), 0) << request;
}

TEST(RunView, InconsistentViewsAndMissingScriptsAreRefused) {
  RunView bad = sample_view();
  bad.reference.pop_back();
  EXPECT_THROW(render_run_view(bad), std::invalid_argument);
  bad = sample_view();
  bad.steps[3].pose = 30;
  EXPECT_THROW(render_run_view(bad), std::invalid_argument);
  bad = sample_view();
  bad.max_map_points = 0;
  EXPECT_THROW(render_run_view(bad), std::invalid_argument);
  try {
    render_run_view(sample_view(), "/nonexistent/sextant/three");
    FAIL() << "no error for a missing three.js";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/sextant/three/three.min.js"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("libjs-three"), std::string::npos) << e.what();
  }
  // An empty run still renders (no steps, no map, one pose).
  RunView empty;
  empty.estimate.push_back(Eigen::Isometry3d::Identity());
  EXPECT_EQ(test::page_data(render_run_view(empty))["steps"]["count"], 0);
}

TEST(RunView, EvaluationViewHasEveryPoseAndItsError) {
  Trajectory reference, estimate;
  for (int i = 0; i < 40; ++i) {
    reference.push_back({100.0 + i, at(1.0 * i, 0.02 * i * i, 0.0)});
    estimate.push_back({100.0 + i, at(1.0 * i + 3.0, 0.02 * i * i + 4.0, 0.0)});  // 5 m off
  }
  const AssociatedPoses pairs = associate_by_stamp(estimate, reference, 0.01);
  TrajectoryEvaluationSettings settings;
  settings.alignment = Alignment::none;
  const TrajectoryEvaluation e = evaluate_trajectory(pairs.estimate, pairs.reference, settings);
  const RunView view = evaluation_run_view(pairs, e, "eval", true);
  ASSERT_EQ(view.steps.size(), 40u);
  EXPECT_TRUE(view.colour_by_error);
  for (const RunViewStep& s : view.steps) {
    EXPECT_NEAR(s.error_m, 5.0, 1e-9);
    EXPECT_NEAR(s.error_deg, 0.0, 1e-9);
    EXPECT_DOUBLE_EQ(s.stamp, 100.0 + static_cast<double>(s.number));
    EXPECT_EQ(verdict_of(s), StepVerdict::unassessed);
  }
  const nlohmann::json data = test::page_data(render_run_view(view));
  EXPECT_EQ(data["steps"]["name"], "pose");
  EXPECT_TRUE(data["colour_by_error"].get<bool>());
  EXPECT_TRUE(std::isnan(evaluation_run_view(pairs, e, "eval", false).steps[3].stamp));  // indices, not times
}

}  // namespace
}  // namespace sextant
