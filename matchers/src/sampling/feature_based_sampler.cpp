#include "sextant/matchers/feature_based_sampler.hpp"

#include <stdexcept>
#include <utility>

#include "sextant/core/checked_settings.hpp"

namespace sextant {

FeatureBasedSampler::FeatureBasedSampler(PlaneExtractionSettings settings)
    : settings_(checked(std::move(settings), "fbs")) {}

// Table 3.2, feature extraction process: split S into cells, RANSAC per cell, F = the inliers.
std::vector<std::size_t> FeatureBasedSampler::select(const PointCloud& input, Rng& rng) const {
  return extract_cell_planes(input, settings_, rng).cell_inlier_indices();
}

}  // namespace sextant
