#include "sextant/features/plane.hpp"

namespace sextant {

// n' = R·n, d' = d + n'·t  (eqs. (4.57)–(4.58)).
Plane Plane::transformed(const Eigen::Isometry3d& T) const {
  Plane out;
  out.normal = T.linear() * normal;
  out.d = d + out.normal.dot(T.translation());
  return out;
}

}  // namespace sextant
