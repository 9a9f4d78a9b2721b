#pragma once
// The synthetic campus an experiment's `dataset:` block asks for (source: synthetic, seed, campus
// settings), for the kinds that run over the campus' scans.
#include <cstdint>
#include <string>

#include "sextant/experiments/experiment_config.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant {

/// The campus settings and seed of `config` (InputError unless the source is synthetic; `kind`
/// names the kind in the message).
synth::CampusSettings campus_settings(const ExperimentConfig& config, const std::string& kind,
                                      std::uint64_t* seed);

/// The campus itself, generated.
synth::Campus open_campus(const ExperimentConfig& config, const std::string& kind);

}  // namespace sextant
