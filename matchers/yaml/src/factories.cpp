// The YAML factories of the matcher and sampler registries (Sextant::matchers_yaml): each reads its
// settings (null node: the defaults) and builds the matcher or sampler of the library.
#include "readers.hpp"

#include "sextant/features/yaml.hpp"
#include "sextant/matchers/fbmlndt_matcher.hpp"
#include "sextant/matchers/icp.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/pcl_peers.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {

std::unique_ptr<Matcher> create_mlndt_matcher(const YAML::Node& settings, const std::string& file) {
  return std::make_unique<MlndtMatcher>(read_mlndt_settings(settings, file));
}

std::unique_ptr<Matcher> create_ndt_matcher(const YAML::Node& settings, const std::string& file) {
  return std::make_unique<NdtMatcher>(read_ndt_settings(settings, file));
}

std::unique_ptr<Matcher> make_icp_p2p_matcher(const YAML::Node& settings, const std::string& file) {
  return make_icp(IcpObjective::kPointToPoint,
                  read_icp_settings(IcpObjective::kPointToPoint, settings, file));
}

std::unique_ptr<Matcher> make_icp_p2l_matcher(const YAML::Node& settings, const std::string& file) {
  return make_icp(IcpObjective::kPointToPlane,
                  read_icp_settings(IcpObjective::kPointToPlane, settings, file));
}

std::unique_ptr<Matcher> make_pcl_ndt_matcher(const YAML::Node& settings, const std::string& file) {
  return make_pcl_ndt(read_pcl_ndt_settings(settings, file));
}

std::unique_ptr<Matcher> make_pcl_icp_matcher(const YAML::Node& settings, const std::string& file) {
  return make_pcl_icp(read_pcl_icp_settings(settings, file));
}

std::unique_ptr<Matcher> make_pcl_gicp_matcher(const YAML::Node& settings, const std::string& file) {
  return make_pcl_gicp(read_pcl_gicp_settings(settings, file));
}

std::unique_ptr<Matcher> create_fbmlndt_matcher(const YAML::Node& settings, const std::string& file) {
  return std::make_unique<FbmlndtMatcher>(read_fbmlndt_settings(settings, file));
}

std::unique_ptr<Sampler> create_feature_based_sampler(const YAML::Node& settings, const std::string& file) {
  return std::make_unique<FeatureBasedSampler>(read_plane_extraction_settings(settings, file));
}

std::unique_ptr<Sampler> create_grid_sampler(const YAML::Node& settings, const std::string& file) {
  return std::make_unique<GridSampler>(read_grid_sampler_settings(settings, file));
}

namespace {

template <class Settings>
Settings checked(SettingsReader& in, const Settings& s) {
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

}  // namespace

std::unique_ptr<Sampler> create_all_sampler(const YAML::Node& settings, const std::string& file) {
  SettingsReader in(settings, file);
  in.finish();
  return std::make_unique<AllSampler>();
}

std::unique_ptr<Sampler> create_regular_sampler(const YAML::Node& settings, const std::string& file) {
  SettingsReader in(settings, file);
  RegularSamplerSettings s;
  in.read("step", s.step);
  return std::make_unique<RegularSampler>(checked(in, s));
}

std::unique_ptr<Sampler> create_random_sampler(const YAML::Node& settings, const std::string& file) {
  SettingsReader in(settings, file);
  RandomSamplerSettings s;
  in.read("fraction", s.fraction);
  return std::make_unique<RandomSampler>(checked(in, s));
}

}  // namespace sextant
