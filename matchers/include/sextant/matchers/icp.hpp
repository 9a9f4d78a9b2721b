#pragma once
// The classic ICP baselines the thesis measures NDT against (§2.2.1): point-to-point
// (closed-form SVD per iteration) and point-to-plane (normals by PCA of the k nearest
// reference points, linearised 6×6 Gauss–Newton solve), over our own k-d tree. Registered as
// `icp_p2p` and `icp_p2l`.
//
//   auto icp = make_icp(IcpObjective::kPointToPlane, IcpSettings{});
//   icp->set_reference(reference);
//   RegistrationResult r = icp->align(input, initial);
//
// Each iteration pairs every input point with its nearest reference point within
// `max_correspondence_distance`, solves for the increment Δξ = [Δt Δα Δβ Δγ] (eq. 3.8
// angles), left-applies it, and stops when ‖Δξ‖ < ε or after `max_iterations`.
#include <memory>
#include <string>

#include "sextant/matchers/dof_mask.hpp"
#include "sextant/matchers/matcher.hpp"

namespace sextant {

enum class IcpObjective {
  kPointToPoint,  ///< Σ‖T·p − q‖², closed form (Arun/Horn SVD)
  kPointToPlane,  ///< Σ (nᵀ(T·p − q))², linearised Gauss–Newton
};

struct IcpSettings {
  double max_correspondence_distance = 1.0;  ///< pairs farther apart are rejected [m, ≤ 1000]
  int max_iterations = 50;                   ///< iteration cap
  double epsilon = 1e-4;                     ///< stop when ‖Δξ‖ < ε [m and rad combined]
  int min_correspondences = 10;              ///< fewer matched points → too_few_correspondences
  int normal_neighbours = 10;                ///< k nearest reference points for PCA normals (p2l only)
  /// Free parameters of the increment (YAML `dof: [x, y, yaw]`); the others' increments stay 0.
  DofMask dof;

  bool valid(std::string* why) const;
};

/// The settings of `icp_p2p` and of `icp_p2l`: one type per objective, so that the type names the matcher
/// (matcher_spec.hpp).
struct IcpP2pSettings : IcpSettings {};
struct IcpP2lSettings : IcpSettings {};

/// Throws std::invalid_argument when `settings` are not valid.
std::unique_ptr<Matcher> make_icp(IcpObjective objective, const IcpSettings& settings);

}  // namespace sextant
