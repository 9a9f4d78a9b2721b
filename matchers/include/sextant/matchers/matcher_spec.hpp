#pragma once
// A matcher and a sampler chosen by value: the settings struct, whose type names the matcher. Parsed
// once at the edge (YAML: read_matcher_spec of matchers/yaml.hpp; the CLI's flags; the Python
// module's keyword arguments) and carried as this type from there: nothing downstream reads text.
//
//   MatcherSpec spec = MlndtSettings{};            // the default ML-NDT
//   spec.name();                                   // "mlndt"
//   MatcherChoice choice = matcher_choice(spec);    // for register_pair and odometry (matcher_choice.hpp)
//
// The catalogue below is the one list of matchers and samplers: a new matcher is an alternative of
// MatcherSettings and its MatcherKind row (name, traits, how it is built).
#include <memory>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "sextant/features/extraction.hpp"
#include "sextant/matchers/fbmlndt_matcher.hpp"
#include "sextant/matchers/feature_based_sampler.hpp"
#include "sextant/matchers/icp.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/matcher_traits.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/pcl_peers.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/samplers.hpp"

namespace sextant {

/// What the code knows of each matcher: its name, its traits, how it is built from its settings.
template <class Settings>
struct MatcherKind;

template <>
struct MatcherKind<MlndtSettings> {
  static constexpr const char* kName = "mlndt";  ///< Multi-Layered NDT, Mahalanobis score (Table 3.1)
  static constexpr MatcherTraits kTraits{true, true, true, true, true};
  static std::unique_ptr<Matcher> make(const MlndtSettings& s) { return std::make_unique<MlndtMatcher>(s); }
};
template <>
struct MatcherKind<FbmlndtSettings> {
  static constexpr const char* kName = "fbmlndt";  ///< ML-NDT on the input's plane inliers (Table 3.2)
  static constexpr MatcherTraits kTraits{true, true, true, true, false};
  static std::unique_ptr<Matcher> make(const FbmlndtSettings& s) {
    return std::make_unique<FbmlndtMatcher>(s);
  }
};
template <>
struct MatcherKind<NdtSettings> {
  static constexpr const char* kName = "ndt";  ///< classic P2D-NDT, Gaussian score, fixed grid
  static constexpr MatcherTraits kTraits{};
  static std::unique_ptr<Matcher> make(const NdtSettings& s) { return std::make_unique<NdtMatcher>(s); }
};
template <>
struct MatcherKind<IcpP2pSettings> {
  static constexpr const char* kName = "icp_p2p";  ///< point-to-point ICP (closed-form SVD, k-d tree)
  static constexpr MatcherTraits kTraits{};
  static std::unique_ptr<Matcher> make(const IcpP2pSettings& s) {
    return make_icp(IcpObjective::kPointToPoint, s);
  }
};
template <>
struct MatcherKind<IcpP2lSettings> {
  static constexpr const char* kName = "icp_p2l";  ///< point-to-plane ICP (PCA normals, k-d tree)
  static constexpr MatcherTraits kTraits{};
  static std::unique_ptr<Matcher> make(const IcpP2lSettings& s) {
    return make_icp(IcpObjective::kPointToPlane, s);
  }
};
template <>
struct MatcherKind<PclNdtSettings> {
  static constexpr const char* kName = "pcl_ndt";  ///< PCL NormalDistributionsTransform (peer)
  static constexpr MatcherTraits kTraits{};
  static std::unique_ptr<Matcher> make(const PclNdtSettings& s) { return make_pcl_ndt(s); }
};
template <>
struct MatcherKind<PclIcpSettings> {
  static constexpr const char* kName = "pcl_icp";  ///< PCL IterativeClosestPoint (peer)
  static constexpr MatcherTraits kTraits{};
  static std::unique_ptr<Matcher> make(const PclIcpSettings& s) { return make_pcl_icp(s); }
};
template <>
struct MatcherKind<PclGicpSettings> {
  static constexpr const char* kName = "pcl_gicp";  ///< PCL GeneralizedIterativeClosestPoint (peer)
  static constexpr MatcherTraits kTraits{};
  static std::unique_ptr<Matcher> make(const PclGicpSettings& s) { return make_pcl_gicp(s); }
};

using MatcherSettings = std::variant<MlndtSettings, FbmlndtSettings, NdtSettings, IcpP2pSettings,
                                     IcpP2lSettings, PclNdtSettings, PclIcpSettings, PclGicpSettings>;

/// What the code knows of each sampler (§2.2.3, §5.1.2.2): its name and how it is built.
template <class Settings>
struct SamplerKind;

template <>
struct SamplerKind<AllPointsSettings> {
  static constexpr const char* kName = "all";  ///< every input point
  static std::unique_ptr<Sampler> make(const AllPointsSettings&) { return std::make_unique<AllSampler>(); }
};
template <>
struct SamplerKind<GridSamplerSettings> {
  static constexpr const char* kName = "gbs";  ///< grid-based sampling: at most max_per_cell points a cell
  static std::unique_ptr<Sampler> make(const GridSamplerSettings& s) {
    return std::make_unique<GridSampler>(s);
  }
};
template <>
struct SamplerKind<PlaneExtractionSettings> {
  static constexpr const char* kName = "fbs";  ///< feature-based sampling: per-cell RANSAC plane inliers
  static std::unique_ptr<Sampler> make(const PlaneExtractionSettings& s) {
    return std::make_unique<FeatureBasedSampler>(s);
  }
};
template <>
struct SamplerKind<RandomSamplerSettings> {
  static constexpr const char* kName = "random";  ///< a uniform random fraction of the points
  static std::unique_ptr<Sampler> make(const RandomSamplerSettings& s) {
    return std::make_unique<RandomSampler>(s);
  }
};
template <>
struct SamplerKind<RegularSamplerSettings> {
  static constexpr const char* kName = "regular";  ///< every step-th point
  static std::unique_ptr<Sampler> make(const RegularSamplerSettings& s) {
    return std::make_unique<RegularSampler>(s);
  }
};

using SamplerSettings = std::variant<AllPointsSettings, GridSamplerSettings, PlaneExtractionSettings,
                                     RandomSamplerSettings, RegularSamplerSettings>;

/// A matcher by value: one of the catalogue's settings structs.
struct MatcherSpec {
  MatcherSettings settings;  ///< default: the default ML-NDT

  MatcherSpec() = default;
  template <class S, class = std::enable_if_t<std::is_constructible_v<MatcherSettings, S>>>
  MatcherSpec(S s) : settings(std::move(s)) {}  // NOLINT: a settings struct is a spec

  std::string name() const;
  MatcherTraits traits() const;
  bool valid(std::string* why) const;
  /// The settings when they are of type S, else null.
  template <class S>
  const S* get() const {
    return std::get_if<S>(&settings);
  }
  template <class S>
  S* get() {
    return std::get_if<S>(&settings);
  }
};

/// A sampler by value: one of the catalogue's settings structs.
struct SamplerSpec {
  SamplerSettings settings = GridSamplerSettings{};  ///< default: GBS

  SamplerSpec() = default;
  template <class S, class = std::enable_if_t<std::is_constructible_v<SamplerSettings, S>>>
  SamplerSpec(S s) : settings(std::move(s)) {}  // NOLINT: a settings struct is a spec

  std::string name() const;
  bool valid(std::string* why) const;
  template <class S>
  const S* get() const {
    return std::get_if<S>(&settings);
  }
};

/// A matcher with the sampler of its input: one registration method.
struct RegistrationSpec {
  MatcherSpec matcher;
  SamplerSpec sampler;
};

/// The catalogue's names, sorted (the spelling of YAML's `matcher:` / `sampler:` and the flags).
std::vector<std::string> matcher_names();
std::vector<std::string> sampler_names();

/// The matcher (sampler) as specified, bare (not judged, judged_matcher.hpp); std::invalid_argument
/// when the settings are not valid.
std::unique_ptr<Matcher> make_matcher(const MatcherSpec& spec);
std::unique_ptr<Sampler> make_sampler(const SamplerSpec& spec);

/// The same matcher with the wide basin on (mlndt_global_init.hpp): its own wide-basin settings when
/// the spec enables them, else their defaults; the spec itself for a matcher without a wide basin.
MatcherSpec with_wide_basin(const MatcherSpec& spec);
/// The spec starts the layer pyramid at `layer` (mlndt and fbmlndt; false, and unchanged, for the others).
bool set_start_layer(MatcherSpec& spec, int layer);
/// The pyramid's last layer (mlndt and fbmlndt `layers`), 0 for a matcher without one.
int last_layer(const MatcherSpec& spec);

}  // namespace sextant
