#pragma once
// The adaptive starting layer the thesis proposes for ML-NDT (§5.1.1.3, after table 5.8) and never
// built: start at the last layer; a registration "fails" when its estimate differs from the
// odometry by more than 1 m or 15°; once the running failure rate passes 5 % start at layer 3,
// past 20 % at layer 2. The rule is sequential (its state is carried from pair to pair), so the
// registration kind runs it as one run over the whole sequence (registration/kind.cpp).
//
//   methods:
//     - {name: mlndt_adaptive, matcher: mlndt, settings: {...}, sampler: gbs,
//        adaptive_start: {max_translation: 1.0, max_rotation_deg: 15, middle_rate: 0.05, first_rate: 0.20,
//                         middle_layer: 3, first_layer: 2}}     # the thesis' values are the defaults
#include <cstddef>
#include <string>

#include <yaml-cpp/yaml.h>
#include <Eigen/Geometry>

namespace sextant {

struct AdaptiveStartSettings {
  double max_translation = 1.0;    ///< [m] estimate vs odometry beyond this = failure
  double max_rotation_deg = 15.0;  ///< [deg] likewise
  double middle_rate = 0.05;       ///< running failure rate above which to start at middle_layer
  double first_rate = 0.20;        ///< ... above which to start at first_layer
  int middle_layer = 3;
  int first_layer = 2;
};

/// Reads `adaptive_start` (a map; empty = the thesis' values). InputError with file, line, key.
AdaptiveStartSettings read_adaptive_start(const YAML::Node& node, const std::string& file);

/// The starting layer for the next registration after `failures` of `registrations` so far
/// (0 registrations: the last layer). Rates are compared strictly ("passes 5 %").
int adaptive_start_layer(const AdaptiveStartSettings& s, int last_layer, std::size_t failures,
                         std::size_t registrations);

/// The rule's failure test: ‖t‖ > max_translation or angle > max_rotation_deg of odometry⁻¹·estimate.
bool adaptive_failure(const AdaptiveStartSettings& s, const Eigen::Isometry3d& estimate,
                      const Eigen::Isometry3d& odometry);

}  // namespace sextant
