// The per-step table (steps_table.hpp): one line per column, in steps.csv's order.
#include "sextant/pipeline/steps_table.hpp"

#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"

namespace sextant {
namespace {

using Step = const OdometryStep&;

/// Adds the columns over the steps, in the order they are added.
class Columns {
 public:
  explicit Columns(const std::vector<OdometryStep>& steps) : steps_(steps) { table_.rows = steps.size(); }

  void integer(const char* name, const std::function<long long(std::size_t, Step)>& value) {
    StepsColumn& c = add(name, StepsColumn::Kind::integer);
    for (std::size_t i = 0; i < steps_.size(); ++i) c.integers.push_back(value(i, steps_[i]));
  }
  void real(const char* name, const std::function<double(std::size_t, Step)>& value, bool missing = false) {
    StepsColumn& c = add(name, StepsColumn::Kind::real);
    c.missing = missing;
    for (std::size_t i = 0; i < steps_.size(); ++i) c.reals.push_back(value(i, steps_[i]));
  }
  void flag(const char* name, const std::function<bool(Step)>& value) {
    StepsColumn& c = add(name, StepsColumn::Kind::flag);
    for (const OdometryStep& step : steps_) c.flags.push_back(value(step));
  }
  void text(const char* name, const std::function<std::string(Step)>& value) {
    StepsColumn& c = add(name, StepsColumn::Kind::text);
    for (const OdometryStep& step : steps_) c.texts.push_back(value(step));
  }
  StepsTable table() && { return std::move(table_); }

 private:
  StepsColumn& add(const char* name, StepsColumn::Kind kind) {
    table_.columns.push_back(StepsColumn{name, kind, {}, {}, false, {}, {}});
    return table_.columns.back();
  }
  const std::vector<OdometryStep>& steps_;
  StepsTable table_;
};

/// The pose columns <prefix>x_m … <prefix>yaw_deg of `motion`.
void pose_columns(Columns& c, const std::string& prefix, Eigen::Isometry3d OdometryStep::*motion) {
  const auto pose = [motion](Step s) { return to_pose6(s.*motion); };
  c.real((prefix + "x_m").c_str(), [pose](std::size_t, Step s) { return pose(s).x; });
  c.real((prefix + "y_m").c_str(), [pose](std::size_t, Step s) { return pose(s).y; });
  c.real((prefix + "z_m").c_str(), [pose](std::size_t, Step s) { return pose(s).z; });
  c.real((prefix + "roll_deg").c_str(), [pose](std::size_t, Step s) { return pose(s).alpha * kDegPerRad; });
  c.real((prefix + "pitch_deg").c_str(), [pose](std::size_t, Step s) { return pose(s).beta * kDegPerRad; });
  c.real((prefix + "yaw_deg").c_str(), [pose](std::size_t, Step s) { return pose(s).gamma * kDegPerRad; });
}

}  // namespace

StepsTable steps_table(const OdometryResult& result, std::size_t first,
                       const std::optional<std::vector<Eigen::Isometry3d>>& truth) {
  // E = (truth_i⁻¹ truth_{i+1})⁻¹ · motion_i; NaN without the truth.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto error = [&](const char* name, Eigen::Isometry3d OdometryStep::*motion, bool degrees,
                         Columns& c) {
    c.real(
        name,
        [&truth, motion, degrees, nan](std::size_t i, Step s) {
          if (!truth) return nan;
          const Eigen::Isometry3d E = relative(relative((*truth)[i], (*truth)[i + 1]), s.*motion);
          return degrees ? rotation_angle(E) * kDegPerRad : translation_norm(E);
        },
        !truth);
  };
  Columns c(result.steps);
  c.integer("step", [](std::size_t i, Step) { return static_cast<long long>(i); });
  c.integer("from_scan", [first](std::size_t i, Step) { return static_cast<long long>(first + i); });
  c.integer("to_scan", [first](std::size_t i, Step) { return static_cast<long long>(first + i + 1); });
  pose_columns(c, "", &OdometryStep::relative);
  c.real("guess_x_m", [](std::size_t, Step s) { return to_pose6(s.guess).x; });
  c.real("guess_y_m", [](std::size_t, Step s) { return to_pose6(s.guess).y; });
  c.real("guess_yaw_deg", [](std::size_t, Step s) { return to_pose6(s.guess).gamma * kDegPerRad; });
  c.flag("converged", [](Step s) { return s.converged; });
  c.integer("iterations", [](std::size_t, Step s) { return static_cast<long long>(s.iterations); });
  c.real("score", [](std::size_t, Step s) { return s.score; });
  c.integer("matched_points", [](std::size_t, Step s) { return static_cast<long long>(s.matched_points); });
  c.integer("reference_points",
            [](std::size_t, Step s) { return static_cast<long long>(s.reference_points); });
  // What reading the step's input scan (to_scan) dropped; the first scan's count is in the summary.
  const auto dropped = [&result](std::size_t i, std::size_t ScanLoadReport::*count) {
    return i + 1 < result.loads.size() ? static_cast<long long>(result.loads[i + 1].*count) : 0LL;
  };
  c.integer("dropped_non_finite",
            [&](std::size_t i, Step) { return dropped(i, &ScanLoadReport::non_finite_dropped); });
  c.integer("dropped_no_return",
            [&](std::size_t i, Step) { return dropped(i, &ScanLoadReport::no_return_dropped); });
  c.real("seconds", [](std::size_t, Step s) { return s.seconds; });
  error("error_m", &OdometryStep::relative, false, c);
  error("error_deg", &OdometryStep::relative, true, c);
  c.text("status", [](Step s) { return s.status; });
  c.text("trust", [](Step s) { return to_string(s.quality.trust); });
  c.text("first_trust", [](Step s) { return to_string(s.first_trust); });
  c.text("recovery", [](Step s) { return s.recovery; });
  c.real("overlap", [](std::size_t, Step s) { return s.quality.overlap; });
  c.real("constraint_ratio", [](std::size_t, Step s) { return s.quality.constraint_ratio; });
  c.real("fit_ratio", [](std::size_t, Step s) { return s.quality.fit_ratio; });
  c.text("trust_reason", [](Step s) { return s.quality.reason; });
  c.text("fallback", [](Step s) { return s.fallback; });
  // The first registration's own pose and error, before any recovery replaced it.
  pose_columns(c, "first_", &OdometryStep::first_relative);
  error("first_error_m", &OdometryStep::first_relative, false, c);
  error("first_error_deg", &OdometryStep::first_relative, true, c);
  return std::move(c).table();
}

std::string csv_free_text(std::string text) {
  for (char& ch : text)
    if (ch == ',' || ch == '"') ch = ';';
  return text;
}

std::string steps_csv(const StepsTable& table) {
  std::ostringstream out;
  for (std::size_t k = 0; k < table.columns.size(); ++k) out << (k ? "," : "") << table.columns[k].name;
  out << "\n" << std::setprecision(9);
  for (std::size_t row = 0; row < table.rows; ++row) {
    for (std::size_t k = 0; k < table.columns.size(); ++k) {
      const StepsColumn& c = table.columns[k];
      if (k) out << ",";
      switch (c.kind) {
        case StepsColumn::Kind::integer: out << c.integers[row]; break;
        case StepsColumn::Kind::real:
          if (!c.missing) out << c.reals[row];
          break;
        case StepsColumn::Kind::flag: out << (c.flags[row] ? 1 : 0); break;
        case StepsColumn::Kind::text: out << csv_free_text(c.texts[row]); break;
      }
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace sextant
