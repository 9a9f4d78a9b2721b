// `sextant eval --view`: the page of two TUM files 5 m apart holds every pose, its time and its ATE
// error (5 m without alignment); KITTI files (no time) give no times; a view whose folder is missing
// is an error naming it.
#include <gtest/gtest.h>

#include <string>

#include "sextant/core/io/trajectory_io.hpp"
#include "sextant_test/cli_run.hpp"
#include "sextant_test/run_view_page.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

TEST(EvalViewCli, PageHoldsEveryPoseItsTimeAndItsError) {
  test::TempDir tmp;
  Trajectory ref, est;
  for (int i = 0; i < 25; ++i) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Eigen::Vector3d(2.0 * i, 0.05 * i * i, 0.0);
    ref.push_back({10.0 + i, T});
    T.translation() += Eigen::Vector3d(3, 4, 0);
    est.push_back({10.0 + i, T});
  }
  write_tum_trajectory(tmp / "ref.tum", ref);
  write_tum_trajectory(tmp / "est.tum", est);
  const test::CliRun r =
      test::run_cli(SEXTANT_CLI, "eval " + (tmp / "ref.tum").string() + " " + (tmp / "est.tum").string() +
                                     " --align none --view " + (tmp / "eval.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("wrote: " + (tmp / "eval.html").string()), std::string::npos) << r.output;
  const nlohmann::json data = test::page_data(test::page_text(tmp / "eval.html"));
  ASSERT_TRUE(data.is_object());
  EXPECT_EQ(data["estimate"]["count"], 25);
  EXPECT_TRUE(data["reference"].is_object());
  EXPECT_EQ(data["map"]["count"], 0);
  const nlohmann::json& steps = data["steps"];
  ASSERT_EQ(steps["count"], 25);
  EXPECT_EQ(steps["name"], "pose");
  for (std::size_t i = 0; i < 25; ++i) {
    EXPECT_NEAR(steps["error_m"][i].get<double>(), 5.0, 1e-6) << i;
    EXPECT_NEAR(steps["stamp"][i].get<double>(), 10.0 + static_cast<double>(i), 1e-9) << i;
    EXPECT_EQ(steps["verdict"][i], 4) << i;  // no verdict: nothing marked
  }
  EXPECT_TRUE(data["colour_by_error"].get<bool>());

  // KITTI files: paired by index, no times.
  write_kitti_trajectory(tmp / "ref.txt", ref);
  write_kitti_trajectory(tmp / "est.txt", est);
  ASSERT_EQ(
      test::run_cli(SEXTANT_CLI, "eval " + (tmp / "ref.txt").string() + " " + (tmp / "est.txt").string() +
                                     " --view " + (tmp / "kitti.html").string())
          .exit_code,
      0);
  const nlohmann::json kitti = test::page_data(test::page_text(tmp / "kitti.html"));
  EXPECT_TRUE(kitti["steps"]["stamp"][3].is_null());

  const test::CliRun missing =
      test::run_cli(SEXTANT_CLI, "eval " + (tmp / "ref.tum").string() + " " + (tmp / "est.tum").string() +
                                     " --view " + (tmp / "nowhere" / "eval.html").string());
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_NE(
      missing.output.find("the folder of '" + (tmp / "nowhere" / "eval.html").string() + "' does not exist"),
      std::string::npos)
      << missing.output;
}

}  // namespace
}  // namespace sextant
