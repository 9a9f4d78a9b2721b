#pragma once
// Which of the six pose parameters ξ = [tx ty tz α β γ] (eq. 3.12) a matcher may change, e.g.
// `dof: [x, y, yaw]` for the thesis' 2D simulation. Inactive parameters keep their initial value.
#include <array>
#include <string>
#include <vector>

namespace sextant {

struct DofMask {
  std::array<bool, 6> active{{true, true, true, true, true, true}};

  int count() const;
  bool all() const { return count() == 6; }
  /// Names: x, y, z, roll (alpha), pitch (beta), yaw (gamma). False with `why` on an unknown name.
  static bool from_names(const std::vector<std::string>& names, DofMask& mask, std::string* why);
  /// "[x, y, yaw]".
  std::string to_string() const;
  /// {"x", "y", "yaw"}: what from_names reads back.
  std::vector<std::string> names() const;
  bool valid(std::string* why) const;
};

}  // namespace sextant
