#pragma once
// How `sextant match` and the Python module's match() register one pair, in one place so that both
// give the same result for the same inputs and options (match_pair does one registration):
//   - without an initial guess the wide basin searches around the identity (`wide_basin` false: a
//     plain registration from the identity);
//   - with a guess the guess is refined, and an untrusted result is registered again with the wide
//     basin from the same guess (same sampler seed); the retry replaces the first result only when
//     it is trusted;
//   - settings that hold their own `wide_basin:` map always search with it.
// Matchers without a wide basin (ICP, the PCL peers) register once, from the guess or the identity.
// A registration turns the input about the origin of its coordinates, the sensor in a scan's own
// frame. Clouds far from that origin (georeferenced, or exported in a map frame) would turn about a
// point hundreds of metres or kilometres away, where a thousandth of a degree moves them by
// centimetres: 300 m away the Velodyne pair ends 2.6 m off (degenerate), 5,400 km away 67 km off.
// Such a pair is registered in a frame centred at the reference (registration_centre), and the
// result is brought back to the clouds' coordinates.
#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/matcher_choice.hpp"

namespace sextant {

struct PairRegistrationRequest {
  /// The matcher (matcher_choice.hpp; by name from YAML: matchers/yaml.hpp); default ML-NDT
  MatcherChoice matcher = matcher_choice(MlndtSettings{});
  SamplerFactory sampler = sampler_factory(GridSamplerSettings{});  ///< default GBS
  std::optional<Eigen::Isometry3d> init;  ///< p_reference ≈ init · p_input; none: the identity, searched
  bool wide_basin = true;                 ///< false: no search without a guess, no retry with one
  std::uint64_t seed = 1;                 ///< the sampler's random choices
};

struct PairRegistration {
  PairMatch match;
  bool searched = false;  ///< the result came from the wide basin
  /// How: "wide basin", "from the guess", with ", <trust>: recovered by the wide basin" or
  /// ", <trust>: the wide basin found no trusted pose either" after a retry.
  std::string search;
  bool searched_without_guess = false;  ///< no guess: the wide basin searched (callers name their switch)
  /// The point the registration turned about, in the clouds' coordinates (zero: their origin). The
  /// transforms are in the clouds' coordinates; the Hessian (and the covariance from it) is that of
  /// the pose about this point.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

/// Where a pair with this reference is registered about: the origin of the coordinates when a
/// sensor could stand there (it lies no farther from the reference's bounding box than half the
/// box's diagonal), else the centre of the box.
Eigen::Vector3d registration_centre(const PointCloud& reference);

/// Registers `input` against `reference` (see above). Never throws for bad data; whatever the
/// request's factories throw for bad settings (the YAML ones: InputErrors naming their file) passes.
PairRegistration register_pair(const PointCloud& reference, const PointCloud& input,
                               const PairRegistrationRequest& request);

/// The registration's covariance R = H⁻¹ (eq. 3.50), rows and columns [x y z α β γ] (m, rad) for
/// the NDT family; NaN everywhere when H is not positive definite (a degenerate or failed result).
Matrix6d registration_covariance(const Matrix6d& H);

}  // namespace sextant
