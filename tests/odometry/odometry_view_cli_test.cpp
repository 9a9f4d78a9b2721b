// `sextant odometry --view`: the page of a run on the built-in campus holds every pose where
// trajectory.tum has it, one step per line of steps.csv with its trust, recovery and reason, the ground
// truth and the map; a view named inside --out is one of the run's files; a view whose folder is
// missing stops the run before it starts.
#include <gtest/gtest.h>

#include <string>

#include "odometry_cli_run.hpp"
#include "sextant/pipeline/steps_table.hpp"
#include "sextant_test/run_view_page.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using test::run_cli;
using test::TempDir;

TEST(OdometryViewCli, PageHoldsTheRunAsItsFilesSayIt) {
  TempDir tmp;
  const test::CliRun r = run_cli("odometry campus --scans 8 --no-progress --out " + (tmp / "o").string() +
                                 " --view " + (tmp / "run.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("view:     " + (tmp / "run.html").string()), std::string::npos) << r.output;
  const nlohmann::json data = test::page_data(test::page_text(tmp / "run.html"));
  ASSERT_TRUE(data.is_object());
  // Every pose, where trajectory.tum has it.
  const Trajectory tum = read_tum_trajectory(tmp / "o" / "trajectory.tum");
  const std::vector<Eigen::Vector3f> poses = test::page_points(data["estimate"]["points"]);
  ASSERT_EQ(poses.size(), 8u);
  ASSERT_EQ(tum.size(), 8u);
  const Eigen::Vector3d origin(data["origin"][0], data["origin"][1], data["origin"][2]);
  for (std::size_t i = 0; i < 8; ++i)
    EXPECT_LT((poses[i].cast<double>() + origin - tum[i].pose.translation()).norm(), 1e-4) << i;
  // One step per line of steps.csv, with its trust, recovery and reason.
  const auto rows = test::read_steps_csv(tmp / "o" / "steps.csv");
  const nlohmann::json& steps = data["steps"];
  ASSERT_EQ(steps["count"], rows.size());
  ASSERT_EQ(rows.size(), 7u);
  const auto text = [&](const char* field, std::size_t i) {
    return steps["texts"][steps[field][i].get<int>()].get<std::string>();
  };
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(steps["from"][i], std::stoul(rows[i].at("from_scan")));
    EXPECT_EQ(steps["to"][i], std::stoul(rows[i].at("to_scan")));
    EXPECT_EQ(text("trust", i), rows[i].at("trust")) << i;
    EXPECT_EQ(text("recovery", i), rows[i].at("recovery")) << i;
    EXPECT_EQ(csv_free_text(text("reason", i)), rows[i].at("trust_reason")) << i;
    EXPECT_NEAR(steps["error_m"][i].get<double>(), std::stod(rows[i].at("error_m")), 1e-5) << i;
  }
  // The campus has a ground truth, and the map is its scans placed by the trajectory.
  EXPECT_TRUE(data["reference"].is_object());
  EXPECT_GT(data["map"]["count"].get<int>(), 1000);
  EXPECT_NE(test::read_text(tmp / "o" / "provenance.json").find("\"view\": \"" + (tmp / "run.html").string()),
            std::string::npos);
}

TEST(OdometryViewCli, ViewInsideTheOutputFolderIsOneOfTheRunsFiles) {
  TempDir tmp;
  const test::CliRun r = run_cli("odometry campus --scans 4 --no-progress --out " + (tmp / "o").string() +
                                 " --view " + (tmp / "o" / "run.html").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(tmp / "o" / "run.html"));
  EXPECT_TRUE(fs::is_regular_file(tmp / "o" / "trajectory.tum"));
  // A rerun without --view removes it with the earlier run's other files.
  ASSERT_EQ(run_cli("odometry campus --scans 4 --no-progress --out " + (tmp / "o").string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(tmp / "o" / "run.html"));
}

TEST(OdometryViewCli, MissingViewFolderStopsTheRunBeforeItStarts) {
  TempDir tmp;
  const test::CliRun r = run_cli("odometry campus --scans 4 --no-progress --out " + (tmp / "o").string() +
                                 " --view " + (tmp / "missing" / "run.html").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("--view"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("registered"), std::string::npos) << r.output;  // no run
  EXPECT_FALSE(fs::exists(tmp / "o"));
  const test::CliRun folder = run_cli("odometry campus --scans 4 --no-progress --out " +
                                      (tmp / "o").string() + " --view " + tmp.path().string());
  EXPECT_EQ(folder.exit_code, 1) << folder.output;
  EXPECT_NE(folder.output.find("is a folder"), std::string::npos) << folder.output;
}

}  // namespace
}  // namespace sextant
