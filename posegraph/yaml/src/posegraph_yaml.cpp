// The pose-graph and loop-closure settings from YAML (Sextant::posegraph_yaml).
#include "sextant/posegraph/yaml.hpp"

#include "sextant/core/settings_reader.hpp"

namespace sextant {

PoseGraphSettings read_pose_graph_settings(const YAML::Node& node, const std::string& file) {
  PoseGraphSettings s;
  SettingsReader in(node, file);
  std::string loss = to_string(s.loss);
  if (in.read("loss", loss)) {
    if (!from_string(loss, &s.loss))
      in.fail("loss",
              "key 'loss': unknown robust loss '" + loss + "' (known: " + names_list(kRobustLossNames) + ")");
  }
  in.read("loss_scale", s.loss_scale);
  in.read("robust_odometry", s.robust_odometry);
  in.read("max_iterations", s.max_iterations);
  in.read("function_tolerance", s.function_tolerance);
  in.read("threads", s.threads);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

LoopClosureSettings read_loop_closure_settings(const YAML::Node& node, const std::string& file) {
  LoopClosureSettings s;
  SettingsReader in(node, file);
  in.read("radius", s.radius);
  in.read("min_index_gap", s.min_index_gap);
  in.read("min_path_gap", s.min_path_gap);
  in.read("stride", s.stride);
  in.read("max_mean_score", s.max_mean_score);
  in.read("min_matched_fraction", s.min_matched_fraction);
  in.read("max_correction_m", s.max_correction_m);
  in.read("max_correction_deg", s.max_correction_deg);
  in.read("information_scale", s.information_scale);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

}  // namespace sextant
