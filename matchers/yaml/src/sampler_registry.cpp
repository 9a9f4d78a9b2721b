// The sampler registry: one line per built-in sampler (others insert their own lines).
#include "readers.hpp"

#include "sextant/matchers/yaml.hpp"

namespace sextant {

namespace {

SamplerRegistry make_builtin_samplers() {
  SamplerRegistry registry("sampler");
  registry.add("all", "every input point", create_all_sampler);
  registry.add("fbs", "feature-based sampling: plane inliers of per-cell RANSAC (Table 3.2)",
               create_feature_based_sampler);
  registry.add("gbs", "grid-based sampling: at most max_per_cell random points per cell",
               create_grid_sampler);
  registry.add("random", "uniform random subset of a fraction of the points", create_random_sampler);
  registry.add("regular", "every step-th point", create_regular_sampler);
  return registry;
}

}  // namespace

SamplerRegistry& sampler_registry() {
  static SamplerRegistry registry = make_builtin_samplers();
  return registry;
}

std::unique_ptr<Sampler> make_sampler(const std::string& name, const YAML::Node& settings,
                                      const std::string& file) {
  return sampler_registry().create(name, settings, file);
}

SamplerFactory sampler_factory(const std::string& name, const YAML::Node& settings, const std::string& file) {
  return [name, settings, file] { return make_sampler(name, settings, file); };
}

}  // namespace sextant
