// Layout (§5.1.1.2 B, tables 5.5–5.7, fig 5.11): NDT and ML-NDT with uniform random sampling
// beside grid-based sampling (GBS). Error statistics over the successful registrations only, as
// the thesis' tables 5.5 and 5.6; success / time / iterations per method; table 5.7 as a 2×2 of
// (sampling × method) with the verdicts "GBS better than random" and "ML-NDT better than NDT".
//
//   reference:
//     methods: {mlndt_random: {table: "5.5", mean: [...], std: [...], max: [...], success_percent: 94}, ...}
//     table_5_7: {random: {ndt: ndt_random, mlndt: mlndt_random}, gbs: {ndt: ndt, mlndt: mlndt}}
#include <cmath>

#include "registration/claims.hpp"
#include "registration/deviations.hpp"
#include "registration/figures.hpp"
#include "registration/report.hpp"
#include "registration/row_keys.hpp"
#include "sextant/core/settings_reader.hpp"

namespace sextant {
namespace {

const char* const kSamplings[2] = {"random", "gbs"};
const char* const kMatchers[2] = {"ndt", "mlndt"};

/// "a is better than b": more successes when the paired test decides; otherwise a smaller
/// translation error on the pairs both solved.
Claim claim_better(const std::string& statement, const MethodRows* a, const MethodRows* b,
                   std::uint64_t seed) {
  const Claim by_success = claim_more_successes(statement, a, b);
  if (by_success.verdict == Verdict::holds || by_success.verdict == Verdict::does_not_hold) return by_success;
  const Claim by_error = claim_smaller_on_solved(statement, a, b, keys::kTranslationCm, " cm", seed);
  return Claim{statement, by_error.verdict,
               by_success.evidence + "; success inconclusive, so by accuracy: " + by_error.evidence};
}

std::string name_at(const YAML::Node& grid, const char* sampling, const char* matcher) {
  const YAML::Node row = child_or_null(grid, sampling);
  const YAML::Node cell = child_or_null(row, matcher);
  return cell.IsScalar() ? cell.as<std::string>() : "";
}

}  // namespace

ReportSection sampling_report(const ExperimentConfig& config, const RegistrationParams& params,
                              const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows) {
  RegistrationStatsSettings settings = stats_settings(params);
  settings.errors_of_successes_only = true;  // tables 5.5 and 5.6
  const std::vector<MethodRows> grouped = group_by_method(config, runs, rows);
  std::vector<RegistrationStats> stats;
  for (const auto& m : grouped) {
    std::vector<RegistrationSample> samples;
    for (const RunRow* r : m.rows) samples.push_back(sample_of(*r));
    stats.push_back(registration_stats(samples, settings));
  }

  ReportSection section;
  section.notes =
      profile_note(config, grouped) +
      " Consecutive pairs from the odometry guess. Error statistics exclude the failed registrations "
      "(as tables 5.5 and 5.6; success = " +
      params.success +
      "); success, time and iterations cover every pair. Random sampling keeps a uniform random "
      "fraction of the input (the same share of points as GBS keeps, so the two compare at equal "
      "cost). Table 5.7's verdicts: more successes on the same pairs (paired test), else a smaller "
      "error on the pairs both solved.\n" +
      deviations_note(config);

  const YAML::Node refs = child_or_null(config.reference, "methods");
  for (std::size_t m = 0; m < grouped.size(); ++m) {
    const YAML::Node ref_node = child_or_null(refs, grouped[m].name);
    const ParameterReference ref = read_parameter_reference(ref_node, config.file);
    std::string id =
        ref_node.IsMap() && ref_node["table"].IsDefined() ? ref_node["table"].as<std::string>() : "";
    std::string label = "errors_" + grouped[m].name;
    if (!id.empty()) {
      label = "table_" + id;
      for (char& c : label) c = c == '.' ? '_' : c;
    }
    section.tables.push_back(registration_error_table(
        stats[m], ref_node.IsMap() ? &ref : nullptr,
        (id.empty() ? std::string("Relative error") : "Table " + id + ": relative error") + " of " +
            grouped[m].name + ", successes only (ours | thesis)",
        label));
  }

  Table summary;
  summary.caption = "Success rate, time and iterations per method (ours | thesis)";
  summary.label = "sampling_summary";
  summary.add_column("method")
      .add_compared_column("success %", 1)
      .add_number_column("time s", 3)
      .add_number_column("iterations", 2)
      .add_number_column("kept %", 1)
      .add_number_column("pairs", 0);
  for (std::size_t m = 0; m < grouped.size(); ++m) {
    double kept = 0;
    for (const RunRow* r : grouped[m].rows) kept += r->value(keys::kKeptFraction);
    const double n = static_cast<double>(grouped[m].rows.size());
    summary.add_row(
        {Cell::text(grouped[m].name), number_or_missing(stats[m].count ? 100.0 * stats[m].success_rate : NAN),
         number_or_missing(reference_number(child_or_null(refs, grouped[m].name), "success_percent")),
         number_or_missing(stats[m].count ? stats[m].seconds.mean : NAN),
         number_or_missing(stats[m].count ? stats[m].iterations.mean : NAN),
         number_or_missing(n > 0 ? 100.0 * kept / n : NAN), Cell::number(n)});
  }
  section.tables.push_back(summary);

  // Table 5.7: sampling × method, success % and median error of the successes.
  const YAML::Node grid = child_or_null(config.reference, "table_5_7");
  Table t57;
  t57.caption =
      "Table 5.7: NDT and ML-NDT by sampling strategy (success % / median translation error of the "
      "successes, cm)";
  t57.label = "table_5_7";
  t57.add_column("sampling").add_column("NDT").add_column("ML-NDT");
  for (const char* sampling : kSamplings) {
    std::vector<Cell> row{Cell::text(sampling)};
    for (const char* matcher : kMatchers) {
      const std::string name = name_at(grid, sampling, matcher);
      std::string text = "–";
      for (std::size_t m = 0; m < grouped.size(); ++m) {
        if (grouped[m].name == name && stats[m].count > 0)
          text = name + ": " + format_number(100.0 * stats[m].success_rate, 0) + " % / " +
                 format_number(stats[m].translation_cm.median, 1) + " cm";
      }
      row.push_back(Cell::text(text));
    }
    t57.add_row(row);
  }
  section.tables.push_back(t57);

  // Fig. 5.11: ML-NDT with random sampling, per parameter against the scan index.
  const std::string ml_random = name_at(grid, "random", "mlndt");
  for (std::size_t m = 0; m < grouped.size(); ++m) {
    if (grouped[m].name != ml_random) continue;
    for (const bool translation : {true, false})
      section.figures.push_back(parameter_error_figure(
          std::string("fig_5_11_") + (translation ? "translation" : "rotation"),
          std::string("Fig. 5.11") + (translation ? " (a)" : " (b)") + ": " + ml_random + " relative " +
              (translation ? "translation" : "rotation") + " error per pair (failures included)",
          ml_random + (translation ? ": translation error" : ": rotation error"),
          row_values(grouped[m].rows, keys::kReferenceScan), stats[m].errors, translation,
          translation && params.success == "translation_50cm" ? 50.0 : 0.0));
  }

  // Claims.
  const auto method = [&](const char* sampling, const char* matcher) {
    return find_method(grouped, name_at(grid, sampling, matcher));
  };
  section.claims.push_back(claim_more_successes(
      "With random sampling ML-NDT succeeds more often than NDT (thesis: ≈ 94 % vs ≈ 64 %)",
      method("random", "mlndt"), method("random", "ndt")));
  section.claims.push_back(claim_smaller_on_solved(
      "With random sampling ML-NDT's translation error is smaller than NDT's (thesis: about half), on the "
      "pairs both "
      "solved",
      method("random", "mlndt"), method("random", "ndt"), keys::kTranslationCm, " cm",
      claim_seed(config, 1)));
  std::uint64_t k = 10;
  for (const char* matcher : kMatchers)
    section.claims.push_back(claim_better(std::string("Table 5.7: GBS is better than random sampling for ") +
                                              (std::string(matcher) == "ndt" ? "NDT" : "ML-NDT"),
                                          method("gbs", matcher), method("random", matcher),
                                          claim_seed(config, k++)));
  for (const char* sampling : kSamplings)
    section.claims.push_back(claim_better(std::string("Table 5.7: ML-NDT is better than NDT with ") +
                                              (std::string(sampling) == "gbs" ? "GBS" : "random sampling"),
                                          method(sampling, "mlndt"), method(sampling, "ndt"),
                                          claim_seed(config, k++)));
  for (const auto& m : grouped) {
    if (!m.rows.empty()) section.claims.push_back(claim_beats_guess(&m, "odometry", claim_seed(config, k++)));
  }
  return section;
}

// The check of the layout's `reference:` block (InputError with file, line, key).
namespace sampling_reference {

/// table_5_7: sampling → {ndt: method name, mlndt: method name}.
void check_sampling_row(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  std::string name;
  in.read("ndt", name);
  in.read("mlndt", name);
  in.finish();
}

}  // namespace sampling_reference

void check_sampling_reference(const ExperimentConfig& config) {
  SettingsReader in(config.reference, config.file);
  check_map_of(in.child("methods"), config.file, "methods", check_accuracy_method);
  check_map_of(in.child("table_5_7"), config.file, "table_5_7", sampling_reference::check_sampling_row);
  in.finish();
}

}  // namespace sextant
