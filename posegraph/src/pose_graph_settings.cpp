// YAML → PoseGraphSettings (pose_graph.hpp).
#include "sextant/core/settings_reader.hpp"
#include "sextant/posegraph/pose_graph.hpp"

namespace sextant {

RobustLoss robust_loss_from_string(const std::string& name, bool* ok) {
  *ok = true;
  if (name == "none") return RobustLoss::none;
  if (name == "huber") return RobustLoss::huber;
  if (name == "cauchy") return RobustLoss::cauchy;
  *ok = false;
  return RobustLoss::none;
}

std::string to_string(RobustLoss loss) {
  switch (loss) {
    case RobustLoss::huber: return "huber";
    case RobustLoss::cauchy: return "cauchy";
    case RobustLoss::none: break;
  }
  return "none";
}

PoseGraphSettings read_pose_graph_settings(const YAML::Node& node, const std::string& file) {
  PoseGraphSettings s;
  SettingsReader in(node, file);
  std::string loss = to_string(s.loss);
  if (in.read("loss", loss)) {
    bool ok = false;
    s.loss = robust_loss_from_string(loss, &ok);
    if (!ok) in.fail("loss", "key 'loss': unknown robust loss '" + loss + "' (known: none, huber, cauchy)");
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

}  // namespace sextant
