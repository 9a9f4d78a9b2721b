#pragma once
// How `sextant match` and the Python module's match() register one pair, in one place so that both
// give the same result for the same inputs and options (match_pair does one registration):
//   - without an initial guess the wide basin searches around the identity (`wide_basin` false: a
//     plain registration from the identity);
//   - with a guess the guess is refined, and an untrusted result is registered again with the wide
//     basin from the same guess (same sampler seed); the retry replaces the first result only when
//     it is trusted;
//   - settings that hold their own `wide_basin:` map always search with it.
//   - a trusted answer is confirmed by the input's points above the horizon (horizon_check.hpp), for
//     clouds in their sensor's frame taken by a spinning lidar (sensor_kind.hpp: declared, or measured
//     on the input): nothing else bounds a pair's answer, and a solid-state lidar draws no rings.
// Matchers without a wide basin (ICP, the PCL peers) register once, from the guess or the identity.
// Clouds far from the origin of their coordinates are registered about the middle of the reference
// (registration_centre.hpp), and the result is brought back to the clouds' coordinates
// (docs/bad_input.md).
#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/matchers/registration_centre.hpp"
#include "sextant/matchers/sensor_kind.hpp"

namespace sextant {

struct PairRegistrationRequest {
  /// The matcher (matcher_choice.hpp; by name from YAML: matchers/yaml.hpp); default ML-NDT
  MatcherChoice matcher = matcher_choice(MlndtSettings{});
  SamplerFactory sampler = sampler_factory(GridSamplerSettings{});  ///< default GBS
  std::optional<Eigen::Isometry3d> init;  ///< p_reference ≈ init · p_input; none: the identity, searched
  bool wide_basin = true;                 ///< false: no search without a guess, no retry with one
  std::uint64_t seed = 1;                 ///< the sampler's random choices
  SensorKind sensor = SensorKind::automatic;  ///< the lidar; automatic: measured on the input
};

struct PairRegistration {
  PairMatch match;
  bool searched = false;  ///< the result came from the wide basin
  /// How: "wide basin", "from the guess", with ", <trust>: recovered by the wide basin" or
  /// ", <trust>: the wide basin found no trusted pose either" after a retry.
  std::string search;
  bool searched_without_guess = false;  ///< no guess: the wide basin searched (callers name their switch)
  /// The lidar the horizon check assumed (declared, or measured on the input; none for clouds not in
  /// their sensor's frame, which are not checked above the horizon)
  std::optional<SensorDetection> sensor;
  /// The point the registration turned about, in the clouds' coordinates (zero: their origin). The
  /// transforms are in the clouds' coordinates; the Hessian (and the covariance from it) is that of
  /// the pose about this point.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

/// Registers `input` against `reference` (see above). Never throws for bad data; whatever the
/// request's factories throw for bad settings (the YAML ones: InputErrors naming their file) passes.
PairRegistration register_pair(const PointCloud& reference, const PointCloud& input,
                               const PairRegistrationRequest& request);

/// The registration's covariance R = H⁻¹ (eq. 3.50), rows and columns [x y z α β γ] (m, rad) for
/// the NDT family; NaN everywhere when H is not positive definite (a degenerate or failed result).
Matrix6d registration_covariance(const Matrix6d& H);

}  // namespace sextant
