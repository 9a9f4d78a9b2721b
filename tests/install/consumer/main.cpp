// Composes two poses with the installed Sextant::core and checks the result; exit 0 on success.
#include <cmath>
#include <iostream>

#include "sextant/core/pose.hpp"

int main() {
  const Eigen::Isometry3d a = sextant::to_isometry({1.0, 0.0, 0.0, 0.0, 0.0, M_PI / 2});
  const Eigen::Isometry3d b = sextant::to_isometry({2.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  const sextant::Pose6 c = sextant::to_pose6(sextant::compose(a, b));
  // a turns 90° left, so b's 2 m forward becomes 2 m along y: (1, 2, 0), yaw 90°.
  const bool ok =
      std::abs(c.x - 1.0) < 1e-12 && std::abs(c.y - 2.0) < 1e-12 && std::abs(c.gamma - M_PI / 2) < 1e-12;
  std::cout << "composed pose: " << c.x << " " << c.y << " " << c.z << " yaw " << c.gamma
            << (ok ? " ok" : " WRONG") << "\n";
  return ok ? 0 : 1;
}
