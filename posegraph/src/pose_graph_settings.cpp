// The robust losses by name (pose_graph.hpp).
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

}  // namespace sextant
