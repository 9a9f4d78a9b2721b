// The ML-NDT presets (mlndt_presets.hpp).
#include "sextant/matchers/mlndt_presets.hpp"

#include <limits>

namespace sextant {
namespace {

MlndtSettings default_preset() {
  MlndtSettings s;
  s.threads = 0;  // every thread TBB allows (`--jobs`); the result is the same for any count
  return s;
}

/// Every field the library's defaults set differently from the thesis, set back.
MlndtSettings thesis_preset() {
  MlndtSettings s;
  s.optimizer.solver = SolverKind::kNewton;
  s.optimizer.step_control = StepControl::kNone;
  s.pyramid.division = 8;
  s.pyramid.layers = 4;
  s.start_layer = 2;
  s.optimizer.iterations_per_stage = 3;
  s.optimizer.max_iterations = 50;
  s.optimizer.epsilon = 1.0e-4;
  s.optimizer.function_tolerance = 0.0;
  s.unmatched_penalty = 50.0;
  s.max_distance = std::numeric_limits<double>::infinity();
  s.truncated_layers = 1;
  s.pyramid.bounds_quantile = 0.0;
  s.pyramid.cells.min_relative_spread = 0.0;
  s.refine_first = false;
  s.precision.min_cell = 0.0;
  return s;
}

/// Measured with the bounding box (before robust_bounds): its 6 layers over the robust box are too fine
/// for a GBS sample of a 64-beam scan.
MlndtSettings outdoor_preset() {
  MlndtSettings s = default_preset();
  s.pyramid.layers = 6;
  s.pyramid.bounds_quantile = 0.0;
  s.pyramid.cells.min_relative_spread = 0.0;
  return s;
}

struct Preset {
  const char* name;
  MlndtSettings (*make)();
};

constexpr Preset kPresets[] = {
    {"default", default_preset}, {"thesis", thesis_preset}, {"outdoor", outdoor_preset}};

}  // namespace

std::vector<std::string> mlndt_preset_names() {
  std::vector<std::string> names;
  for (const Preset& p : kPresets) names.emplace_back(p.name);
  return names;
}

std::optional<MlndtSettings> mlndt_preset(const std::string& name) {
  for (const Preset& p : kPresets)
    if (name == p.name) return p.make();
  return std::nullopt;
}

}  // namespace sextant
