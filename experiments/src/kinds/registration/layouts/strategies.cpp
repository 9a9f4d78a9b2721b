// Layout (§5.1.2.2, table 5.9, figs 5.13–5.14): ML-NDT with regular, random, grid-based (GBS)
// and feature-based (FBS) sampling from the odometry guess. Table 5.9 (iterations, matched points,
// time, success), the sampling costs (feature extraction vs GBS), mean errors per parameter,
// FbML-NDT's error per pair, and a computed test of "FbML-NDT's errors look zero-mean Gaussian,
// odometry's do not" (mean against its standard error, Jarque–Bera). Methods are found by sampler.
//
//   reference:
//     table_5_9: {regular: [17.27, 12.17, 44.70, 97], ...}   # iterations, matched %, time s, success %
//     sampling_seconds: {fbs: 1.0, gbs: 0.1}
//     mean_error_below: {translation_cm: 2, rotation_deg: 0.3}  # GBS and FBS
#include <cmath>

#include "kit/row_keys.hpp"
#include "registration/claims.hpp"
#include "registration/deviations.hpp"
#include "registration/figures.hpp"
#include "registration/report.hpp"
#include "registration/row_keys.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/eval/statistics.hpp"
#include "strategies_causes.hpp"

namespace sextant {
namespace {

/// Non-inferiority margin of FBS's success rate against the other samplers (table 5.9).
constexpr double kSuccessMargin = 0.05;
/// Share trimmed from each end for fig. 5.14's mean-error claim.
constexpr double kTrim = 0.1;

/// Mean and standard error of each parameter, and Jarque–Bera: "zero-mean Gaussian" is rejected
/// for a parameter when the mean lies outside ±1.96 · SE or JB's p < 0.05.
struct Normality {
  std::array<SampleStats, 6> stats;
  std::array<NormalityTest, 6> jb;
  bool rejected(std::size_t k) const {
    const double se =
        stats[k].count > 1 ? stats[k].std / std::sqrt(static_cast<double>(stats[k].count)) : NAN;
    return !(std::abs(stats[k].mean) <= 1.96 * se) || jb[k].p_value < 0.05;
  }
};

Normality normality(const std::vector<RegistrationError>& errors) {
  Normality n;
  for (std::size_t k = 0; k < 6; ++k) {
    std::vector<double> v;
    for (const auto& e : errors) v.push_back(e.parameters[k]);
    n.stats[k] = summarize(v);
    n.jb[k] = jarque_bera(v);
  }
  return n;
}

std::string normality_evidence(const Normality& n) {
  std::string out;
  for (std::size_t k = 0; k < 6; ++k) {
    const double se =
        n.stats[k].count > 1 ? n.stats[k].std / std::sqrt(static_cast<double>(n.stats[k].count)) : NAN;
    out += parameter_names()[k] + ": mean " + format_number(n.stats[k].mean, 2) + " ± " +
           format_number(se, 2) + " (SE), JB " + format_number(n.jb[k].statistic, 1) + " p " +
           format_number(n.jb[k].p_value, 3) + (n.rejected(k) ? " ✗" : " ✓") + "; ";
  }
  return out + "n = " + std::to_string(n.stats[0].count);
}

}  // namespace

ReportSection strategies_report(const ExperimentConfig& config, const RegistrationParams& params,
                                const std::vector<RunSpec>& runs, const std::vector<const RunRow*>& rows) {
  const RegistrationStatsSettings settings = stats_settings(params);
  const std::vector<MethodRows> grouped = group_by_method(config, runs, rows);
  std::vector<std::string> samplers;
  std::vector<RegistrationStats> stats;
  for (std::size_t m = 0; m < grouped.size(); ++m) {
    samplers.push_back(read_registration_method(config.methods[m].node, config.file).sampler.name());
    std::vector<RegistrationSample> samples;
    for (const RunRow* r : grouped[m].rows) samples.push_back(sample_of(*r));
    stats.push_back(registration_stats(samples, settings));
  }
  const auto by_sampler = [&](const std::string& s) -> std::size_t {
    for (std::size_t m = 0; m < grouped.size(); ++m) {
      if (samplers[m] == s && !grouped[m].rows.empty()) return m;
    }
    return grouped.size();
  };
  const auto runs_of = [&](const std::string& s) {
    const std::size_t m = by_sampler(s);
    return m < grouped.size() ? &grouped[m] : nullptr;
  };

  ReportSection section;
  section.notes =
      profile_note(config, grouped) +
      " Consecutive pairs from the odometry guess; success = " + params.success +
      ". Matched points are counted against the whole input scan (kept share × matched share of the "
      "sample), as the thesis' percentages. Time = the matching (alignment) alone, as table 5.9's, whose "
      "text adds the sampling apart (extraction ≈ 1 s, GBS ≈ 0.1 s); total = sampling + reference model + "
      "alignment; the sampling column alone is the cost of feature extraction (FBS) or of the grid (GBS).\n" +
      deviations_note(config);

  // Table 5.9.
  const YAML::Node t59 = child_or_null(config.reference, "table_5_9");
  Table table;
  table.caption = "Table 5.9: sampling strategies for ML-NDT (ours | thesis)";
  table.label = "table_5_9";
  table.add_column("method")
      .add_column("sampler")
      .add_compared_column("iterations", 2)
      .add_compared_column("matched %", 2)
      .add_compared_column("time s", 3)
      .add_compared_column("success %", 0);
  table.add_number_column("sampling s", 4).add_number_column("total s", 4).add_number_column("pairs", 0);
  for (std::size_t m = 0; m < grouped.size(); ++m) {
    const YAML::Node ref = child_or_null(t59, samplers[m]);
    const auto thesis = [&](std::size_t k) {
      return ref.IsSequence() && ref.size() == 4 ? Cell::number(ref[k].as<double>()) : Cell::missing();
    };
    std::vector<double> matched;
    for (const RunRow* r : grouped[m].rows)
      matched.push_back(r->value(keys::kKeptFraction) * r->value(keys::kMatchedPercent));
    const SampleStats mt = summarize(matched),
                      sampling = summarize(row_values(grouped[m].rows, keys::kSecondsSampling)),
                      align = summarize(row_values(grouped[m].rows, keys::kSecondsAlign));
    const bool any = stats[m].count > 0;
    table.add_row({Cell::text(grouped[m].name), Cell::text(samplers[m]),
                   number_or_missing(any ? stats[m].iterations.mean : NAN), thesis(0),
                   number_or_missing(mt.count ? mt.mean : NAN), thesis(1),
                   number_or_missing(align.count ? align.mean : NAN), thesis(2),
                   number_or_missing(any ? 100.0 * stats[m].success_rate : NAN), thesis(3),
                   number_or_missing(sampling.count ? sampling.mean : NAN),
                   number_or_missing(any ? stats[m].seconds.mean : NAN),
                   Cell::number(static_cast<double>(stats[m].count))});
  }
  section.tables.push_back(table);

  // Mean errors per parameter (fig. 5.14), with the odometry, and the normality test.
  std::vector<RegistrationError> odometry;
  if (!grouped.empty()) {
    std::vector<RegistrationSample> samples;
    for (const RunRow* r : grouped.front().rows) {
      if (auto s = odometry_sample_of(*r)) samples.push_back(*s);
    }
    odometry = registration_stats(samples, settings).errors;
  }
  std::vector<std::string> names{"odometry"};
  std::vector<std::array<double, 6>> means{mean_parameters(odometry)};
  for (std::size_t m = 0; m < grouped.size(); ++m) {
    if (stats[m].count == 0) continue;
    names.push_back(grouped[m].name + " (" + samplers[m] + ")");
    means.push_back(mean_parameters(stats[m].errors));
  }
  Table mean_table;
  mean_table.caption = "Mean error per parameter over all pairs (fig. 5.14)";
  mean_table.label = "mean_errors";
  mean_table.add_column("method");
  for (const auto& p : parameter_names()) mean_table.add_number_column(p, 3);
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::vector<Cell> row{Cell::text(names[i])};
    for (double v : means[i]) row.push_back(number_or_missing(v));
    mean_table.add_row(row);
  }
  section.tables.push_back(mean_table);
  for (const bool translation : {true, false})
    section.figures.push_back(mean_error_figure(
        std::string("fig_5_14_") + (translation ? "translation" : "rotation"),
        std::string("Fig. 5.14") + (translation ? " (a)" : " (b)") + ": mean " +
            (translation ? "translation" : "rotation") +
            " error per parameter, odometry and each sampling strategy",
        std::string("Fig. 5.14 (") + (translation ? "a): mean translation error" : "b): mean rotation error"),
        names, means, translation));

  const std::size_t fbs = by_sampler("fbs");
  if (fbs < grouped.size()) {
    for (const bool translation : {true, false})
      section.figures.push_back(parameter_error_figure(
          std::string("fig_5_13_") + (translation ? "translation" : "rotation"),
          std::string("Fig. 5.13") + (translation ? " (a)" : " (b)") + ": FbML-NDT (" + grouped[fbs].name +
              ") relative " + (translation ? "translation" : "rotation") + " error per pair",
          grouped[fbs].name + (translation ? ": translation error" : ": rotation error"),
          row_values(grouped[fbs].rows, keys::kReferenceScan), stats[fbs].errors, translation, 0.0));
  }

  // Claims.
  std::uint64_t k = 0;
  const MethodRows* f = runs_of("fbs");
  const MethodRows* g = runs_of("gbs");
  std::vector<Claim> fastest, fewer, robust, fastest_total;
  for (const char* other : {"regular", "random", "gbs"}) {
    const MethodRows* o = runs_of(other);
    fastest.push_back(claim_speedup("", o, f, 1.0, INFINITY, claim_seed(config, k++), keys::kSecondsAlign));
    fewer.push_back(claim_smaller_on_solved("", f, o, keys::kIterations, "", claim_seed(config, k++)));
    robust.push_back(claim_not_fewer_successes("", f, o, kSuccessMargin));
  }
  // The measured causes of what does not hold (strategies_causes.hpp), from these rows.
  std::vector<std::vector<RegistrationError>> errors;
  std::vector<std::string> method_names;
  for (std::size_t m = 0; m < stats.size(); ++m) {
    errors.push_back(stats[m].errors);
    method_names.push_back(grouped[m].name);
  }
  const std::string sample_size = sample_size_cause(f, g);
  const auto combine = [&](const std::string& statement, const std::vector<Claim>& parts,
                           const std::string& cause = "") {
    std::vector<Verdict> vs;
    std::string evidence;
    for (const auto& c : parts) {
      vs.push_back(c.verdict);
      evidence += c.evidence + " | ";
    }
    Claim claim{statement, verdict_all(vs), evidence};
    if (claim.verdict == Verdict::does_not_hold) claim.cause = cause;
    section.claims.push_back(claim);
  };
  // Table 5.9: 100 % against 97 / 97 / 99 % on 100 pairs. Tested as "more often", even the
  // thesis' own counts could not hold (3 and 1 discordant pairs: McNemar p = 0.25 and 1), so the
  // claim is what those counts support: FBS is no less robust, within a 5-point margin.
  combine("FBS (FbML-NDT) succeeds at least as often as regular, random and GBS sampling (no more than " +
              format_number(100 * kSuccessMargin, 0) +
              " points fewer; thesis: 100 vs 97 / 97 / 99 %, differences 100 pairs cannot resolve)",
          robust);
  combine("FBS is the fastest strategy, matching time (thesis: 2.51 s vs 44.70 / 43.84 / 7.46 s)", fastest,
          sample_size);
  combine(
      "FBS needs the fewest iterations (thesis: 12.67 vs 17.27 / 17.24 / 14.29), on the pairs both solved",
      fewer);
  combine(
      "GBS is faster than regular and random sampling, matching time (thesis: 7.46 s vs 44.70 / 43.84 s)",
      {claim_speedup("", runs_of("regular"), g, 1.0, INFINITY, claim_seed(config, k++), keys::kSecondsAlign),
       claim_speedup("", runs_of("random"), g, 1.0, INFINITY, claim_seed(config, k++), keys::kSecondsAlign)});
  std::uint64_t total_seed = 300;  // apart from k: the claims after keep their seeds
  for (const char* other : {"regular", "random", "gbs"})
    fastest_total.push_back(
        claim_speedup("", runs_of(other), f, 1.0, INFINITY, claim_seed(config, total_seed++)));
  combine(
      "FBS is the fastest also counting its sampling and the reference model (thesis: 2.51 + ≈ 1 s "
      "vs 44.70 / 43.84 / 7.46 (+ ≈ 0.1) s)",
      fastest_total, sample_size);
  if (f && g) {
    const Interval cost =
        bootstrap_ratio_of_medians(row_values(f->rows, keys::kSecondsSampling),
                                   row_values(g->rows, keys::kSecondsSampling), claim_seed(config, k++));
    section.claims.push_back(
        Claim{"Feature extraction costs ≈ 10× GBS's sampling (thesis: ≈ 1 s vs ≈ 0.1 s; band [3, 30])",
              verdict_in_band(cost, 3.0, 30.0), "median sampling time FBS / GBS = " + describe(cost, "×")});
  }
  const YAML::Node below = child_or_null(config.reference, "mean_error_below");
  const double cm = reference_number(below, "translation_cm").value_or(2.0);
  const double deg = reference_number(below, "rotation_deg").value_or(0.3);
  // Fig. 5.14: "the mean of translation error is less than 2 cm and rotation error is less than
  // 0.3 degree". Our per-pair errors are heavy-tailed (std 16–28 cm against a few cm for the bulk;
  // the thesis' own table 5.3: 17 and 13 cm in tx and tz), so the plain mean's 95 % interval is
  // ±3–5 cm wide on 100 pairs and could never fit inside ±2 cm. The verdict takes the 10 %-trimmed
  // mean (bootstrap interval), whose width the bulk sets; the plain mean stays in the evidence.
  for (const char* s : {"gbs", "fbs"}) {
    const MethodRows* m = runs_of(s);
    Claim c{std::string(s == std::string("gbs") ? "GBS" : "FBS") + ": mean error below " +
                format_number(cm, 1) + " cm and " + format_number(deg, 1) +
                "° per parameter (95 % interval of the " + format_number(100 * kTrim, 0) +
                " %-trimmed signed mean inside ±)",
            Verdict::not_comparable, ""};
    if (m) {
      std::vector<Verdict> vs;
      for (std::size_t p = 0; p < 6; ++p) {
        static const char* const kKeys[6] = {"error_tx",    "error_ty",   "error_tz",
                                             "error_alpha", "error_beta", "error_gamma"};
        const std::vector<double> values = row_values(m->rows, kKeys[p]);
        const Interval trimmed = bootstrap_trimmed_mean(values, kTrim, claim_seed(config, k++));
        const double limit = p < 3 ? cm : deg;
        const std::string unit = p < 3 ? " cm" : "°";
        vs.push_back(verdict_in_band(trimmed, -limit, limit));
        c.evidence += parameter_names()[p] + " " + describe(trimmed, unit) + " (plain mean " +
                      describe(mean_interval(values), unit) + "); ";
      }
      c.verdict = verdict_all(vs);
      if (c.verdict == Verdict::does_not_hold && s == std::string("fbs"))
        c.cause = sample_bias_cause(method_names, errors, fbs);
    }
    section.claims.push_back(c);
  }
  if (fbs < grouped.size() && !odometry.empty()) {
    const Normality fn = normality(stats[fbs].errors), on = normality(odometry);
    bool f_rejected = false, o_rejected = false;
    for (std::size_t p = 0; p < 6; ++p) {
      f_rejected = f_rejected || fn.rejected(p);
      o_rejected = o_rejected || on.rejected(p);
    }
    section.claims.push_back(
        Claim{"FbML-NDT's errors look zero-mean Gaussian (no parameter rejects mean within ±1.96·SE or "
              "Jarque–Bera at 5 %)",
              f_rejected ? Verdict::does_not_hold : Verdict::holds, normality_evidence(fn), ClaimKind::thesis,
              f_rejected ? heavy_tail_cause(method_names, errors, fbs) : ""});
    // A sanity check of the dataset, not a test of the thesis: the campus' odometry is generated with
    // table 5.1's 77 cm mean error, so its errors cannot look zero-mean.
    section.claims.push_back(Claim{
        "The odometry guess's errors are not zero-mean Gaussian (some parameter rejects), as its "
        "error model (table 5.1's biased odometry) makes them",
        o_rejected ? Verdict::holds : Verdict::does_not_hold, normality_evidence(on), ClaimKind::sanity});
  }
  for (const auto& m : grouped) {
    if (!m.rows.empty())
      section.claims.push_back(claim_beats_guess(&m, "odometry", claim_seed(config, 100 + k++)));
  }
  return section;
}

// The check of the layout's `reference:` block (InputError with file, line, key).
namespace strategies_reference {

/// table_5_9: sampler → [iterations, matched %, time s, success %].
void check_strategy_row(const YAML::Node& node, const std::string& file) {
  try {
    if (node.as<std::vector<double>>().size() == 4) return;
  } catch (const YAML::Exception&) {
  }
  throw InputError(file, at_line(yaml_line(node)),
                   "key 'table_5_9': expected sampler: [iterations, matched %, time s, success %]");
}

}  // namespace strategies_reference

void check_strategies_reference(const ExperimentConfig& config) {
  SettingsReader in(config.reference, config.file);
  check_map_of(in.child("table_5_9"), config.file, "table_5_9", strategies_reference::check_strategy_row);
  SettingsReader sampling(in.child("sampling_seconds"), config.file);
  SettingsReader below(in.child("mean_error_below"), config.file);
  double x = 0;
  for (const char* key : {"fbs", "gbs"}) sampling.read(key, x);
  for (const char* key : {"translation_cm", "rotation_deg"}) below.read(key, x);
  sampling.finish();
  below.finish();
  in.finish();
}

}  // namespace sextant
