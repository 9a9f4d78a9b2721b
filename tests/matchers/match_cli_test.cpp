// `sextant match` end to end: runs the CLI binary on the shared real pairs and checks the JSON; with
// no options it must register every shared pair from the guess a user has (docs/matcher_defaults.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/uos.hpp"
#include "sextant_test/cli_run.hpp"

namespace {

using sextant::test::CliRun;
CliRun run_cli(const std::string& arguments) {
  return sextant::test::run_cli(SEXTANT_CLI, arguments);
}

/// The number after "key": in a one-line JSON object; NaN when absent or null.
double json_number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return NAN;
  const char* start = json.c_str() + at + key.size() + 4;
  char* end = nullptr;
  const double v = std::strtod(start, &end);
  return end == start ? NAN : v;
}

const std::string kPair = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/fast_gicp_251370668.pcd " +
                          SEXTANT_DATA_DIR + "/velodyne_pair/fast_gicp_251371071.pcd --gt " +
                          SEXTANT_DATA_DIR + "/velodyne_pair/fast_gicp_relative.txt";
// About 5 cm and 0.3° away from the reference transform (0.486, 0.106, −0.013; ≈ −0.62° yaw).
const std::string kNearGuess = " --init 0.5,0.1,0,0.3,0,-0.6";

class MatchCli : public ::testing::TestWithParam<const char*> {};

TEST_P(MatchCli, JsonOnVelodynePairFromNearGuess) {
  const CliRun r = run_cli("match " + kPair + kNearGuess + " --sampling gbs --json --method " + GetParam());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string json = r.output.substr(r.output.rfind("{\"method\""));
  EXPECT_NE(json.find("\"converged\": true"), std::string::npos) << json;
  EXPECT_NE(json.find("\"transform\": [["), std::string::npos) << json;
  EXPECT_LT(json_number(json, "error_cm"), 5.0) << json;
  EXPECT_LT(json_number(json, "error_deg"), 0.3) << json;
  EXPECT_GT(json_number(json, "iterations"), 0.0) << json;
  EXPECT_GE(json_number(json, "seconds"), 0.0) << json;
}

INSTANTIATE_TEST_SUITE_P(Methods, MatchCli, ::testing::Values("icp_p2l", "pcl_ndt"),
                         [](const auto& info) { return std::string(info.param); });

/// Element (row, col) of the JSON "transform" (4×4, row-major); NaN when absent.
double transform_element(const std::string& json, int row, int col) {
  auto at = json.find("\"transform\": [[");
  if (at == std::string::npos) return NAN;
  const char* p = json.c_str() + at + 15;
  for (int k = 0; k < 4 * row + col; ++k) {
    while (*p && *p != ',') ++p;
    if (*p) ++p;
    while (*p == ' ' || *p == '[' || *p == ']') ++p;
  }
  return std::strtod(p, nullptr);
}

std::string last_json(const CliRun& r) {
  const auto at = r.output.rfind("{\"method\"");
  return at == std::string::npos ? std::string() : r.output.substr(at);
}

const std::string kData = std::string(SEXTANT_DATA_DIR) + "/";

// The defaults on every shared pair, from the identity: the Velodyne pair (ground truth), the uos
// scans 000/001 (3DTK's .frames), the KITTI pair (cross-method consensus ≈ 0.68 m forward, its derived
// ground truth is withdrawn) and PCL's room scans from the tutorial's guess (no ground truth: PCL's NDT
// and our ICP agree on x ≈ 1.97 m, y ≈ 0.06 m).
// Without --preset: `default` (as odometry and the library), the wide basin from the identity; every
// result within 5 cm and trusted (exit 0), but the uos pair's: its fit is 1.42 × the prediction and
// 49–50 % of its input matches, and it is flagged (exit 3: suspect or low_overlap, whichever check
// it meets first) although it is right (a known false alarm, docs/matcher_defaults.md).
TEST(MatchCliDefaults, NoOptionsRegistersEverySharedPair) {
  const CliRun velodyne = run_cli("match " + kPair + " --json");
  ASSERT_EQ(velodyne.exit_code, 0) << velodyne.output;
  EXPECT_LT(json_number(last_json(velodyne), "error_cm"), 5.0) << velodyne.output;
  EXPECT_LT(json_number(last_json(velodyne), "error_deg"), 0.5) << velodyne.output;
  EXPECT_NE(last_json(velodyne).find("\"trust\": \"ok\""), std::string::npos) << velodyne.output;
  const CliRun velodyne_text = run_cli("match " + kPair);
  EXPECT_NE(velodyne_text.output.find("mlndt (preset default)"), std::string::npos) << velodyne_text.output;
  EXPECT_NE(velodyne_text.output.find("search:      wide basin (no --init"), std::string::npos)
      << velodyne_text.output;

  const std::string gt = ::testing::TempDir() + "uos_000_001_gt.txt";
  {
    const auto frame = [](const char* f) { return sextant::read_uos_frames(kData + "uos_3dtk/" + f).back(); };
    const Eigen::Matrix4d T = (frame("scan000.frames").inverse() * frame("scan001.frames")).matrix();
    std::ofstream out(gt);
    out.precision(12);
    out << T << "\n";
  }
  const CliRun uos = run_cli("match " + kData + "uos_3dtk/scan000.3d " + kData + "uos_3dtk/scan001.3d --gt " +
                             gt + " --json");
  ASSERT_EQ(uos.exit_code, 3) << uos.output;
  EXPECT_TRUE(last_json(uos).find("\"trust\": \"suspect\"") != std::string::npos ||
              last_json(uos).find("\"trust\": \"low_overlap\"") != std::string::npos)
      << uos.output;
  EXPECT_LT(json_number(last_json(uos), "error_cm"), 5.0) << uos.output;
  EXPECT_LT(json_number(last_json(uos), "error_deg"), 0.5) << uos.output;

  const CliRun kitti = run_cli("match " + kData + "kitti00_pair/000000.xyz32.bin " + kData +
                               "kitti00_pair/000001.xyz32.bin --json");
  ASSERT_EQ(kitti.exit_code, 0) << kitti.output;
  EXPECT_NEAR(transform_element(last_json(kitti), 0, 3), 0.68, 0.05) << kitti.output;

  const CliRun room = run_cli("match " + kData + "pcl_room_scan/room_scan1.pcd " + kData +
                              "pcl_room_scan/room_scan2.pcd --init 1.79387,0.720047,0,0,0,39.7121 --json");
  // The room scans are noisy: the fit check calls the result suspect (exit 3); the pose is PCL's.
  ASSERT_TRUE(room.exit_code == 0 || room.exit_code == 3) << room.output;
  EXPECT_NE(last_json(room).find("\"converged\": true"), std::string::npos) << room.output;
  EXPECT_NEAR(transform_element(last_json(room), 0, 3), 1.97, 0.1) << room.output;
  EXPECT_NEAR(transform_element(last_json(room), 1, 3), 0.06, 0.1) << room.output;
}

// The outdoor preset (6 layers over the bounding box) is close on the Velodyne pair but its fine cells
// match only 41 % of the sample, so it says low_overlap (exit 3); the thesis preset is the
// reproduction's setting. Either way the result is printed.
TEST(MatchCliDefaults, PresetsAreSelectable) {
  const CliRun outdoor = run_cli("match " + kPair + " --preset outdoor --json");
  ASSERT_TRUE(outdoor.exit_code == 0 || outdoor.exit_code == 3) << outdoor.output;
  EXPECT_LT(json_number(last_json(outdoor), "error_cm"), 5.0) << outdoor.output;
  const CliRun thesis = run_cli("match " + kPair + " --preset thesis");
  ASSERT_TRUE(thesis.exit_code == 0 || thesis.exit_code == 3) << thesis.output;
  EXPECT_NE(thesis.output.find("mlndt (preset thesis)"), std::string::npos) << thesis.output;
}

// --jobs 1 runs the registration on one thread: the same transform, to the last printed digit, as
// the default (every core), with the wide basin's parallel starts.
TEST(MatchCliDefaults, OneThreadGivesTheSameResult) {
  const CliRun all = run_cli("match " + kPair + " --json");
  const CliRun one = run_cli("match " + kPair + " --json -j 1");
  ASSERT_EQ(all.exit_code, 0) << all.output;
  ASSERT_EQ(one.exit_code, 0) << one.output;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 4; ++col)
      EXPECT_EQ(transform_element(last_json(all), row, col), transform_element(last_json(one), row, col))
          << row << "," << col;
  EXPECT_EQ(json_number(last_json(all), "iterations"), json_number(last_json(one), "iterations"));
  EXPECT_LT(json_number(last_json(all), "error_cm"), 5.0) << all.output;
  EXPECT_EQ(run_cli("match " + kPair + " -j -1").exit_code, 2);
}

TEST(MatchCliErrors, BadInputIsAnErrorWithExitCode1) {
  for (const std::string& arguments :
       {kPair + " --method no_such_matcher", kPair + " --init 1,2,3",
        kPair + " --method icp_p2p --preset thesis", kPair + " --method pcl_ndt --init=1e39,0,0,0,0,0",
        std::string("/no/such/file.pcd /no/such/other.pcd")}) {
    const CliRun r = run_cli("match " + arguments);
    EXPECT_EQ(r.exit_code, 1) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find("sextant: error: "), std::string::npos) << r.output;
  }
}

/// The 4×4 numbers `sextant -q match` prints, row-major; empty when the output is not 4 lines of 4.
std::vector<double> quiet_transform(const std::string& output) {
  std::vector<double> values;
  std::stringstream in(output);
  for (double v; in >> v;) values.push_back(v);
  return values.size() == 16 && in.eof() ? values : std::vector<double>{};
}

// Issue 26: --init takes what PCL and small_gicp users hold (a 4×4 or 3×4 matrix, as numbers or a
// file); the same guess in every form gives the same result.
TEST(MatchCliConventions, InitAsEulerNumbersMatrixOrFile) {
  const std::string pair = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/fast_gicp_251370668.pcd " +
                           SEXTANT_DATA_DIR + "/velodyne_pair/fast_gicp_251371071.pcd";
  const CliRun euler = run_cli("-q match " + pair + " --init 0.5,0.1,0,0,0,90");
  const std::vector<double> expected = quiet_transform(euler.output);
  ASSERT_EQ(expected.size(), 16u) << euler.output;
  const std::string rows = "0,-1,0,0.5, 1,0,0,0.1, 0,0,1,0";  // Rz(90°), the 3×4 form
  const std::string file = ::testing::TempDir() + "init_4x4.txt";
  std::ofstream(file) << "0 -1 0 0.5\n1 0 0 0.1\n0 0 1 0\n0 0 0 1\n";
  for (const std::string& init : {"'" + rows + "'", "'" + rows + ", 0,0,0,1'", file}) {
    const CliRun r = run_cli("match " + pair + " --init " + init + " --quiet");
    const std::vector<double> got = quiet_transform(r.output);
    ASSERT_EQ(got.size(), 16u) << init << "\n" << r.output;
    for (int k = 0; k < 16; ++k) EXPECT_NEAR(got[k], expected[k], 1e-6) << init << " element " << k;
  }
  const CliRun mirror = run_cli("match " + pair + " --init '1,0,0,0, 0,1,0,0, 0,0,-1,0'");
  EXPECT_EQ(mirror.exit_code, 1);
  EXPECT_NE(mirror.output.find("--init: not a rigid transform"), std::string::npos) << mirror.output;
  const CliRun five = run_cli("match " + pair + " --init 1,2,3,4,5");
  EXPECT_NE(five.output.find("found 5 numbers"), std::string::npos) << five.output;
}

/// The 36 numbers after "key": [[ (row-major).
Eigen::Matrix<double, 6, 6> matrix6(const std::string& json, const std::string& key) {
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Constant(NAN);
  const auto at = json.find("\"" + key + "\": [[");
  if (at == std::string::npos) return M;
  const char* p = json.c_str() + at + key.size() + 6;
  for (int k = 0; k < 36; ++k) {
    while (*p == ' ' || *p == ',' || *p == '[' || *p == ']') ++p;
    char* end = nullptr;
    M(k / 6, k % 6) = std::strtod(p, &end);
    p = end;
  }
  return M;
}

// Issue 26: --json carries H and its covariance (symmetric, = H⁻¹), the matched fraction and
// where --out wrote; -v prints the iterations.
TEST(MatchCliConventions, JsonHasHessianCovarianceAndMatchedFraction) {
  const std::string out = ::testing::TempDir() + "aligned.pcd";
  const CliRun r = run_cli("match " + kPair + kNearGuess + " --json --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string json = r.output.substr(r.output.rfind("{\"method\""));
  for (const char* key : {"\"hessian\": [[", "\"covariance\": [[", "\"parameters\": [\"x_m\"", "\"out\": \""})
    EXPECT_NE(json.find(key), std::string::npos) << key << "\n" << json;
  const Eigen::Matrix<double, 6, 6> H = matrix6(json, "hessian"), C = matrix6(json, "covariance");
  EXPECT_TRUE((C * H).isApprox(Eigen::Matrix<double, 6, 6>::Identity(), 1e-6)) << C * H;
  EXPECT_TRUE(C.isApprox(C.transpose(), 1e-9));
  EXPECT_NEAR(json_number(json, "matched_fraction"),
              json_number(json, "matched_points") / json_number(json, "input_points"), 1e-9);
  std::ifstream written(out);
  EXPECT_TRUE(written.good()) << out;
  // --view: one self-contained page (three.js inlined, no network) with both clouds.
  const std::string view = ::testing::TempDir() + "pair.html";
  const CliRun viewed = run_cli("match " + kPair + kNearGuess + " --view " + view);
  ASSERT_EQ(viewed.exit_code, 0) << viewed.output;
  EXPECT_NE(viewed.output.find("wrote:       " + view + " (3D view"), std::string::npos) << viewed.output;
  std::ifstream page_file(view);
  const std::string page((std::istreambuf_iterator<char>(page_file)), std::istreambuf_iterator<char>());
  EXPECT_GT(page.size(), 500000u) << "three.js and two clouds inlined";
  EXPECT_NE(page.find("fast_gicp_251370668.pcd ← fast_gicp_251371071.pcd (ok)"), std::string::npos);
  EXPECT_EQ(page.find("<script src=\"http"), std::string::npos);
  const CliRun verbose = run_cli("match " + kPair + kNearGuess + " -v");
  EXPECT_NE(verbose.output.find("iterations:  layer"), std::string::npos) << verbose.output;
}

// Clouds far from their coordinates' origin (register_pair.hpp): the pair moved 300 m is registered
// about the middle of the reference and says so; moved to UTM-like coordinates, the reader warns that
// float points lose what the file held below 0.5 m.
TEST(MatchCliConventions, CloudsFarFromTheirOriginAreRegisteredAboutTheReference) {
  const std::string dir = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/";
  const auto moved = [&](const Eigen::Vector3d& offset, const std::string& tag) {
    const Eigen::Isometry3d away(Eigen::Translation3d{offset});
    std::string files;
    for (const char* name : {"fast_gicp_251370668", "fast_gicp_251371071"}) {
      const std::string path = ::testing::TempDir() + name + tag + ".xyz";
      sextant::write_cloud(path, sextant::read_cloud(dir + name + ".pcd").transformed(away));
      files += " " + path;
    }
    return files;
  };
  const std::string near = moved({0, 300, 0}, "_300m");
  const CliRun text = run_cli("match" + near);
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("centre:      -2."), std::string::npos) << text.output;
  const CliRun json = run_cli("match" + near + " --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  EXPECT_NE(json.output.find("\"centre_m\": [-2."), std::string::npos) << json.output;
  const CliRun home = run_cli("match " + kPair + " --json");
  EXPECT_NE(home.output.find("\"centre_m\": [0.0, 0.0, 0.0]"), std::string::npos) << home.output;

  const CliRun utm = run_cli("match" + moved({512345.678, 5401234.567, 312.5}, "_utm") + " --json");
  EXPECT_NE(utm.output.find("where Sextant's float points are 500.000 mm apart"), std::string::npos)
      << utm.output;
}

// A trusted result more than 1 m or 5° from --gt is a wrong registration that passed the checks or a
// wrong ground truth: the output says so (the result itself, and the exit status, are the matcher's).
TEST(MatchCliGroundTruth, ATrustedResultFarFromTheGroundTruthIsNamed) {
  const std::string pair = std::string(SEXTANT_DATA_DIR) + "/velodyne_pair/fast_gicp_251370668.pcd " +
                           SEXTANT_DATA_DIR + "/velodyne_pair/fast_gicp_251371071.pcd";
  const std::string wrong = ::testing::TempDir() + "velodyne_gt_3m_off.txt";
  std::ofstream(wrong)
      << "0.999941 0.0108432 -0.000635437 3.485657\n-0.0108468 0.999924 -0.00587782 0.10642\n"
         "0.000571654 0.00588436 0.999983 -0.0131581\n0 0 0 1\n";
  const std::string check = "check:       trusted, yet more than 1 m or 5° from --gt";
  const CliRun right = run_cli("match " + kPair + kNearGuess);
  ASSERT_EQ(right.exit_code, 0) << right.output;
  EXPECT_EQ(right.output.find(check), std::string::npos) << right.output;
  const CliRun off = run_cli("match " + pair + kNearGuess + " --gt " + wrong);
  ASSERT_EQ(off.exit_code, 0) << off.output;
  EXPECT_NE(off.output.find(check), std::string::npos) << off.output;
  const CliRun json = run_cli("match " + pair + kNearGuess + " --gt " + wrong + " --json");
  EXPECT_NE(last_json(json).find("\"trusted_off_ground_truth\": true"), std::string::npos) << json.output;
  const CliRun no_truth = run_cli("match " + pair + kNearGuess + " --json");
  EXPECT_NE(last_json(no_truth).find("\"trusted_off_ground_truth\": null"), std::string::npos)
      << no_truth.output;
}

}  // namespace
