#include "kit/dataset_source.hpp"

#include "kit/simulated_odometry_dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/synth/campus.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/yaml.hpp"

namespace sextant {
namespace {

[[noreturn]] void no_source(const ExperimentConfig& config, const std::string& kind) {
  throw InputError(config.file, "", "key 'dataset': the " + kind + " kind needs source: synthetic or folder");
}

}  // namespace

synth::OdometrySettings simulated_odometry_settings(const ExperimentConfig& config) {
  YAML::Node campus(YAML::NodeType::Map);
  campus["odometry"] = config.dataset.simulated_odometry;
  return synth::read_campus_settings(campus, config.file).odometry;  // checks keys, types and bounds
}

void check_experiment_dataset(const ExperimentConfig& config, const std::string& kind) {
  if (config.dataset.source == DatasetSource::kNone) no_source(config, kind);
  if (config.dataset.simulates_odometry()) (void)simulated_odometry_settings(config);
  if (config.dataset.source == DatasetSource::kSynthetic) {
    std::uint64_t seed = config.dataset.seed;
    (void)synth::read_campus_settings(config.dataset.campus, config.file, &seed);
  }
}

std::unique_ptr<Dataset> open_experiment_dataset(const ExperimentConfig& config, const std::string& kind) {
  switch (config.dataset.source) {
    case DatasetSource::kSynthetic: {
      std::uint64_t seed = config.dataset.seed;
      const synth::CampusSettings settings =
          synth::read_campus_settings(config.dataset.campus, config.file, &seed);
      return std::make_unique<synth::CampusDataset>(synth::generate_campus(settings, seed));
    }
    case DatasetSource::kFolder: {
      RecordingSelection selection = config.dataset.recording;
      selection.topic_argument = "the key 'topic' of " + config.file;
      std::unique_ptr<Dataset> folder = open_dataset_or_recording(config.dataset.path, selection);
      if (!config.dataset.simulates_odometry()) return folder;
      return std::make_unique<SimulatedOdometryDataset>(
          std::move(folder), simulated_odometry_settings(config), config.dataset.seed);
    }
    case DatasetSource::kNone: break;
  }
  no_source(config, kind);
}

}  // namespace sextant
