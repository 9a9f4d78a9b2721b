// A user's odometry run checked once for both faces (pipeline/odometry_request.hpp).
#include <gtest/gtest.h>

#include <string>

#include "sextant/core/error.hpp"
#include "sextant/pipeline/dataset_argument.hpp"
#include "sextant/pipeline/odometry_request.hpp"

namespace sextant {
namespace {

/// A dataset of `scans` scans without odometry or ground truth: only its size and format matter here.
class NoOdometry final : public Dataset {
 public:
  explicit NoOdometry(std::size_t scans) {
    meta_.name = "walk";
    meta_.format = "folder";
    meta_.scan_count = scans;
  }
  const DatasetMetadata& metadata() const override { return meta_; }
  PointCloud scan(std::size_t, ScanLoadReport*) const override { return {}; }
  std::optional<Eigen::Isometry3d> odometry(std::size_t) const override { return std::nullopt; }
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t) const override { return std::nullopt; }

 private:
  DatasetMetadata meta_;
};

/// The problem of the InputError `call` throws ("" when none).
template <class Call>
std::string problem_of(Call call) {
  try {
    call();
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  return "";
}

TEST(OdometryRequest, EachFaceSpellsItsArguments) {
  EXPECT_EQ(argument(Face::cli, "local_map_scans"), "--local-map-scans");
  EXPECT_EQ(argument(Face::python, "local_map_scans"), "local_map_scans");
  EXPECT_EQ(given(Face::cli, "guess", "odometry"), "--guess odometry");
  EXPECT_EQ(given(Face::python, "guess", "odometry"), "guess='odometry'");
}

TEST(OdometryRequest, BadNamesAreNamedInTheFacesSpelling) {
  OdometryRequest r;
  r.map = "atlas";
  EXPECT_NE(problem_of([&] { odometry_settings(r, Face::cli); }).find("--map"), std::string::npos);
  EXPECT_NE(problem_of([&] { odometry_settings(r, Face::python); }).find("map"), std::string::npos);
  r.map = "scan";
  r.platform = "bicycle";
  EXPECT_NE(problem_of([&] { odometry_settings(r, Face::cli); }).find("--platform"), std::string::npos);
}

TEST(OdometryRequest, TheCommonViewFollowsTheMethodUnlessGiven) {
  OdometryRequest r;
  EXPECT_TRUE(odometry_settings(r, Face::cli).common_view) << "mlndt's default";
  r.method = "icp_p2l";
  EXPECT_FALSE(odometry_settings(r, Face::cli).common_view);
  r.common_view = true;
  EXPECT_TRUE(odometry_settings(r, Face::cli).common_view);
}

TEST(OdometryRequest, ScansPastTheDatasetAreNamed) {
  const NoOdometry dataset(10);
  OdometryRequest r;
  r.first = 10;
  const std::string first =
      problem_of([&] { plan_odometry(odometry_settings(r, Face::cli), r, dataset, "walk", Face::cli); });
  EXPECT_NE(first.find("--first"), std::string::npos) << first;
  EXPECT_NE(first.find("10 is past the dataset's 10 scans"), std::string::npos) << first;
  r.first = 4;
  r.scans = 7;
  const std::string scans = problem_of(
      [&] { plan_odometry(odometry_settings(r, Face::python), r, dataset, "walk", Face::python); });
  EXPECT_NE(scans.find("scans"), std::string::npos) << scans;
  EXPECT_NE(scans.find("scans 4–10 go past the dataset's 10 scans"), std::string::npos) << scans;
  r.scans = 0;
  const OdometryPlan plan = plan_odometry(odometry_settings(r, Face::cli), r, dataset, "walk", Face::cli);
  EXPECT_EQ(plan.first, 4u);
  EXPECT_EQ(plan.scans, 6u) << "0: to the end";
}

TEST(OdometryRequest, TheGuessIsTheDatasetsOdometryWhenItHasOne) {
  const NoOdometry walk(5);
  OdometryRequest r;
  EXPECT_EQ(plan_odometry(odometry_settings(r, Face::cli), r, walk, "walk", Face::cli).settings.guess,
            OdometryGuess::constant_velocity);
  const auto campus = open_builtin_campus(1);
  EXPECT_EQ(plan_odometry(odometry_settings(r, Face::cli), r, *campus, "campus", Face::cli).settings.guess,
            OdometryGuess::odometry);
  r.guess = "odometry";
  const std::string cli =
      problem_of([&] { plan_odometry(odometry_settings(r, Face::cli), r, walk, "data/walk", Face::cli); });
  EXPECT_NE(cli.find("data/walk"), std::string::npos) << cli;
  EXPECT_NE(cli.find("which --guess odometry needs; use --guess constant_velocity (or identity)"),
            std::string::npos)
      << cli;
  const std::string python = problem_of(
      [&] { plan_odometry(odometry_settings(r, Face::python), r, walk, "data/walk", Face::python); });
  EXPECT_NE(python.find("which guess='odometry' needs; use guess='constant_velocity' (or 'identity')"),
            std::string::npos)
      << python;
}

}  // namespace
}  // namespace sextant
