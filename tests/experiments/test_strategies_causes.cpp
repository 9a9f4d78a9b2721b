// E6's measured causes (strategies_causes.hpp) state the numbers of the rows they are given.
#include <gtest/gtest.h>

#include "registration/layouts/strategies_causes.hpp"
#include "registration/row_keys.hpp"

namespace sextant {
namespace {

RegistrationError error_in_tz(double cm) {
  RegistrationError e;
  e.parameters = {0, 0, cm, 0, 0, 0};
  return e;
}

std::vector<RegistrationError> errors_in_tz(std::initializer_list<double> cm) {
  std::vector<RegistrationError> v;
  for (double c : cm) v.push_back(error_in_tz(c));
  return v;
}

TEST(StrategiesCauses, TheSampleSizeCauseComparesKeptSharesAndTimePerKeptPoint) {
  std::vector<RunRow> fbs_rows(3), gbs_rows(3);
  for (int i = 0; i < 3; ++i) {
    fbs_rows[i].values = {{keys::kKeptFraction, 0.8}, {keys::kSecondsAlign, 0.4}};   // 0.5 s per scan kept
    gbs_rows[i].values = {{keys::kKeptFraction, 0.2}, {keys::kSecondsAlign, 0.05}};  // 0.25 s
  }
  MethodRows fbs, gbs;
  for (int i = 0; i < 3; ++i) {
    fbs.rows.push_back(&fbs_rows[i]);
    gbs.rows.push_back(&gbs_rows[i]);
  }
  const std::string cause = sample_size_cause(&fbs, &gbs);
  EXPECT_NE(cause.find("keeps 80.0 % of the scan"), std::string::npos) << cause;
  EXPECT_NE(cause.find("GBS 20.0 %"), std::string::npos) << cause;
  EXPECT_NE(cause.find("costs 2.00× GBS's"), std::string::npos) << cause;
  EXPECT_EQ(sample_size_cause(&fbs, nullptr), "");
}

TEST(StrategiesCauses, TheBiasCauseNamesTheParameterAndEveryMethodsMedian) {
  const std::vector<std::string> names{"regular", "fbs"};
  const std::vector<std::vector<RegistrationError>> errors{errors_in_tz({-1, -2, -3}),
                                                           errors_in_tz({4, 5, 9})};
  const std::string cause = sample_bias_cause(names, errors, 1);
  EXPECT_EQ(cause, "data: fbs's errors are biased in tz: median 5.0 cm (regular -2.0 cm)");
}

TEST(StrategiesCauses, TheHeavyTailCauseGivesEveryMethodsJarqueBera) {
  // Method 1's tz has one far outlier among near-equal values: a large Jarque–Bera; method 0's is spread
  // evenly: a small one.
  std::vector<RegistrationError> even, tailed;
  for (int i = 0; i < 40; ++i) {
    even.push_back(error_in_tz(i % 2 ? 1.0 : -1.0));
    tailed.push_back(error_in_tz(i == 0 ? 100.0 : 0.01 * i));
  }
  const std::string cause = heavy_tail_cause({"even", "tailed"}, {even, tailed}, 1);
  EXPECT_NE(cause.find("Jarque–Bera on tz: even "), std::string::npos) << cause;
  EXPECT_NE(cause.find(", tailed "), std::string::npos) << cause;
}

}  // namespace
}  // namespace sextant
