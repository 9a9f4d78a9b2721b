#pragma once
// A run kind executes the runs of one family of experiments and lays out its report. One folder
// per kind under src/kinds/<family>/ (what families share in src/kinds/kit/), registered by name
// in run_kind_registry(). Which experiments use which kind and layout is in their YAML configs
// (`kind:`, `params.report`), not in comments here.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "sextant/core/registry.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/experiments/run_row.hpp"

namespace sextant {

struct PrepareContext {
  std::filesystem::path cache_root;  ///< where generated datasets are cached
  bool verbose = false;
};

/// Shared, read-only state of one experiment's runs (a loaded dataset, parsed methods).
class KindSession {
 public:
  virtual ~KindSession() = default;
  /// Executes one run; called concurrently from several threads. Fills row.values / row.series.
  virtual void run(const RunSpec& run, RunRow& row) const = 0;
};

class RunKind {
 public:
  virtual ~RunKind() = default;
  virtual std::string name() const = 0;
  /// Checks methods, params, metrics and reference before anything runs (InputError: file, line, key).
  virtual void validate(const ExperimentConfig& config) const = 0;
  /// Shapes the plan: one flag per run of `expansion` (expand_sweep, in its order), true = the run
  /// is planned. Default: every run. For a method whose one run covers several sweep points (it
  /// loops over them itself), so that the plan holds no run that would do nothing. A kind can only
  /// leave runs out, never add or alter one: the kept runs have the keys, seeds and rows they have
  /// unshaped. Called wherever runs are listed (expand_runs), also on configs not yet validated:
  /// keep it cheap, and throw only what validate() would.
  virtual std::vector<bool> planned_runs(const ExperimentConfig& config,
                                         const std::vector<RunSpec>& expansion) const {
    (void)config;
    return std::vector<bool>(expansion.size(), true);
  }
  /// Loads what the runs share. Called once, only when some run has to execute.
  virtual std::unique_ptr<KindSession> prepare(const ExperimentConfig& config,
                                               const PrepareContext& context) const = 0;
  /// The report section from the rows of the current expansion (in expansion order; some may be missing).
  virtual ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                               const std::vector<const RunRow*>& rows) const = 0;
};

using RunKindRegistry = Registry<RunKind>;
/// All run kinds, filled on first use.
const RunKindRegistry& run_kind_registry();

}  // namespace sextant
