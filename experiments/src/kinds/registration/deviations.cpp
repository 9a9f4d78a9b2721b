#include "registration/deviations.hpp"

#include <cmath>

#include "registration/report.hpp"
#include "sextant/matchers/feature_based_sampler.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

void add(std::string& out, const std::string& item) {
  out += (out.empty() ? "" : "; ") + item;
}

/// The thesis' solver is Newton (eq. 3.16) without step control for NDT and ML-NDT (§5.1.1.2).
void optimizer_deviations(const OptimizerSettings& o, std::string& out) {
  switch (o.solver) {
    case SolverKind::kLevenbergMarquardt:
      add(out, "Levenberg–Marquardt on Σ‖Lᵀe‖² with the Gauss–Newton matrix (thesis: Newton, eq. 3.16)");
      break;
    case SolverKind::kCeres: add(out, "Ceres' LM on Σ‖Lᵀe‖² (thesis: Newton)"); break;
    case SolverKind::kNewton:
      if (o.step_control != StepControl::kNone)
        add(out, "Newton with step control " + to_string(o.step_control) +
                     " (thesis: the plain step of eq. 3.16)");
      break;
  }
}

void mlndt_deviations(const MlndtSettings& s, std::string& out) {
  optimizer_deviations(s.optimizer, out);
  if (s.unmatched_penalty > 0)
    add(out, "points outside every Gaussian charged " + format_number(s.unmatched_penalty, 0) +
                 " (thesis: not specified)");
  if (std::isfinite(s.max_distance) && s.truncated_layers > 0)
    add(out, "terms truncated at eᵀC⁻¹e = " + format_number(s.max_distance, 0) + " in the finest " +
                 std::to_string(s.truncated_layers) + " layer(s) (thesis: plain sum)");
  if (s.pyramid.layers != 4 || s.pyramid.division != 8)
    add(out, "pyramid q = " + std::to_string(s.pyramid.division) +
                 ", n = " + std::to_string(s.pyramid.layers) + " (thesis: q = 8, n = 4)");
  add(out, "start layer " + std::to_string(s.start_layer));
}

}  // namespace

std::string method_deviations(const RegistrationMethod& m) {
  std::string out;
  if (const MlndtSettings* s = m.matcher.get<MlndtSettings>()) {
    mlndt_deviations(*s, out);
  } else if (const FbmlndtSettings* f = m.matcher.get<FbmlndtSettings>()) {
    mlndt_deviations(f->mlndt, out);
  } else if (const NdtSettings* n = m.matcher.get<NdtSettings>()) {
    optimizer_deviations(n->optimizer, out);
    if (n->trilinear) add(out, "trilinear interpolation (Magnusson's variant the thesis cites)");
  } else {
    add(out, "a peer the thesis does not run");
  }
  if (m.adaptive) add(out, "adaptive starting layer (proposed in §5.1.1.3, never built by the thesis)");
  return m.name + ": " + (out.empty() ? "as in the thesis" : out);
}

std::string deviations_note(const ExperimentConfig& config) {
  std::string out = "Deviations from the thesis, per method:";
  for (const auto& m : config.methods)
    out += "\n- " + method_deviations(read_registration_method(m.node, config.file));
  return out;
}

}  // namespace sextant
