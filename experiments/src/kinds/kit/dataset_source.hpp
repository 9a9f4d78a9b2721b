#pragma once
// The dataset of an experiment config, for the kinds that read scans (registration, sequence):
// `source: synthetic` builds the built-in campus in memory from `campus:` settings and `seed`;
// `source: folder` opens a uos, KITTI or scan folder or a recording (`path:`, relative to the config file;
// a recording's `topic:`, `start:`, `duration:`, `every:` choose its scans), with
// `simulated_odometry:` an odometry simulated from its reference (kit/simulated_odometry_dataset.hpp).
#include <memory>
#include <string>

#include "sextant/core/dataset.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/synth/settings.hpp"

namespace sextant {

/// Checks the dataset block without generating anything (InputError naming `kind`).
void check_experiment_dataset(const ExperimentConfig& config, const std::string& kind);
/// The error model of a folder's simulated odometry (config.dataset.simulates_odometry()): its
/// `simulated_odometry:` map read as the campus' `odometry:` block (InputError for a bad key or value).
synth::OdometrySettings simulated_odometry_settings(const ExperimentConfig& config);
/// Opens the dataset (InputError when the source is none).
std::unique_ptr<Dataset> open_experiment_dataset(const ExperimentConfig& config, const std::string& kind);

}  // namespace sextant
