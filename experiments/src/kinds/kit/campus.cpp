#include "kit/campus.hpp"

#include "sextant/core/error.hpp"
#include "sextant/synth/yaml.hpp"

namespace sextant {

synth::CampusSettings campus_settings(const ExperimentConfig& config, const std::string& kind,
                                      std::uint64_t* seed) {
  if (config.dataset.source != DatasetSource::kSynthetic)
    throw InputError(config.file, "", "key 'dataset': the " + kind + " kind needs source: synthetic");
  *seed = config.dataset.seed;
  return synth::read_campus_settings(config.dataset.campus, config.file, seed);
}

synth::Campus open_campus(const ExperimentConfig& config, const std::string& kind) {
  std::uint64_t seed = 0;
  const synth::CampusSettings settings = campus_settings(config, kind, &seed);
  return synth::generate_campus(settings, seed);
}

}  // namespace sextant
