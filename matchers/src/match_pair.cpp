#include "sextant/matchers/match_pair.hpp"

#include <chrono>

namespace sextant {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

PairMatch match_pair(Matcher& matcher, const Sampler& sampler, const PointCloud& reference,
                     const PointCloud& input, const Eigen::Isometry3d& initial, Rng& rng,
                     const QualitySettings& quality) {
  PairMatch out;
  auto start = std::chrono::steady_clock::now();
  const SampleResult sample = sample_points(sampler, input, rng);
  const PointCloud sampled = input.subset(sample.indices);
  out.kept_fraction = sample.kept_fraction;
  out.sampling_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  matcher.set_reference(reference);
  out.reference_seconds = seconds_since(start);
  out.result = matcher.align(sampled, initial);
  // A matcher that samples again (FbML-NDT) says how many points it matched from; the others, the sample.
  if (out.result.input_points == 0) out.result.input_points = sampled.size();
  out.result.quality = assess_registration(out.result, sampled, quality);
  return out;
}

}  // namespace sextant
