#pragma once
// The one way a constructor enforces its settings: every settings struct has `bool valid(std::string*
// why) const`, and a class built from invalid settings throws std::invalid_argument naming them.
//
//   explicit GridSampler(GridSamplerSettings s) : settings_(checked(std::move(s), "gbs")) {}
#include <stdexcept>
#include <string>

namespace sextant {

template <class Settings>
Settings checked(Settings settings, const char* what) {
  std::string why;
  if (!settings.valid(&why))
    throw std::invalid_argument(std::string("invalid ") + what + " settings: " + why);
  return settings;
}

}  // namespace sextant
