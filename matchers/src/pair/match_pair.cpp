#include "sextant/matchers/match_pair.hpp"

#include <chrono>

namespace sextant {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SampledInput sample_input(const Sampler& sampler, const PointCloud& input, Rng& rng) {
  const auto start = std::chrono::steady_clock::now();
  const SampleResult sample = sample_points(sampler, input, rng);
  SampledInput out;
  out.points = input.subset(sample.indices);
  out.kept_fraction = sample.kept_fraction;
  out.seconds = seconds_since(start);
  return out;
}

PairMatch align_sample(Matcher& matcher, const SampledInput& sample, const Eigen::Isometry3d& initial,
                       const QualitySettings& quality) {
  PairMatch out;
  out.kept_fraction = sample.kept_fraction;
  out.result = matcher.align(sample.points, initial);
  // A matcher that samples again (FbML-NDT) says how many points it matched from; the others, the sample.
  if (out.result.input_points == 0) out.result.input_points = sample.points.size();
  out.result.quality = assess_registration(out.result, sample.points, quality);
  return out;
}

PairMatch match_sample(Matcher& matcher, const SampledInput& sample, const PointCloud& reference,
                       const Eigen::Isometry3d& initial, const QualitySettings& quality) {
  const auto start = std::chrono::steady_clock::now();
  matcher.set_reference(reference);
  const double reference_seconds = seconds_since(start);
  PairMatch out = align_sample(matcher, sample, initial, quality);
  out.reference_seconds = reference_seconds;
  out.sampling_seconds = sample.seconds;
  return out;
}

PairMatch match_pair(Matcher& matcher, const Sampler& sampler, const PointCloud& reference,
                     const PointCloud& input, const Eigen::Isometry3d& initial, Rng& rng,
                     const QualitySettings& quality) {
  return match_sample(matcher, sample_input(sampler, input, rng), reference, initial, quality);
}

}  // namespace sextant
