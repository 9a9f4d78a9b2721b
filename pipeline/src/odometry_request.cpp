// An odometry run's arguments, checked once for both faces (odometry_request.hpp).
#include "sextant/pipeline/odometry_request.hpp"

#include <algorithm>

#include "sextant/core/error.hpp"
#include "sextant/matchers/matcher_traits.hpp"

namespace sextant {
namespace {

/// 'value' for Python, value for the command line.
std::string literal(Face face, const std::string& value) {
  return face == Face::python ? "'" + value + "'" : value;
}

}  // namespace

std::string argument(Face face, const std::string& name) {
  if (face == Face::python) return name;
  std::string flag = "--" + name;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

std::string given(Face face, const std::string& name, const std::string& value) {
  return face == Face::python ? name + "=" + literal(face, value) : argument(face, name) + " " + value;
}

OdometrySettings odometry_settings(const OdometryRequest& r, Face face) {
  OdometrySettings s;
  s.map = parse_enum(kOdometryMapNames, r.map, argument(face, "map"));
  if (!r.guess.empty()) s.guess = parse_enum(kOdometryGuessNames, r.guess, argument(face, "guess"));
  s.registration = r.registration;
  s.local_map_scans = r.local_map_scans;
  s.min_range = r.min_range;
  s.max_acceleration = r.max_acceleration;
  s.seed = r.seed;
  s.recover = r.recover;
  s.deskew = r.deskew;
  s.sensor = parse_enum(kSensorKindNames, r.sensor, argument(face, "sensor"));
  s.platform = parse_enum(kPlatformNames, r.platform, argument(face, "platform"));
  s.common_view = r.common_view.value_or(matcher_traits(r.method).common_view_by_default);
  if (const std::string why = s.problem(); !why.empty()) throw InputError("arguments", "", why);
  return s;
}

OdometryPlan plan_odometry(OdometrySettings settings, const OdometryRequest& r, const Dataset& dataset,
                           const std::string& dataset_name, Face face) {
  const std::size_t size = dataset.size();
  if (r.first >= size)
    throw InputError(argument(face, "first"), "",
                     std::to_string(r.first) + " is past the dataset's " + std::to_string(size) + " scans");
  OdometryPlan plan;
  plan.first = r.first;
  plan.scans = r.scans == 0 ? size - r.first : r.scans;
  if (plan.scans > size - r.first)
    throw InputError(argument(face, "scans"), "",
                     "scans " + std::to_string(r.first) + "–" + std::to_string(r.first + plan.scans - 1) +
                         " go past the dataset's " + std::to_string(size) + " scans");
  const DatasetMetadata& meta = dataset.metadata();
  const bool asks_odometry = !r.guess.empty() && settings.guess == OdometryGuess::odometry;
  if (asks_odometry && !meta.has_odometry)
    throw InputError(dataset_name, "",
                     "this " + meta.format + " dataset has no odometry, which " +
                         given(face, "guess", "odometry") + " needs; use " +
                         given(face, "guess", "constant_velocity") + " (or " + literal(face, "identity") +
                         ")");
  if (r.guess.empty())
    settings.guess = meta.has_odometry ? OdometryGuess::odometry : OdometryGuess::constant_velocity;
  plan.settings = std::move(settings);
  return plan;
}

}  // namespace sextant
