#pragma once
// Feature-based sampling (§3.3.1.3, Table 3.2, feature extraction process): the input scan is split
// into cells, RANSAC finds the plane inliers in each cell, and those points are the sample.
//
//   sampler `fbs`: settings = plane extraction settings (features/extraction.hpp)
//
// FbML-NDT, ML-NDT on this sample, is fbmlndt_matcher.hpp.
#include <cstdint>
#include <string>
#include <vector>

#include "sextant/features/extraction.hpp"
#include "sextant/matchers/sampler.hpp"

namespace sextant {

/// `fbs`: the indices of the per-cell RANSAC plane inliers (Table 3.2, feature extraction process).
class FeatureBasedSampler final : public Sampler {
 public:
  explicit FeatureBasedSampler(PlaneExtractionSettings settings = {});
  std::string name() const override { return "fbs"; }
  std::vector<std::size_t> select(const PointCloud& input, Rng& rng) const override;

 private:
  PlaneExtractionSettings settings_;
};

}  // namespace sextant
