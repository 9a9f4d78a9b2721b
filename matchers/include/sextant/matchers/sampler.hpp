#pragma once
// Input-scan point selection (§2.2.3, §5.1.2.2): all, regular, random, gbs, fbs. A sampler picks
// indices of the input cloud; every random choice draws from the Rng passed in.
#include <cstddef>
#include <string>
#include <vector>

#include "sextant/core/point_cloud.hpp"
#include "sextant/core/rng.hpp"

namespace sextant {

class Sampler {
 public:
  virtual ~Sampler() = default;
  virtual std::string name() const = 0;
  /// Indices of the selected points, ascending.
  virtual std::vector<std::size_t> select(const PointCloud& input, Rng& rng) const = 0;
};

/// The selected indices and the share of the input they represent.
struct SampleResult {
  std::vector<std::size_t> indices;
  double kept_fraction = 0.0;  ///< indices.size() / input.size(); 0 for an empty input
};

/// Runs `sampler` and reports the kept fraction.
SampleResult sample_points(const Sampler& sampler, const PointCloud& input, Rng& rng);

}  // namespace sextant
