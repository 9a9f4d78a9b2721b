// sextant.odometry()'s steps table (steps_table.hpp): one line per column, in steps.csv's order.
#include "steps_table.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include <pybind11/numpy.h>

#include "sextant/core/units.hpp"

namespace sextant::python {
namespace py = pybind11;

namespace {

/// Builds the columns over the steps; the dict keeps the order they are added in.
class Columns {
 public:
  explicit Columns(const std::vector<OdometryStep>& steps) : steps_(steps) {}

  template <class T>
  void add(const char* name, const std::function<T(std::size_t, const OdometryStep&)>& value) {
    std::vector<T> values;
    for (std::size_t i = 0; i < steps_.size(); ++i) values.push_back(value(i, steps_[i]));
    table_[name] = py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
  }
  void text(const char* name, const std::function<std::string(const OdometryStep&)>& value) {
    py::list values;
    for (const OdometryStep& step : steps_) values.append(value(step));
    table_[name] = py::module_::import("numpy").attr("asarray")(values, py::arg("dtype") = "str");
  }
  void flag(const char* name, const std::function<bool(const OdometryStep&)>& value) {
    py::array_t<bool> values(static_cast<py::ssize_t>(steps_.size()));
    for (std::size_t i = 0; i < steps_.size(); ++i)
      values.mutable_at(static_cast<py::ssize_t>(i)) = value(steps_[i]);
    table_[name] = values;
  }
  py::dict table() const { return table_; }

 private:
  const std::vector<OdometryStep>& steps_;
  py::dict table_;
};

using Step = const OdometryStep&;

}  // namespace

py::dict steps_table(const OdometryResult& result, std::size_t first,
                     const std::optional<std::vector<Eigen::Isometry3d>>& truth) {
  // E = (truth_i⁻¹ truth_{i+1})⁻¹ · relative_i, as steps.csv's error columns.
  const auto error = [&](std::size_t i, const Eigen::Isometry3d& motion) {
    return relative(relative((*truth)[i], (*truth)[i + 1]), motion);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Columns c(result.steps);
  c.add<long long>("step", [](std::size_t i, Step) { return static_cast<long long>(i); });
  c.add<long long>("from_scan", [&](std::size_t i, Step) { return static_cast<long long>(first + i); });
  c.add<long long>("to_scan", [&](std::size_t i, Step) { return static_cast<long long>(first + i + 1); });
  c.add<double>("x_m", [](std::size_t, Step s) { return to_pose6(s.relative).x; });
  c.add<double>("y_m", [](std::size_t, Step s) { return to_pose6(s.relative).y; });
  c.add<double>("z_m", [](std::size_t, Step s) { return to_pose6(s.relative).z; });
  c.add<double>("roll_deg", [](std::size_t, Step s) { return to_pose6(s.relative).alpha * kDegPerRad; });
  c.add<double>("pitch_deg", [](std::size_t, Step s) { return to_pose6(s.relative).beta * kDegPerRad; });
  c.add<double>("yaw_deg", [](std::size_t, Step s) { return to_pose6(s.relative).gamma * kDegPerRad; });
  c.add<double>("guess_x_m", [](std::size_t, Step s) { return to_pose6(s.guess).x; });
  c.add<double>("guess_y_m", [](std::size_t, Step s) { return to_pose6(s.guess).y; });
  c.add<double>("guess_yaw_deg", [](std::size_t, Step s) { return to_pose6(s.guess).gamma * kDegPerRad; });
  c.flag("converged", [](Step s) { return s.converged; });
  c.add<long long>("iterations", [](std::size_t, Step s) { return static_cast<long long>(s.iterations); });
  c.add<double>("score", [](std::size_t, Step s) { return s.score; });
  c.add<long long>("matched_points",
                   [](std::size_t, Step s) { return static_cast<long long>(s.matched_points); });
  c.add<long long>("reference_points",
                   [](std::size_t, Step s) { return static_cast<long long>(s.reference_points); });
  c.add<double>("seconds", [](std::size_t, Step s) { return s.seconds; });
  c.add<double>("error_m",
                [&](std::size_t i, Step s) { return truth ? translation_norm(error(i, s.relative)) : nan; });
  c.add<double>("error_deg", [&](std::size_t i, Step s) {
    return truth ? rotation_angle(error(i, s.relative)) * kDegPerRad : nan;
  });
  c.text("status", [](Step s) { return s.status; });
  c.text("trust", [](Step s) { return to_string(s.quality.trust); });
  c.text("first_trust", [](Step s) { return to_string(s.first_trust); });
  c.text("recovery", [](Step s) { return s.recovery; });
  c.add<double>("overlap", [](std::size_t, Step s) { return s.quality.overlap; });
  c.add<double>("constraint_ratio", [](std::size_t, Step s) { return s.quality.constraint_ratio; });
  c.add<double>("fit_ratio", [](std::size_t, Step s) { return s.quality.fit_ratio; });
  c.text("trust_reason", [](Step s) { return s.quality.reason; });
  c.text("fallback", [](Step s) { return s.fallback; });
  // The first registration's own pose and error, before any recovery replaced it.
  c.add<double>("first_x_m", [](std::size_t, Step s) { return to_pose6(s.first_relative).x; });
  c.add<double>("first_y_m", [](std::size_t, Step s) { return to_pose6(s.first_relative).y; });
  c.add<double>("first_z_m", [](std::size_t, Step s) { return to_pose6(s.first_relative).z; });
  c.add<double>("first_roll_deg",
                [](std::size_t, Step s) { return to_pose6(s.first_relative).alpha * kDegPerRad; });
  c.add<double>("first_pitch_deg",
                [](std::size_t, Step s) { return to_pose6(s.first_relative).beta * kDegPerRad; });
  c.add<double>("first_yaw_deg",
                [](std::size_t, Step s) { return to_pose6(s.first_relative).gamma * kDegPerRad; });
  c.add<double>("first_error_m", [&](std::size_t i, Step s) {
    return truth ? translation_norm(error(i, s.first_relative)) : nan;
  });
  c.add<double>("first_error_deg", [&](std::size_t i, Step s) {
    return truth ? rotation_angle(error(i, s.first_relative)) * kDegPerRad : nan;
  });
  return c.table();
}

}  // namespace sextant::python
