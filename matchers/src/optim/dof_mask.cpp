#include "sextant/matchers/dof_mask.hpp"

namespace sextant {

namespace {

int parameter_index(const std::string& name) {
  static const char* const kNames[6][2] = {{"x", "tx"},       {"y", "ty"},       {"z", "tz"},
                                           {"roll", "alpha"}, {"pitch", "beta"}, {"yaw", "gamma"}};
  for (int i = 0; i < 6; ++i)
    if (name == kNames[i][0] || name == kNames[i][1]) return i;
  return -1;
}

}  // namespace

int DofMask::count() const {
  int n = 0;
  for (bool a : active) n += a ? 1 : 0;
  return n;
}

bool DofMask::from_names(const std::vector<std::string>& names, DofMask& mask, std::string* why) {
  DofMask out;
  out.active.fill(false);
  for (const std::string& name : names) {
    const int i = parameter_index(name);
    if (i < 0) {
      if (why) *why = "unknown degree of freedom '" + name + "' (known: x y z roll pitch yaw)";
      return false;
    }
    out.active[static_cast<std::size_t>(i)] = true;
  }
  mask = out;
  return mask.valid(why);
}

std::vector<std::string> DofMask::names() const {
  static const char* const kNames[6] = {"x", "y", "z", "roll", "pitch", "yaw"};
  std::vector<std::string> out;
  for (int i = 0; i < 6; ++i)
    if (active[static_cast<std::size_t>(i)]) out.emplace_back(kNames[i]);
  return out;
}

std::string DofMask::to_string() const {
  std::string out = "[";
  for (const std::string& name : names()) out += (out.size() > 1 ? ", " : "") + name;
  return out + "]";
}

bool DofMask::valid(std::string* why) const {
  if (count() > 0) return true;
  if (why) *why = "at least one degree of freedom must be free";
  return false;
}

}  // namespace sextant
