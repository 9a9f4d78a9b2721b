// `selftest`: a run kind that exercises the runner itself (sharding, resume after a kill, merge)
// without any dataset: each run sleeps `params.sleep_ms` and records values derived from its seed.
#include <chrono>
#include <thread>

#include "sextant/core/settings_reader.hpp"
#include "sextant/experiments/run_kind.hpp"

namespace sextant {
namespace {

int sleep_ms_of(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  int sleep_ms = 0;
  in.read("sleep_ms", sleep_ms);
  in.finish();
  if (sleep_ms < 0 || sleep_ms > 60000) in.fail("sleep_ms", "key 'sleep_ms' must be in [0, 60000]");
  return sleep_ms;
}

class SelftestSession : public KindSession {
 public:
  explicit SelftestSession(int sleep_ms) : sleep_ms_(sleep_ms) {}
  void run(const RunSpec& run, RunRow& row) const override {
    std::this_thread::sleep_for(std::chrono::milliseconds(sleep_ms_));
    row.values["uniform"] = static_cast<double>(run.seed % 1000003) / 1000003.0;
    row.values["index"] = static_cast<double>(run.index);
  }

 private:
  int sleep_ms_;
};

class SelftestKind : public RunKind {
 public:
  std::string name() const override { return "selftest"; }
  void validate(const ExperimentConfig& config) const override {
    sleep_ms_of(config);
    for (const auto& m : config.methods) {
      SettingsReader in(m.node, config.file);
      std::string name;
      in.require("name", name);
      in.finish();
    }
  }
  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    return std::make_unique<SelftestSession>(sleep_ms_of(config));
  }
  ReportSection report(const ExperimentConfig&, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    ReportSection section;
    Table t;
    t.caption = "Runner self-test: runs per method";
    t.label = "runs_per_method";
    t.add_column("method").add_number_column("runs found", 0).add_number_column("mean uniform", 3);
    std::map<std::string, std::pair<double, double>> per_method;  // count, sum
    for (std::size_t i = 0; i < runs.size(); ++i) {
      auto& [count, sum] = per_method[runs[i].method];
      if (rows[i]) {
        count += 1;
        sum += rows[i]->value("uniform");
      }
    }
    for (const auto& [method, cs] : per_method)
      t.add_row({Cell::text(method), Cell::number(cs.first),
                 Cell::number(cs.first > 0 ? cs.second / cs.first : 0.0)});
    section.tables.push_back(t);
    return section;
  }
};

}  // namespace

std::unique_ptr<RunKind> make_selftest_kind() {
  return std::make_unique<SelftestKind>();
}

}  // namespace sextant
