#pragma once
// The finished rows of an experiment grouped by method (over the whole sweep, or per sweep point
// as plane_slam groups them), so that two methods are compared on the same sweep points and
// repetitions.
#include <map>
#include <string>
#include <vector>

#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

struct MethodRows {
  std::string name;
  std::vector<const RunRow*> rows;                ///< ok rows in expansion order
  std::map<std::string, const RunRow*> by_point;  ///< point_key → row
  /// The sweep label the rows are at, when grouped per sweep point ("" otherwise).
  std::string point;
  /// Failed runs the family still counts (plane_slam: a filter that failed on most steps).
  std::vector<const RunRow*> ended;

  /// `value(key)` of each row, in expansion order (NaN when missing).
  std::vector<double> values(const std::string& key) const;
  const RunRow* first() const { return rows.empty() ? nullptr : rows.front(); }
};

/// "axis=label;…;rep=N": a sweep point and repetition, the same for every method.
std::string point_key(const std::map<std::string, std::string>& point, int repetition);

/// One entry per config method (in config order), holding its ok rows.
std::vector<MethodRows> group_by_method(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                                        const std::vector<const RunRow*>& rows);
/// The method named `name`, or null (also null when it has no rows).
const MethodRows* find_method(const std::vector<MethodRows>& methods, const std::string& name);

/// Rows of a and b at the sweep points and repetitions both have.
struct PairedRows {
  std::vector<const RunRow*> a, b;
};
/// In the order of their point_key.
PairedRows pair_up(const MethodRows& a, const MethodRows& b);
/// In a's expansion order.
PairedRows pair_up_in_order(const MethodRows& a, const MethodRows& b);

/// `value(key)` of each row (NaN when missing).
std::vector<double> row_values(const std::vector<const RunRow*>& rows, const std::string& key);

}  // namespace sextant
