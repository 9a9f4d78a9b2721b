// `sextant match` end to end: runs the CLI binary on the Velodyne pair and checks the JSON.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct CliRun {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr
};

CliRun run_cli(const std::string& arguments) {
  CliRun r;
  const std::string command = std::string(SEXTANT_CLI) + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) r.output += buffer.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
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

TEST(MatchCliErrors, BadInputIsAnErrorWithExitCode1) {
  for (const std::string& arguments :
       {kPair + " --method no_such_matcher", kPair + " --init 1,2,3", kPair + " --method icp_p2p --solver lm",
        std::string("/no/such/file.pcd /no/such/other.pcd")}) {
    const CliRun r = run_cli("match " + arguments);
    EXPECT_EQ(r.exit_code, 1) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find("sextant: error: "), std::string::npos) << r.output;
  }
}

}  // namespace
