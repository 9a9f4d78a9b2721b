// The robust losses by name (pose_graph.hpp).
#include "sextant/posegraph/pose_graph.hpp"

namespace sextant {

bool from_string(const std::string& text, RobustLoss* out) {
  return from_name(kRobustLossNames, text, out);
}

std::string to_string(RobustLoss loss) {
  return name_of(kRobustLossNames, loss);
}

}  // namespace sextant
