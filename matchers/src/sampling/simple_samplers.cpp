// The samplers that need no geometry: all, regular (every k-th), random (uniform subset).
#include <algorithm>
#include <cmath>
#include <numeric>

#include "sextant/core/checked_settings.hpp"
#include "sextant/matchers/samplers.hpp"

namespace sextant {

SampleResult sample_points(const Sampler& sampler, const PointCloud& input, Rng& rng) {
  SampleResult result;
  result.indices = sampler.select(input, rng);
  result.kept_fraction =
      input.empty() ? 0.0 : static_cast<double>(result.indices.size()) / static_cast<double>(input.size());
  return result;
}

std::vector<std::size_t> AllSampler::select(const PointCloud& input, Rng& /*rng*/) const {
  std::vector<std::size_t> indices(input.size());
  std::iota(indices.begin(), indices.end(), std::size_t{0});
  return indices;
}

bool RegularSamplerSettings::valid(std::string* why) const {
  if (step >= 1) return true;
  if (why) *why = "step must be at least 1";
  return false;
}

RegularSampler::RegularSampler(RegularSamplerSettings settings) : settings_(checked(settings, "regular")) {}

std::vector<std::size_t> RegularSampler::select(const PointCloud& input, Rng& /*rng*/) const {
  std::vector<std::size_t> indices;
  indices.reserve(input.size() / settings_.step + 1);
  for (std::size_t i = 0; i < input.size(); i += settings_.step) indices.push_back(i);
  return indices;
}

bool RandomSamplerSettings::valid(std::string* why) const {
  if (fraction >= 0.0 && fraction <= 1.0) return true;
  if (why) *why = "fraction must lie in [0, 1]";
  return false;
}

RandomSampler::RandomSampler(RandomSamplerSettings settings) : settings_(checked(settings, "random")) {}

std::vector<std::size_t> RandomSampler::select(const PointCloud& input, Rng& rng) const {
  const std::size_t n = input.size();
  const auto keep =
      std::min(n, static_cast<std::size_t>(std::llround(settings_.fraction * static_cast<double>(n))));
  std::vector<std::size_t> pool(n);
  std::iota(pool.begin(), pool.end(), std::size_t{0});
  for (std::size_t i = 0; i < keep; ++i)
    std::swap(pool[i], pool[i + rng.index(n - i)]);  // partial Fisher–Yates
  pool.resize(keep);
  std::sort(pool.begin(), pool.end());
  return pool;
}

}  // namespace sextant
