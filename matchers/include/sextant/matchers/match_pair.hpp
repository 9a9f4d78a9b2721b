#pragma once
// One registration of a pair, sampler + matcher, for the experiment runner and `sextant match`:
//
//   Rng rng(seed);
//   const PairMatch m = match_pair(*make_matcher("mlndt"), *make_sampler("gbs"), ref, in, guess, rng);
//   m.result.T;  m.kept_fraction;  m.reference_seconds;
#include "sextant/core/point_cloud.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/matchers/sampler.hpp"

namespace sextant {

struct PairMatch {
  RegistrationResult result;       ///< input_points = sampled points offered to the matcher
  double kept_fraction = 0.0;      ///< sampled / all input points
  double reference_seconds = 0.0;  ///< time to build the reference model (grids, trees)
  double sampling_seconds = 0.0;   ///< time to sample the input
};

/// Samples `input`, builds the reference model of `matcher` from `reference`, aligns the sample
/// from `initial` (p_ref ≈ T·p_input) and assesses the result (result.quality, with `quality`'s
/// thresholds). Never throws for bad data.
PairMatch match_pair(Matcher& matcher, const Sampler& sampler, const PointCloud& reference,
                     const PointCloud& input, const Eigen::Isometry3d& initial, Rng& rng,
                     const QualitySettings& quality = {});

/// match_pair's parts, for several registrations of one pair (odometry's recovery): the sample, ...
struct SampledInput {
  PointCloud points;
  double kept_fraction = 0.0;  ///< sampled / all input points
  double seconds = 0.0;        ///< time to sample
};
SampledInput sample_input(const Sampler& sampler, const PointCloud& input, Rng& rng);

/// ... the reference model built from `reference` and the sample aligned against it from `initial`,
/// assessed (match_pair's second half: the sample stays the caller's, for more starts) ...
PairMatch match_sample(Matcher& matcher, const SampledInput& sample, const PointCloud& reference,
                       const Eigen::Isometry3d& initial, const QualitySettings& quality = {});
/// ... and its alignment against the reference model `matcher` holds, assessed (reference_seconds and
/// sampling_seconds 0: the caller counts what it did once).
PairMatch align_sample(Matcher& matcher, const SampledInput& sample, const Eigen::Isometry3d& initial,
                       const QualitySettings& quality = {});

}  // namespace sextant
