// The per-step table both faces show (pipeline/steps_table.hpp): its columns, values and CSV.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/pipeline/steps_table.hpp"

namespace sextant {
namespace {

/// Two steps: 1 m along x, then 1 m along x and 90° of yaw; the second was recovered.
OdometryResult two_steps() {
  OdometryResult r;
  OdometryStep a;
  a.relative = to_isometry(Pose6{1.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  a.first_relative = a.relative;
  a.converged = true;
  a.iterations = 7;
  a.quality.trust = Trust::kOk;
  OdometryStep b = a;
  b.relative = to_isometry(Pose6{1.0, 0.0, 0.0, 0.0, 0.0, 90.0 * kRadPerDeg});
  b.first_relative = to_isometry(Pose6{3.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  b.converged = false;
  b.recovery = "wide_basin";
  b.quality.reason = "fit 1.4, above 1.3";
  r.steps = {a, b};
  return r;
}

const StepsColumn& column(const StepsTable& t, const std::string& name) {
  for (const StepsColumn& c : t.columns)
    if (c.name == name) return c;
  throw std::runtime_error("no column " + name);
}

TEST(StepsTable, HoldsSteps_csvsColumnsInItsOrder) {
  const StepsTable t = steps_table(two_steps(), 10, std::nullopt);
  ASSERT_EQ(t.columns.size(), 39u);
  EXPECT_EQ(t.rows, 2u);
  EXPECT_EQ(t.columns.front().name, "step");
  EXPECT_EQ(t.columns[3].name, "x_m");
  EXPECT_EQ(t.columns.back().name, "first_error_deg");
  EXPECT_EQ(column(t, "from_scan").integers, (std::vector<long long>{10, 11}));
  EXPECT_EQ(column(t, "to_scan").integers, (std::vector<long long>{11, 12}));
  EXPECT_NEAR(column(t, "yaw_deg").reals[1], 90.0, 1e-9);
  EXPECT_EQ(column(t, "converged").flags, (std::vector<bool>{true, false}));
  EXPECT_EQ(column(t, "recovery").texts[1], "wide_basin");
  EXPECT_TRUE(std::isnan(column(t, "error_m").reals[0])) << "no truth, no error";
  EXPECT_TRUE(column(t, "error_m").missing);
  EXPECT_FALSE(column(t, "x_m").missing);
}

TEST(StepsTable, EachStepCountsWhatReadingItsInputScanDropped) {
  OdometryResult r = two_steps();
  r.loads.resize(3);
  r.loads[0].non_finite_dropped = 9;  // the first scan is no step's input: the summary counts it
  r.loads[1].non_finite_dropped = 4;
  r.loads[2].no_return_dropped = 2;
  const StepsTable t = steps_table(r, 0, std::nullopt);
  EXPECT_EQ(column(t, "dropped_non_finite").integers, (std::vector<long long>{4, 0}));
  EXPECT_EQ(column(t, "dropped_no_return").integers, (std::vector<long long>{0, 2}));
  EXPECT_EQ(r.dropped_total().dropped(), 15u);
}

TEST(StepsTable, ErrorsAreAgainstTheTruthsMotions) {
  // The truth moves 1 m along x per scan, without turning.
  std::vector<Eigen::Isometry3d> truth;
  for (int i = 0; i < 3; ++i) truth.push_back(to_isometry(Pose6{double(i), 0.0, 0.0, 0.0, 0.0, 0.0}));
  const StepsTable t = steps_table(two_steps(), 0, truth);
  EXPECT_NEAR(column(t, "error_m").reals[0], 0.0, 1e-12);
  EXPECT_NEAR(column(t, "error_deg").reals[1], 90.0, 1e-9);
  EXPECT_NEAR(column(t, "first_error_m").reals[1], 2.0, 1e-12) << "the first registration's own error";
}

TEST(StepsTable, AMeasuredNanIsNotAMissingValue) {
  OdometryResult r = two_steps();
  r.steps[0].quality.constraint_ratio = std::numeric_limits<double>::quiet_NaN();  // a failed registration's
  const std::string csv = steps_csv(steps_table(r, 0, std::nullopt));
  EXPECT_NE(csv.find(",nan,"), std::string::npos) << csv;
}

TEST(StepsTable, AsCsvAnEmptyFieldForNoValueAndNoCommaInsideAField) {
  const std::string csv = steps_csv(steps_table(two_steps(), 0, std::nullopt));
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header.substr(0, 28), "step,from_scan,to_scan,x_m,y");
  std::size_t lines = 0;
  for (char c : csv) lines += c == '\n';
  EXPECT_EQ(lines, 3u);
  EXPECT_NE(csv.find("fit 1.4; above 1.3"), std::string::npos) << csv;
  // The second row, field by field: 1 m and 90° of yaw, not converged, its errors empty.
  const std::string row = csv.substr(csv.find("\n1,") + 1, std::string::npos);
  std::vector<std::string> fields(1);
  for (char c : row.substr(0, row.find('\n'))) {
    if (c == ',')
      fields.emplace_back();
    else
      fields.back().push_back(c);
  }
  ASSERT_EQ(fields.size(), 39u);
  EXPECT_EQ(fields[0], "1");
  EXPECT_EQ(fields[3], "1");
  EXPECT_NEAR(std::stod(fields[8]), 90.0, 1e-6);
  EXPECT_EQ(fields[12], "0");
  EXPECT_EQ(fields[13], "7");
  EXPECT_EQ(fields[17], "0");  // dropped_non_finite: the result records no loads
  EXPECT_EQ(fields[20], "");
  EXPECT_EQ(fields[21], "");
  EXPECT_EQ(fields[25], "wide_basin");
}

}  // namespace
}  // namespace sextant
