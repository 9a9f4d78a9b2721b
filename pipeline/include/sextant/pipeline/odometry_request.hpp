#pragma once
// A user's odometry run as both faces take it (`sextant odometry` and sextant.odometry()): the arguments
// checked once, in one place, with messages in the face's own spelling ("--first" or "first"), first the
// cheap ones, then against the dataset.
//
//   OdometryRequest request;  request.method = "mlndt";  request.registration = …;
//   OdometrySettings s = odometry_settings(request, Face::cli);    // names and settings
//   const OdometryPlan plan = plan_odometry(std::move(s), request, *dataset, "data/walk", Face::cli);
//   run_odometry(*dataset, plan.settings, plan.first, plan.scans);
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "sextant/core/dataset.hpp"
#include "sextant/odometry/odometry.hpp"

namespace sextant {

/// Which face an argument is named for in a message.
enum class Face { cli, python };

/// The argument `name` (snake_case) as `face` spells it: "--local-map-scans" or "local_map_scans".
std::string argument(Face face, const std::string& name);
/// The argument given a value: "--guess odometry" or "guess='odometry'".
std::string given(Face face, const std::string& name, const std::string& value);

struct OdometryRequest {
  std::string method = "mlndt";       ///< the matcher's name (its common view default)
  OdometryRegistration registration;  ///< its matcher and sampler, built by the face from its options
  std::string guess;                  ///< empty: odometry when the dataset has it, else constant_velocity
  std::string map = "local_map";
  std::string sensor = "auto", platform = "auto";
  std::optional<bool> common_view;  ///< none: the method's default (matcher_traits.hpp)
  std::size_t first = 0;
  std::size_t scans = 0;  ///< 0: to the end of the dataset
  std::size_t local_map_scans = 5;
  double min_range = 0.0;
  double max_acceleration = OdometrySettings{}.max_acceleration;
  std::uint64_t seed = 1;
  bool recover = true;
  bool deskew = true;  ///< deskew scans whose points carry time (OdometrySettings::deskew)
};

/// The settings of `request` but its guess (which needs the dataset); InputError naming the argument for
/// an unknown name or settings that do not go together.
OdometrySettings odometry_settings(const OdometryRequest& request, Face face);

/// A run checked against its dataset: the settings with their guess, and the scans.
struct OdometryPlan {
  OdometrySettings settings;
  std::size_t first = 0, scans = 0;
};

/// `settings` (odometry_settings) completed for `dataset`: InputError for scans past its end, naming the
/// argument, or for the odometry guess on a dataset without odometry, naming `dataset_name`.
OdometryPlan plan_odometry(OdometrySettings settings, const OdometryRequest& request, const Dataset& dataset,
                           const std::string& dataset_name, Face face);

}  // namespace sextant
