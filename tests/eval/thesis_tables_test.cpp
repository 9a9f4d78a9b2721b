#include <gtest/gtest.h>

#include "sextant/eval/thesis_tables.hpp"

namespace sextant {
namespace {

TEST(ThesisTables, RegistrationErrorTableLikeTable51) {
  std::vector<RegistrationSample> samples(2);
  samples[0].estimate.translation() = Eigen::Vector3d(0.10, 0, 0);
  samples[1].estimate.translation() = Eigen::Vector3d(0.30, 0, 0);
  const RegistrationStats stats = registration_stats(samples);
  ParameterReference thesis;  // table 5.1 (odometry): ty, α, γ are n/a
  thesis.mean = {77.52, std::nullopt, 16.96, std::nullopt, 0.50, std::nullopt};
  thesis.std = {22.91, std::nullopt, 12.678, std::nullopt, 0.61541, std::nullopt};
  thesis.max = {178.61, std::nullopt, 53.938, std::nullopt, 2.5508, std::nullopt};
  const Table t = registration_error_table(stats, &thesis, "Table 5.1", "tab:5.1");
  ASSERT_EQ(t.columns.size(), 13u);
  ASSERT_EQ(t.rows.size(), 3u);
  const std::string csv = render_csv(t);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            ",tx (ours),tx (thesis),ty (ours),ty (thesis),tz (ours),tz (thesis),α (ours),α (thesis),"
            "β (ours),β (thesis),γ (ours),γ (thesis)");
  EXPECT_NE(csv.find("\nMean,20.00,77.52,0.00,,0.00,16.96,0.00,,0.00,0.50,0.00,\n"), std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\nMax,30.00,178.61,"), std::string::npos) << csv;
  const Table no_thesis = registration_error_table(stats, nullptr, "ours only");
  EXPECT_EQ(no_thesis.rows[0][2].kind, Cell::Kind::missing);
}

}  // namespace
}  // namespace sextant
