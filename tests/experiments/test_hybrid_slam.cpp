// Hybrid SLAM (E21): the relative pose → control mapping with known answers, FbML-NDT's motion on
// campus scans against the true increment, the hybrid EKF against the odometry-driven EKF on a
// short stretch (what holds and why, see the test), and E21's quick profile end to end (rows, series, tables,
// figures, claims).
#include <gtest/gtest.h>

#include "kit/fbmlndt_motion.hpp"
#include "kit/plane_slam_record.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "sextant/filters/plane_slam.hpp"
#include "sextant/filters/plane_slam_model.hpp"
#include "sextant/synth/campus.hpp"
#include "sextant/synth/odometry.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;

TEST(HybridSlam, IncrementFromRelativePoseReproducesTheChainedPose) {
  Vector6d from;
  from << 3.0, -2.0, 0.5, 0.05, -0.03, 2.5;
  const Pose6 rel{1.2, 0.3, 0.05, 0.01, 0.02, 0.15};
  const MotionIncrement m = increment_from_relative_pose(from, to_isometry(rel), Matrix6d::Identity() * 1e-4);
  const Eigen::Isometry3d expected = to_isometry(Pose6::from_vector(from)) * to_isometry(rel);
  const Eigen::Isometry3d got = to_isometry(Pose6::from_vector(PlaneSlamModel().process(from, m.u)));
  EXPECT_LT((got.translation() - expected.translation()).norm(), 1e-12);
  EXPECT_LT((got.linear() - expected.linear()).norm(), 1e-12);
  EXPECT_EQ(m.u.head<3>(), Eigen::Vector3d(1.2, 0.3, 0.05)) << "δt is the relative translation itself";
  EXPECT_EQ(Eigen::LLT<Matrix6d>(m.Q).info(), Eigen::Success);
}

TEST(HybridSlam, AtZeroOrientationTheCovarianceIsUnchanged) {
  // δo = euler(R(a)) − 0 = a: J = I, Q = Σ.
  Matrix6d A = Matrix6d::Random();
  const Matrix6d sigma = A * A.transpose() + Matrix6d::Identity() * 1e-3;
  const Pose6 rel{0.8, -0.1, 0.0, 0.02, -0.01, 0.1};
  const MotionIncrement m = increment_from_relative_pose(Vector6d::Zero(), to_isometry(rel), sigma);
  EXPECT_LT((m.Q - sigma).norm(), 1e-6 * sigma.norm());
  // Elsewhere the angle block of J is not the identity but keeps δt's block and is invertible.
  Vector6d from = Vector6d::Zero();
  from[3] = 0.1, from[4] = 0.3, from[5] = 1.0;
  const Matrix6d J = relative_pose_jacobian(from, rel.vector());
  EXPECT_TRUE((J.topLeftCorner<3, 3>().isIdentity()));
  EXPECT_TRUE((J.topRightCorner<3, 3>().isZero() && J.bottomLeftCorner<3, 3>().isZero()));
  EXPECT_GT((J.bottomRightCorner<3, 3>() - Eigen::Matrix3d::Identity()).norm(), 0.01);
  EXPECT_GT(std::abs(J.determinant()), 0.5);
}

const synth::Campus& campus() {
  static const synth::Campus c = [] {
    synth::CampusSettings s;
    s.odometry.model = "gaussian";
    return synth::generate_campus(s, 1);
  }();
  return c;
}

TEST(HybridSlam, FbmlndtMotionOnCampusScansIsTheTrueIncrement) {
  const synth::Campus& c = campus();
  const PlaneSlamSettings s;
  // The pyramid over the bounding box, as measured for this test (robust_bounds moves the campus'
  // cells and FbML-NDT then disagrees with the odometry at scan 13: not investigated yet, issue 22).
  FbmlndtMotion hybrid(YAML::Load("{preset: default, bounds_quantile: 0}"), HybridParams{}, "<test>");
  PointCloud previous = c.scan(10).cloud;
  double matcher_error = 0.0, odometry_error = 0.0;
  for (std::size_t k = 11; k <= 14; ++k) {
    const PointCloud current = c.scan(k).cloud;
    Rng rng(k);
    const PlaneExtraction e = extract_planes(current, s.extraction, rng);
    const Vector6d from = to_pose6(c.ground_truth[k - 1]).vector();
    const MotionIncrement odometry{odometry_increment(to_pose6(c.odometry[k - 1]), to_pose6(c.odometry[k])),
                                   s.process_noise()};
    const HybridMotion m = hybrid.motion(previous, current, e, from, odometry);
    ASSERT_TRUE(m.matched) << "scan " << k << ": " << m.reason;
    const Vector6d truth = odometry_increment(to_pose6(c.ground_truth[k - 1]), to_pose6(c.ground_truth[k]));
    const Vector6d d = m.motion.u - truth;
    // Within 15 cm and 0.6° of the true increment (FbML-NDT on the campus underestimates the forward
    // motion by 5–12 cm per step; the gaussian odometry is off by ≈ 28 cm).
    EXPECT_LT(d.head<3>().norm(), 0.15) << "scan " << k;
    for (int i = 3; i < 6; ++i) EXPECT_LT(std::abs(wrap_angle(d[i])), 0.01) << "scan " << k << " angle " << i;
    matcher_error += d.head<3>().norm();
    odometry_error += (odometry.u - truth).head<3>().norm();
    EXPECT_EQ(Eigen::LLT<Matrix6d>(m.motion.Q).info(), Eigen::Success) << "Q positive definite";
    EXPECT_GT(m.seconds, 0.0);
    previous = current;
  }
  EXPECT_LT(matcher_error, 0.6 * odometry_error) << "closer to the truth than the odometry on average";
}

TEST(HybridSlam, HybridEkfIsCloserEarlyAndBoundedAtTheEnd) {
  const synth::Campus& c = campus();
  constexpr std::size_t kScans = 30;
  CampusScans data;
  data.campus = &c;
  for (std::size_t k = 0; k < kScans; ++k) data.clouds.push_back(c.scan(k).cloud);
  PlaneSlamParams params;
  params.landmarks = LandmarkSource::kExtracted;
  params.odometry = OdometrySource::kResample;
  params.hybrid.noise_scale = 1000.0;  // as E21 (alarms: the defaults, as E21)
  PlaneSlamSettings s;
  s.sigma_xy = 0.2;
  s.sigma_yaw = 0.0174533;
  s.sigma_roll_pitch = 0.0174533;
  PlaneSlamMethod hybrid;
  hybrid.name = "ekf_fbmlndt";
  hybrid.motion = MotionSource::kFbmlndt;
  hybrid.matcher = YAML::Load("{preset: default, bounds_quantile: 0}");  // as measured (see above)
  const RecordedRun odo = record_plane_slam(data, params, s, kScans, 7);
  const RecordedRun hyb = record_plane_slam(data, params, s, kScans, 7, hybrid);
  const auto error = [&](const RecordedRun& r, std::size_t k) {
    return (r.steps[k].pose.head<3>() - c.ground_truth[k].translation()).norm();
  };
  ASSERT_EQ(hyb.steps.size(), kScans);
  int matched = 0;
  for (const RecordedStep& st : hyb.steps) matched += st.matched_motion == 1;
  EXPECT_GE(matched, static_cast<int>(kScans) - 6) << "the matcher predicts nearly every step";
  EXPECT_EQ(odo.steps.back().matched_motion, -1);
  EXPECT_EQ(odo.steps.back().registration_seconds, 0.0);
  EXPECT_GT(hyb.steps.back().registration_seconds, 0.0);
  const auto rotation = [&](const RecordedRun& r, std::size_t k) {
    const Eigen::Matrix3d R = rotation_from_euler(r.steps[k].pose[3], r.steps[k].pose[4], r.steps[k].pose[5]);
    return Eigen::AngleAxisd(R.transpose() * c.ground_truth[k].linear()).angle();
  };
  // What holds: over the first 20 scans the hybrid EKF is closer to the truth than
  // the odometry-driven one (FbML-NDT is off by 5–12 cm per step, the odometry by ≈ 28 cm). It does
  // not end closer at scan 30: near scan 21 a registration falls into a wrong minimum 0.5 m away,
  // inside the alarm band (0.6 m, so that the odometry's own 20 cm noise rarely trips it), and the
  // filter keeps that error; it ends within 0.5 m of the odometry-driven EKF and far
  // inside the odometry's dead reckoning.
  double hybrid_early = 0.0, odometry_early = 0.0;
  for (std::size_t k = 1; k <= 20; ++k) hybrid_early += error(hyb, k), odometry_early += error(odo, k);
  EXPECT_LT(hybrid_early, 0.8 * odometry_early);  // measured: 0.67
  const double dead_reckoning =
      (to_isometry(hyb.odometry.back()).translation() - c.ground_truth[kScans - 1].translation()).norm();
  EXPECT_LT(error(hyb, kScans - 1), error(odo, kScans - 1) + 0.5);
  EXPECT_LT(error(hyb, kScans - 1), 0.25 * dead_reckoning);
  EXPECT_LT(rotation(hyb, kScans - 1), 0.02);
}
TEST(HybridSlam, QuickProfileOutputShape) {
  TempDir tmp;
  const RunnerSummary s = test::run_quick(test::experiments_dir() / "e21_hybrid_slam.yaml", tmp / "results");
  ASSERT_EQ(s.failed, 0u);
  const auto rows = read_rows(s.folder / kRunsJsonl).rows;
  ASSERT_EQ(rows.size(), 6u);  // 3 filters × {odometry, fbmlndt}, 1 repetition
  for (const RunRow& row : rows) {
    const bool hybrid = row.method.find("_fbmlndt") != std::string::npos;
    const std::size_t n = row.method.rfind("ukf", 0) == 0 ? 15u : 30u;
    EXPECT_EQ(row.series.at("error_m").size(), n) << row.method;
    EXPECT_EQ(row.series.at("registration_ms").size(), n) << row.method;
    EXPECT_EQ(row.series.at("extraction_ms").size(), n) << row.method;
    EXPECT_EQ(row.value("registration_ms_mean") > 0.0, hybrid) << row.method;
    if (hybrid) {
      EXPECT_GT(row.value("motion_matched_fraction"), 0.5) << row.method;
    }
    EXPECT_GT(row.value("extraction_ms_mean"), 0.0) << row.method;
  }
  const ReportSummary r = write_report({tmp / "results"}, tmp / "report");
  const auto section = tmp / "report" / "e21_hybrid_slam";
  for (const char* f :
       {"hybrid_accuracy.md", "hybrid_cost.md", "hybrid_error.svg", "hybrid_rotation_error.svg"})
    EXPECT_TRUE(std::filesystem::exists(section / f)) << f;
  const std::string table = test::read_text(section / "hybrid_accuracy.md");
  for (const char* m : {"odometry (dead reckoning)", "ekf_fbmlndt", "ukf_fbmlndt", "seif_fbmlndt"})
    EXPECT_NE(table.find(m), std::string::npos) << m;
  const std::string html = test::read_text(r.index_html);
  for (const char* claim : {"ekf: the hybrid (FbML-NDT-driven) filter is more accurate",
                            "seif: the hybrid costs little extra", "ukf: the hybrid costs little extra"})
    EXPECT_NE(html.find(claim), std::string::npos) << claim;
}

}  // namespace
}  // namespace sextant
