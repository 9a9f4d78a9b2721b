// Matchers and samplers chosen in code (matcher_choice.hpp).
#include "sextant/matchers/matcher_choice.hpp"

#include "sextant/matchers/judged_matcher.hpp"

namespace sextant {

namespace {

template <class Settings, class Make>
MatcherChoice choice(std::string name, const Settings& settings, Make make) {
  MatcherChoice c;
  c.name = std::move(name);
  c.make = [settings, make] { return judged(make(settings)); };
  return c;
}

/// The wide basin on, with its own settings when the ML-NDT settings enable it, else its defaults.
MlndtSettings with_wide_basin(MlndtSettings s) {
  if (!s.wide_basin.enabled) {
    s.wide_basin = WideBasinSettings{};
    s.wide_basin.enabled = true;
  }
  return s;
}

}  // namespace

MatcherChoice matcher_choice(const MlndtSettings& settings) {
  MatcherChoice c = choice("mlndt", settings, [](const MlndtSettings& s) -> std::unique_ptr<Matcher> {
    return std::make_unique<MlndtMatcher>(s);
  });
  const MlndtSettings wide = with_wide_basin(settings);
  c.make_wide = [wide]() -> std::unique_ptr<Matcher> { return std::make_unique<MlndtMatcher>(wide); };
  c.own_wide_basin = settings.wide_basin.enabled;
  return c;
}

MatcherChoice matcher_choice(const FbmlndtSettings& settings) {
  MatcherChoice c = choice("fbmlndt", settings, [](const FbmlndtSettings& s) -> std::unique_ptr<Matcher> {
    return std::make_unique<FbmlndtMatcher>(s);
  });
  FbmlndtSettings wide = settings;
  wide.mlndt = with_wide_basin(settings.mlndt);
  c.make_wide = [wide]() -> std::unique_ptr<Matcher> { return std::make_unique<FbmlndtMatcher>(wide); };
  c.own_wide_basin = settings.mlndt.wide_basin.enabled;
  return c;
}

MatcherChoice matcher_choice(const NdtSettings& settings) {
  return choice("ndt", settings, [](const NdtSettings& s) -> std::unique_ptr<Matcher> {
    return std::make_unique<NdtMatcher>(s);
  });
}

MatcherChoice matcher_choice(IcpObjective objective, const IcpSettings& settings) {
  return choice(objective == IcpObjective::kPointToPlane ? "icp_p2l" : "icp_p2p", settings,
                [objective](const IcpSettings& s) { return make_icp(objective, s); });
}

MatcherChoice matcher_choice(const PclNdtSettings& settings) {
  return choice("pcl_ndt", settings, [](const PclNdtSettings& s) { return make_pcl_ndt(s); });
}

MatcherChoice matcher_choice(const PclIcpSettings& settings) {
  return choice("pcl_icp", settings, [](const PclIcpSettings& s) { return make_pcl_icp(s); });
}

MatcherChoice matcher_choice(const PclGicpSettings& settings) {
  return choice("pcl_gicp", settings, [](const PclGicpSettings& s) { return make_pcl_gicp(s); });
}

SamplerFactory sampler_factory(const GridSamplerSettings& settings) {
  return [settings]() -> std::unique_ptr<Sampler> { return std::make_unique<GridSampler>(settings); };
}

SamplerFactory sampler_factory(const RegularSamplerSettings& settings) {
  return [settings]() -> std::unique_ptr<Sampler> { return std::make_unique<RegularSampler>(settings); };
}

SamplerFactory sampler_factory(const RandomSamplerSettings& settings) {
  return [settings]() -> std::unique_ptr<Sampler> { return std::make_unique<RandomSampler>(settings); };
}

SamplerFactory sampler_factory(const PlaneExtractionSettings& settings) {
  return [settings]() -> std::unique_ptr<Sampler> { return std::make_unique<FeatureBasedSampler>(settings); };
}

SamplerFactory all_points_sampler_factory() {
  return []() -> std::unique_ptr<Sampler> { return std::make_unique<AllSampler>(); };
}

}  // namespace sextant
