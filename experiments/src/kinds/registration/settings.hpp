#pragma once
// The `registration` kind's view of an experiment config:
//
//   methods:
//     - {name: mlndt, matcher: mlndt, settings: {solver: lm}, sampler: gbs, sampler_settings: {...}}
//   sweep:
//     pair: {from: 0, to: 99}     # consecutive: reference scan i, input scan i + 1
//     tx: [0, 1, 2]               # displaced: offset along x [m]
//     yaw: [0, 5, 10]             # displaced: offset about z [deg]
//     f: [0.9, 0.6, 0.3, 0]       # guess: scaled — Z_init = f · Z_gt in parameter space
//     start_layer: [2, 3, 4]      # overrides the method's settings.start_layer
//   params:
//     pairs: consecutive          # or displaced (one pair: scan → second, or the scenes of `displaced`)
//     guess: odometry             # odometry | identity | scaled (displaced: always identity)
//     scan: 0                     # displaced without `displaced:` scenes: reference scan index
//     second: 1                   # … and input scan index (default scan + 1)
//     success: translation_50cm   # eval's thesis_success_criterion name
//     axes: uos                   # uos (the thesis' tables) | internal
//     report: accuracy            # a layout of the table in registration/layouts/layouts.cpp:
//                                 # accuracy | basin | init_layer | sampling | strategies | zero_guess
//     baseline: ndt               # report: the method compared against ...
//     proposed: mlndt             # ... this one in the claims
//     displaced: {...}            # displaced: several scenes, offsets in NDT cells (registration/scenes.hpp)
//     thesis_baseline: ndt_plain  # optional: the thesis-faithful variants, compared the same way
//     thesis_proposed: mlndt_newton
//   A method with `adaptive_start: {...}` (kit/adaptive_start.hpp) runs the thesis' adaptive
//   starting layer over the whole pair sequence in one run; its plan holds only the runs at the
//   first pair and first start_layer (RegistrationKind::planned_runs).
#include <cstddef>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "kit/registration_method.hpp"
#include "sextant/eval/registration_metrics.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/run_plan.hpp"

namespace sextant {

enum class PairSource { kConsecutive, kDisplaced };
enum class GuessSource { kOdometry, kIdentity, kScaled };
struct RegistrationLayout;  // registration/layouts/layouts.hpp

struct RegistrationParams {
  PairSource pairs = PairSource::kConsecutive;
  GuessSource guess = GuessSource::kOdometry;
  std::size_t scan = 0;    ///< displaced: reference scan index
  std::size_t second = 1;  ///< displaced: input scan index
  std::string success = "translation_50cm";
  AxisConvention axes = AxisConvention::uos;
  const RegistrationLayout* report = nullptr;  ///< the `report:` line of the layout table (set on read)
  std::string baseline;                        ///< method name (may be empty)
  std::string proposed;                        ///< method name (may be empty)
  std::string thesis_baseline;                 ///< thesis-faithful variant of the baseline (may be empty)
  std::string thesis_proposed;  ///< thesis-faithful variant of the proposed method (may be empty)
  YAML::Node displaced;         ///< displaced: scenes and offset unit (registration/scenes.hpp); may be null

  bool valid(std::string* why) const;
};

/// The sweep axes the kind understands.
inline const std::vector<std::string>& registration_axes() {
  static const std::vector<std::string> axes{"pair",        "tx",    "yaw",    "f",
                                             "start_layer", "scene", "offset", "direction"};
  return axes;
}

/// Reads and checks `params` (InputError with file, line, key).
RegistrationParams read_registration_params(const ExperimentConfig& config);
/// Checks the sweep axes against the pair source and guess (InputError).
void check_registration_sweep(const ExperimentConfig& config, const RegistrationParams& params,
                              const std::vector<RegistrationMethod>& methods);

/// The number of sweep axis `axis` at a run's point, or `fallback` when the point has no such axis.
double point_value(const RunSpec& run, const std::string& axis, double fallback);

/// The scan indices the runs read (reference and input of every pair).
std::vector<std::size_t> needed_scans(const ExperimentConfig& config, const RegistrationParams& params);

}  // namespace sextant
