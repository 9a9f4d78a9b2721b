#pragma once
// The matcher choice shared by `sextant match` and `sextant odometry`: --method, --preset,
// --solver, --sampling and an optional --config YAML file with `matcher:` and `sampler:` maps.
#include <string>

#include "sextant/pipeline/matcher_request.hpp"

namespace sextant::cli {

struct MatcherOptions {
  std::string method = "mlndt";
  std::string preset;  ///< mlndt / fbmlndt settings preset; empty: "default" (matcher_request.hpp)
  std::string solver;  ///< empty: the preset's
  std::string sampling = "gbs";
  std::string config;  ///< YAML file with optional `matcher:` and `sampler:` maps
};

/// The flags and the --config file's maps, read (matcher_request.hpp): errors name --config or the flags.
MatcherConfig read_matcher_config(const MatcherOptions& o, bool wide_basin = false);

}  // namespace sextant::cli
