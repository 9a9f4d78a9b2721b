#include "sextant/experiments/run_plan.hpp"

#include <cctype>
#include <stdexcept>

#include "sextant/core/error.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/pipeline/json.hpp"
#include "sextant/pipeline/yaml_json.hpp"

namespace sextant {

std::string point_label(const YAML::Node& value) {
  return value.IsScalar() ? value.Scalar() : canonical_json(value);
}

namespace {

// Mixes the base seed with the sweep point and repetition (not the method), so every method of
// one point and repetition sees the same random draws: paired comparisons.
std::uint64_t run_seed(std::uint64_t base, const YAML::Node& point, int repetition) {
  const std::string text =
      std::to_string(base) + "|" + canonical_json(point) + "|" + std::to_string(repetition);
  return stable_hash(text);
}

}  // namespace

std::vector<RunSpec> expand_sweep(const ExperimentConfig& config) {
  std::size_t points = 1;
  for (const auto& axis : config.sweep) points *= axis.values.size();

  std::vector<RunSpec> runs;
  runs.reserve(config.methods.size() * points * static_cast<std::size_t>(config.repetitions));
  for (std::size_t m = 0; m < config.methods.size(); ++m) {
    for (std::size_t p = 0; p < points; ++p) {
      // Mixed-radix decomposition of p: the first axis varies slowest.
      std::vector<std::size_t> digit(config.sweep.size());
      std::size_t rest = p;
      for (std::size_t a = config.sweep.size(); a-- > 0;) {
        digit[a] = rest % config.sweep[a].values.size();
        rest /= config.sweep[a].values.size();
      }
      for (int r = 0; r < config.repetitions; ++r) {
        RunSpec run;
        run.index = runs.size();
        run.method = config.methods[m].name;
        run.method_index = m;
        run.repetition = r;
        YAML::Node point(YAML::NodeType::Map);
        for (std::size_t a = 0; a < config.sweep.size(); ++a) {
          const YAML::Node& value = config.sweep[a].values[digit[a]];
          point[config.sweep[a].name] = YAML::Clone(value);
          run.point[config.sweep[a].name] = point_label(value);
        }
        run.seed = run_seed(config.seed, point, r);
        YAML::Node resolved(YAML::NodeType::Map);
        resolved["experiment"] = config.name;
        resolved["kind"] = config.kind;
        resolved["dataset"] = YAML::Clone(config.dataset.node);
        resolved["method"] = YAML::Clone(config.methods[m].node);
        resolved["point"] = point;
        resolved["repetition"] = r;
        resolved["seed"] = run.seed;
        resolved["params"] = YAML::Clone(config.params);
        run.key = hex64(stable_hash(canonical_json(resolved)));
        run.resolved = resolved;
        runs.push_back(std::move(run));
      }
    }
  }
  return runs;
}

std::vector<RunSpec> expand_runs(const ExperimentConfig& config) {
  std::vector<RunSpec> runs = expand_sweep(config);
  // An unknown kind is reported as such by whoever asks for it (runner, report); its runs are the sweep.
  if (!run_kind_registry().contains(config.kind)) return runs;
  const std::vector<bool> planned = run_kind_registry().create(config.kind)->planned_runs(config, runs);
  if (planned.size() != runs.size())
    throw std::logic_error("run kind '" + config.kind + "' shaped a plan of " +
                           std::to_string(planned.size()) + " flags for " + std::to_string(runs.size()) +
                           " runs");
  std::vector<RunSpec> plan;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (!planned[k]) continue;
    runs[k].index = plan.size();  // shards split the planned runs evenly (index mod n)
    plan.push_back(std::move(runs[k]));
  }
  return plan;
}

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto bad = [&text]() {
    return InputError("--shard", "", "'" + text + "' is not i/n with 1 ≤ i ≤ n (e.g. --shard 2/8)");
  };
  if (slash == std::string::npos || slash == 0 || slash + 1 >= text.size()) throw bad();
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (k != slash && !std::isdigit(static_cast<unsigned char>(text[k]))) throw bad();
  }
  if (slash > 9 || text.size() - slash - 1 > 9) throw bad();
  const std::size_t i = std::stoul(text.substr(0, slash));
  const std::size_t n = std::stoul(text.substr(slash + 1));
  if (n < 1 || i < 1 || i > n) throw bad();
  return Shard{i - 1, n};
}

std::vector<RunSpec> select_shard(const std::vector<RunSpec>& runs, const Shard& shard) {
  std::vector<RunSpec> out;
  for (const auto& run : runs) {
    if (shard.count <= 1 || run.index % shard.count == shard.index) out.push_back(run);
  }
  return out;
}

}  // namespace sextant
