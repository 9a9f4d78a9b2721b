#include "sextant/experiments/runner.hpp"

#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <optional>
#include <thread>
#include <unordered_set>

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "results_lock.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/log.hpp"
#include "sextant/core/progress.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/threads.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/pipeline/json.hpp"
#include "sextant/pipeline/provenance.hpp"
#include "sextant/pipeline/yaml_json.hpp"

namespace sextant {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// A killed writer may leave a last line without its newline; end it so the next append starts clean.
void terminate_partial_line(const std::filesystem::path& jsonl) {
  std::ifstream in(jsonl, std::ios::binary | std::ios::ate);
  if (!in || in.tellg() <= 0) return;
  in.seekg(-1, std::ios::end);
  char last = 0;
  in.get(last);
  if (last != '\n') append_line_durably(jsonl, "");
}

struct ProvenanceInput {
  const ExperimentConfig* config;
  const RunnerOptions* options;
  const RunnerSummary* summary;
  std::string start, end;
  int threads;
};

std::string provenance_json(const ProvenanceInput& p) {
  const GitState git = current_git_state();
  const auto& s = *p.summary;
  const Json provenance = {
      {"experiment", p.config->name},
      {"kind", p.config->kind},
      {"config_file", p.config->file},
      {"profile", p.options->quick ? "quick" : "full"},
      {"seed", std::to_string(p.config->seed)},
      {"git", {{"sha", git.sha}, {"dirty", git.dirty}, {"source", git.source}}},
      {"libraries", Json::parse(library_versions_json())},
      {"host", host_name()},
      {"threads", p.threads},
      {"hardware_threads", std::thread::hardware_concurrency()},
      {"shard", std::to_string(p.options->shard.index + 1) + "/" + std::to_string(p.options->shard.count)},
      {"start", p.start},
      {"end", p.end.empty() ? Json() : Json(p.end)},
      {"runs",
       {{"total", s.total},
        {"in_shard", s.in_shard},
        {"skipped", s.skipped},
        {"executed", s.executed},
        {"failed", s.failed}}},
      {"resolved_config", yaml_to_json(p.config->effective)}};
  return json_lines(provenance, {"resolved_config"});
}

struct Loaded {
  ExperimentConfig config;
  std::vector<RunSpec> runs;  ///< the whole expansion
  std::vector<RunSpec> mine;  ///< this shard's runs
};

Loaded load_and_expand(const std::filesystem::path& config_file, const RunnerOptions& options) {
  std::string why;
  if (!options.valid(&why)) throw InputError("options", "", why);
  Loaded out{read_experiment_config(config_file, options.quick), {}, {}};
  const ExperimentConfig& config = out.config;
  if (!run_kind_registry().contains(config.kind)) {
    throw InputError(config.file, at_line(yaml_line(config.effective["kind"])),
                     "key 'kind': " + run_kind_registry().unknown(config.kind));
  }
  run_kind_registry().create(config.kind)->validate(config);
  out.runs = expand_runs(config);
  out.mine = select_shard(out.runs, options.shard);
  return out;
}

/// Keys of the successful rows of runs.jsonl: what resume skips (a failed row is retried).
std::unordered_set<std::string> finished_keys(const RowFile& existing) {
  std::unordered_set<std::string> finished;
  for (const auto& row : existing.rows) {
    if (row.ok) finished.insert(row.key);
  }
  return finished;
}

}  // namespace

bool RunnerOptions::valid(std::string* why) const {
  const auto fail = [why](const std::string& text) {
    if (why) *why = text;
    return false;
  };
  if (const std::string problem = worker_threads_problem(jobs, "--jobs"); !problem.empty())
    return fail(problem);
  if (shard.count < 1 || shard.index >= shard.count) return fail("--shard must be i/n with 1 ≤ i ≤ n");
  if (results_root.empty()) return fail("the results folder is empty");
  return true;
}

std::string provenance_file_name(const Shard& shard) {
  if (shard.count <= 1) return "provenance.json";
  return "provenance.shard-" + std::to_string(shard.index + 1) + "-of-" + std::to_string(shard.count) +
         ".json";
}

RunnerSummary run_experiment(const std::filesystem::path& config_file, const RunnerOptions& options) {
  const auto start = Clock::now();
  const Loaded loaded = load_and_expand(config_file, options);
  const ExperimentConfig& config = loaded.config;
  const auto kind = run_kind_registry().create(config.kind);
  const std::vector<RunSpec>& runs = loaded.runs;
  const std::vector<RunSpec>& mine = loaded.mine;

  RunnerSummary summary;
  summary.experiment = config.name;
  summary.folder = options.results_root / config.name;
  summary.total = runs.size();
  summary.in_shard = mine.size();
  const auto jsonl = summary.folder / kRunsJsonl;
  const detail::ResultsLock lock(summary.folder);  // one runner per results folder
  terminate_partial_line(jsonl);

  const RowFile existing = read_rows(jsonl);
  const std::unordered_set<std::string> finished = finished_keys(existing);
  summary.warnings = bad_line_messages(jsonl, existing);
  for (const auto& warning : summary.warnings) log_warning(warning);
  std::vector<const RunSpec*> todo;
  for (const auto& run : mine) {
    if (finished.count(run.key)) {
      ++summary.skipped;
    } else if (options.max_runs == 0 || todo.size() < options.max_runs) {
      todo.push_back(&run);
    }
  }

  const int threads =
      options.jobs > 0 ? options.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  ProvenanceInput provenance{&config, &options, &summary, iso_time_now(), "", threads};
  {
    YAML::Emitter emitter;
    emitter << config.effective;
    write_file_atomically(summary.folder / kEffectiveConfig, std::string(emitter.c_str()) + "\n");
  }
  write_file_atomically(summary.folder / provenance_file_name(options.shard), provenance_json(provenance));

  if (!todo.empty()) {
    PrepareContext context;
    context.cache_root = options.cache_root.empty() ? options.results_root / "_cache" : options.cache_root;
    const auto session = kind->prepare(config, context);
    std::optional<Progress> progress;
    if (options.progress) {
      progress.emplace(todo.size(), config.name);
    } else {
      progress.emplace(todo.size(), config.name, nullptr);
    }
    std::atomic<std::size_t> executed{0}, failed{0};
    std::mutex append_mutex;
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, todo.size(), 1),
          [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
              const RunSpec& run = *todo[i];
              RunRow row = row_for(run, config.name);
              const auto run_start = Clock::now();
              try {
                session->run(run, row);
              } catch (const std::exception& e) {
                row.ok = false;
                row.error = e.what();
                ++failed;
              }
              row.seconds = seconds_since(run_start);
              {
                const std::lock_guard<std::mutex> lock(append_mutex);
                append_line_durably(jsonl, to_json_line(row));
              }
              ++executed;
              progress->tick();
            }
          },
          tbb::simple_partitioner());
    });
    progress->finish();
    summary.executed = executed;
    summary.failed = failed;
  }

  write_rows_csv(summary.folder / kRunsCsv, in_expansion_order(read_rows(jsonl).rows, runs));
  summary.seconds = seconds_since(start);
  provenance.end = iso_time_now();
  write_file_atomically(summary.folder / provenance_file_name(options.shard), provenance_json(provenance));
  return summary;
}

RunnerPlan plan_experiment(const std::filesystem::path& config_file, const RunnerOptions& options) {
  const Loaded loaded = load_and_expand(config_file, options);
  RunnerPlan plan;
  plan.experiment = loaded.config.name;
  plan.folder = options.results_root / loaded.config.name;
  plan.total = loaded.runs.size();
  plan.in_shard = loaded.mine.size();
  const std::unordered_set<std::string> finished = finished_keys(read_rows(plan.folder / kRunsJsonl));
  for (const auto& run : loaded.mine) plan.finished += finished.count(run.key);
  return plan;
}

std::vector<RunnerPlan> plan_shards(const std::filesystem::path& config_file, const RunnerOptions& options,
                                    const std::function<std::filesystem::path(const Shard&)>& results_root) {
  const Loaded loaded = load_and_expand(config_file, options);  // read, validated and expanded once
  std::vector<RunnerPlan> plans;
  for (std::size_t k = 0; k < options.shard.count; ++k) {
    const Shard shard{k, options.shard.count};
    RunnerPlan& plan = plans.emplace_back();
    plan.experiment = loaded.config.name;
    plan.folder = results_root(shard) / loaded.config.name;
    plan.total = loaded.runs.size();
    const std::unordered_set<std::string> finished = finished_keys(read_rows(plan.folder / kRunsJsonl));
    for (const auto& run : select_shard(loaded.runs, shard)) {
      ++plan.in_shard;
      plan.finished += finished.count(run.key);
    }
  }
  return plans;
}

}  // namespace sextant
