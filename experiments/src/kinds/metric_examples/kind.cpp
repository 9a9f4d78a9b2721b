// E18 (§6.3, tables 6.1–6.2): the Wulf (eqs. 6.1–6.3) and Kümmerle (eq. 6.6) metrics on the
// thesis' worked 1D and 2D examples. Exact and deterministic: no dataset, no randomness.
//
//   methods: [{name: wulf, metric: wulf}, {name: kummerle, metric: kummerle}]
//   sweep:   {example: [1d_case1, ...]}
//   params:  {examples: {1d_case1: {table: "6.1", truth: [[0], [4], ...], estimate: [[0], [1], ...]}}}
//   reference: {tolerance: 0.005, wulf: {1d_case1: 1.5, ...}, kummerle: {...}}
#include <algorithm>
#include <cmath>
#include <map>

#include "kit/number_format.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/experiments/run_kind.hpp"

namespace sextant {
namespace {

struct Example {
  std::string table;  ///< "6.1" or "6.2"
  PoseList truth, estimate;
};

PoseList read_positions(const YAML::Node& node, SettingsReader& in, const std::string& key) {
  std::vector<std::vector<double>> rows;
  in.require(key, rows);
  PoseList poses;
  for (const auto& r : rows) {
    if (r.empty() || r.size() > 3) in.fail(key, "key '" + key + "': each position has 1 to 3 coordinates");
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    for (std::size_t k = 0; k < r.size(); ++k) T.translation()[static_cast<Eigen::Index>(k)] = r[k];
    poses.push_back(T);
  }
  (void)node;
  return poses;
}

std::map<std::string, Example> read_examples(const ExperimentConfig& config) {
  SettingsReader params(config.params, config.file);
  const YAML::Node node = params.child("examples");
  params.finish();
  if (!node.IsMap() || node.size() == 0)
    params.fail("examples", "key 'examples' must be a map name → {truth, estimate}");
  std::map<std::string, Example> examples;
  for (const auto& entry : node) {
    SettingsReader in(entry.second, config.file);
    Example e;
    in.read("table", e.table);
    e.truth = read_positions(entry.second, in, "truth");
    e.estimate = read_positions(entry.second, in, "estimate");
    in.finish();
    if (e.truth.size() != e.estimate.size() || e.truth.size() < 2)
      in.fail("estimate", "key 'estimate': needs as many positions as 'truth' (at least 2)");
    examples[entry.first.as<std::string>()] = e;
  }
  return examples;
}

std::string metric_of(const YAML::Node& method, const std::string& file) {
  SettingsReader in(method, file);
  std::string name, metric;
  in.require("name", name);
  in.require("metric", metric);
  in.finish();
  if (metric != "wulf" && metric != "kummerle")
    in.fail("metric", "key 'metric': '" + metric + "' is not wulf or kummerle");
  return metric;
}

/// Figures 6.1 and 6.2: the true and estimated positions of each example, one plot per table.
/// 1D examples are drawn as position against step; 2D examples in the plane.
std::vector<ReportFigure> example_figures(const std::map<std::string, Example>& examples,
                                          const std::vector<YAML::Node>& order) {
  std::map<std::string, XYPlot> plots;
  std::map<std::string, bool> truth_drawn;
  for (const auto& value : order) {
    const std::string name = value.Scalar();
    const Example& e = examples.at(name);
    const std::string table = e.table.empty() ? "6.x" : e.table;
    const bool planar = std::any_of(e.truth.begin(), e.truth.end(),
                                    [](const Eigen::Isometry3d& T) { return T.translation().y() != 0.0; });
    XYPlot& plot = plots[table];
    plot.title = "Examples of table " + table + ": truth and estimates";
    plot.x_label = planar ? "x" : "step";
    plot.y_label = planar ? "y" : "position";
    const auto series_of = [planar](const PoseList& poses) {
      std::vector<double> x, y;
      for (std::size_t i = 0; i < poses.size(); ++i) {
        x.push_back(planar ? poses[i].translation().x() : static_cast<double>(i));
        y.push_back(planar ? poses[i].translation().y() : poses[i].translation().x());
      }
      return std::make_pair(x, y);
    };
    if (!truth_drawn[table]) {
      auto [x, y] = series_of(e.truth);
      plot.series.push_back({"truth", x, y, PlotSeries::Style::line_and_markers, "#000000"});
      truth_drawn[table] = true;
    }
    auto [x, y] = series_of(e.estimate);
    plot.series.push_back({name, x, y, PlotSeries::Style::line_and_markers, ""});
  }
  std::vector<ReportFigure> figures;
  for (const auto& [table, plot] : plots) {
    const std::string id = "examples_table_" + table.substr(0, 1) + "_" + table.substr(table.find('.') + 1);
    figures.push_back({id, "Figure for table " + table + ": the true and estimated positions of each example",
                       render_svg(plot)});
  }
  return figures;
}

class MetricExamplesSession : public KindSession {
 public:
  MetricExamplesSession(std::map<std::string, Example> examples, std::vector<std::string> metrics)
      : examples_(std::move(examples)), metrics_(std::move(metrics)) {}

  void run(const RunSpec& run, RunRow& row) const override {
    const Example& e = examples_.at(run.point.at("example"));
    if (metrics_.at(run.method_index) == "wulf") {
      const WulfResult r = wulf_metric(e.estimate, e.truth);  // eqs. (6.1)–(6.3)
      if (!r.status.ok) throw std::runtime_error(r.status.message);
      row.values["translation"] = r.position_rms;
      row.values["rotation"] = r.orientation_rms;
    } else {
      const KummerleResult r = kummerle_metric(e.estimate, e.truth);  // eq. (6.6)
      if (!r.status.ok) throw std::runtime_error(r.status.message);
      row.values["translation"] = r.translation_rms;
      row.values["rotation"] = r.rotation_rms;
    }
  }

 private:
  std::map<std::string, Example> examples_;
  std::vector<std::string> metrics_;
};

double reference_value(const YAML::Node& reference, const std::string& metric, const std::string& example) {
  if (!reference.IsMap() || !reference[metric].IsMap() || !reference[metric][example].IsDefined())
    return std::numeric_limits<double>::quiet_NaN();
  return reference[metric][example].as<double>();
}

class MetricExamplesKind : public RunKind {
 public:
  std::string name() const override { return "metric_examples"; }

  void validate(const ExperimentConfig& config) const override {
    const auto examples = read_examples(config);
    for (const auto& m : config.methods) metric_of(m.node, config.file);
    if (config.sweep.size() != 1 || config.sweep[0].name != "example")
      throw InputError(config.file, "", "key 'sweep': metric_examples needs exactly one axis 'example'");
    for (const auto& v : config.sweep[0].values) {
      if (!v.IsScalar() || !examples.count(v.Scalar()))
        throw InputError(config.file, at_line(yaml_line(v)),
                         "key 'example': no example named '" + YAML::Dump(v) + "' in params.examples");
    }
    SettingsReader ref(config.reference, config.file);
    double tolerance = 0;
    ref.read("tolerance", tolerance);
    for (const char* metric : {"wulf", "kummerle"}) {
      std::map<std::string, double> values;
      ref.read(metric, values);
    }
    ref.finish();
  }

  std::unique_ptr<KindSession> prepare(const ExperimentConfig& config, const PrepareContext&) const override {
    std::vector<std::string> metrics;
    for (const auto& m : config.methods) metrics.push_back(metric_of(m.node, config.file));
    return std::make_unique<MetricExamplesSession>(read_examples(config), metrics);
  }

  ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                       const std::vector<const RunRow*>& rows) const override {
    const auto examples = read_examples(config);
    const double tolerance = config.reference["tolerance"].as<double>(0.005);
    // ours[metric][example]
    std::map<std::string, std::map<std::string, double>> ours;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (rows[i])
        ours[metric_of(config.methods[runs[i].method_index].node, config.file)][runs[i].point.at("example")] =
            rows[i]->value("translation");
    }
    ReportSection section;
    section.notes = "Exact values of the thesis' worked examples; positions in the thesis' units.";
    std::map<std::string, Table> tables;
    std::size_t compared = 0, agree = 0;
    std::string disagreements;
    for (const auto& example_value : config.sweep[0].values) {
      const std::string example = example_value.Scalar();
      const std::string table_name = examples.at(example).table.empty() ? "6.x" : examples.at(example).table;
      auto [it, fresh] = tables.try_emplace(table_name);
      Table& t = it->second;
      if (fresh) {
        t.caption =
            "Table " + table_name + ": Wulf and Kümmerle metrics on the thesis' examples (ours | thesis)";
        t.label = "table_" + table_name.substr(0, 1) + "_" + table_name.substr(table_name.find('.') + 1);
        t.add_column("example").add_compared_column("σ Wulf", 2).add_compared_column("σ Kümmerle", 2);
      }
      std::vector<Cell> cells{Cell::text(example)};
      for (const char* metric : {"wulf", "kummerle"}) {
        const auto found = ours[metric].find(example);
        const double value =
            found == ours[metric].end() ? std::numeric_limits<double>::quiet_NaN() : found->second;
        const double thesis = reference_value(config.reference, metric, example);
        cells.push_back(std::isfinite(value) ? Cell::number(value) : Cell::missing());
        cells.push_back(std::isfinite(thesis) ? Cell::number(thesis) : Cell::missing());
        if (std::isfinite(value) && std::isfinite(thesis)) {
          ++compared;
          if (std::abs(value - thesis) <= tolerance) {
            ++agree;
          } else {
            disagreements += " " + std::string(metric) + " " + example;
          }
        }
      }
      t.add_row(std::move(cells));
    }
    for (auto& [name, t] : tables) section.tables.push_back(t);
    section.figures = example_figures(examples, config.sweep[0].values);

    Claim exact{
        "Our Wulf and Kümmerle values equal the thesis' tables 6.1 and 6.2 (to the printed precision)",
        compared == 0 ? Verdict::not_comparable
                      : (agree == compared ? Verdict::holds : Verdict::does_not_hold),
        std::to_string(agree) + " of " + std::to_string(compared) + " values within ±" +
            format_number(tolerance, 3) + (disagreements.empty() ? "" : "; differ:" + disagreements)};
    section.claims.push_back(exact);

    const auto get = [&](const char* metric, const char* example) {
      const auto found = ours[metric].find(example);
      return found == ours[metric].end() ? std::numeric_limits<double>::quiet_NaN() : found->second;
    };
    const double w2 = get("wulf", "1d_case2"), w3 = get("wulf", "1d_case3");
    const double k2 = get("kummerle", "1d_case2"), k3 = get("kummerle", "1d_case3");
    Claim inconsistent{
        "1D: the same 1-unit error in the second or the third motion gives Wulf equal values but "
        "Kümmerle different ones (\"inconsistent result\")",
        Verdict::not_comparable, ""};
    if (std::isfinite(w2 + w3 + k2 + k3)) {
      inconsistent.verdict =
          std::abs(w2 - w3) < 1e-9 && std::abs(k2 - k3) > 1e-3 ? Verdict::holds : Verdict::does_not_hold;
      inconsistent.evidence = "Wulf " + format_number(w2) + " vs " + format_number(w3) + ", Kümmerle " +
                              format_number(k2) + " vs " + format_number(k3);
    }
    section.claims.push_back(inconsistent);

    const double w21 = get("wulf", "2d_case1"), w22 = get("wulf", "2d_case2");
    const double k21 = get("kummerle", "2d_case1"), k22 = get("kummerle", "2d_case2");
    Claim larger{"2D: the Kümmerle metric gives larger values than the Wulf metric in both cases",
                 Verdict::not_comparable, ""};
    if (std::isfinite(w21 + w22 + k21 + k22)) {
      larger.verdict = k21 > w21 && k22 > w22 ? Verdict::holds : Verdict::does_not_hold;
      larger.evidence = "case 1: " + format_number(k21) + " > " + format_number(w21) +
                        "; case 2: " + format_number(k22) + " > " + format_number(w22);
    }
    section.claims.push_back(larger);
    return section;
  }
};

}  // namespace

std::unique_ptr<RunKind> make_metric_examples_kind() {
  return std::make_unique<MetricExamplesKind>();
}

}  // namespace sextant
