#pragma once
// The `sequence` kind's view of an experiment config: one run = one method over a
// sequence of consecutive scans (not independent pairs), repeated with fresh odometry noise.
//
//   methods:
//     - {name: fbmlndt, matcher: fbmlndt, settings: {...}, sampler: all}   # registration.hpp keys
//   repetitions: 5                # synthetic + odometry: simulated → a new odometry draw each
//   params:
//     first_scan: 0               # index of the sequence's first scan
//     scans: 100                  # scans in the sequence (scans − 1 registrations)
//     odometry: simulated         # simulated: redrawn per run from the campus' odometry model, or
//                                 #   a folder's `simulated_odometry:` model applied to its
//                                 #   reference; dataset: the dataset's own odometry
//     filter: none                # none: chain the matcher (dead reckoning, E7);
//                                 # kf: Table 3.3's linear KF, control = odometry increment
//     kf: {sigma_translation: 0.8, sigma_rotation_deg: 1, alarm_translation: 2,
//          alarm_rotation_deg: 10, measurement_noise_scale: 1, initial_sigma: 0.01}
//     report: dead_reckoning      # a layout of sequence/layouts/layouts.cpp: dead_reckoning | kalman
//     ellipses_at: [15, 30, 45, 60]   # kalman: 1-based scan numbers with covariance ellipses
//     ellipse_scale: 0            # kalman: ellipses drawn at this many σ (the thesis exaggerates);
//                                 #   0 = automatic (the largest ≈ 3 % of the map), stated in the legend
// Every registration starts from the odometry increment, so the registrations of one run do not
// depend on each other and run in parallel; chaining and filtering follow in scan order.
#include <cstddef>
#include <string>
#include <vector>

#include "kit/registration_method.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/filters/scan_matching_kf.hpp"

namespace sextant {

enum class SequenceOdometry { kSimulated, kDataset };
enum class SequenceFilter { kNone, kKf };
struct SequenceLayout;  // sequence/layouts/layouts.hpp

struct SequenceParams {
  std::size_t first_scan = 0;
  std::size_t scans = 100;  ///< ≥ 2
  SequenceOdometry odometry = SequenceOdometry::kSimulated;
  SequenceFilter filter = SequenceFilter::kNone;
  ScanMatchingKfSettings kf;               ///< Q and the alarm thresholds (radians inside)
  double measurement_noise_scale = 1;      ///< R = scale · H⁻¹
  double initial_sigma = 0.01;             ///< P0 = σ² I (the first pose is the true one) [m, rad]
  const SequenceLayout* report = nullptr;  ///< the `report:` line of the layout table (set on read)
  std::vector<int> ellipses_at{15, 30, 45, 60};
  double ellipse_scale = 0;  ///< σ multiple of the drawn ellipses; 0 = automatic
};

/// Reads and checks `params` (InputError with file, line, key); checks the odometry source
/// against the dataset source.
SequenceParams read_sequence_params(const ExperimentConfig& config);

}  // namespace sextant
