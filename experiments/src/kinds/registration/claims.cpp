#include "registration/claims.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "kit/dataset_source.hpp"
#include "registration/row_keys.hpp"
#include "sextant/eval/small_sample_intervals.hpp"

namespace sextant {
namespace {

Claim not_comparable(const std::string& statement, const std::string& why) {
  return Claim{statement, Verdict::not_comparable, why};
}

}  // namespace

std::vector<bool> row_successes(const std::vector<const RunRow*>& rows) {
  std::vector<bool> v;
  v.reserve(rows.size());
  for (const RunRow* r : rows) v.push_back(r->value(keys::kSuccess) > 0.5);
  return v;
}

std::uint64_t claim_seed(const ExperimentConfig& config, std::uint64_t k) {
  return config.seed * 1000003ULL + 7919ULL * (k + 1);
}

Claim claim_more_successes(const std::string& statement, const MethodRows* a, const MethodRows* b) {
  if (!a || !b) return not_comparable(statement, "a method has no runs");
  const PairedRows p = pair_up(*a, *b);
  const PairedRates r = compare_paired_successes(row_successes(p.a), row_successes(p.b));
  return Claim{
      statement, verdict_greater(r.difference, 0.0),
      a->name + " vs " + b->name + ": " + describe(r) + " (paired, n = " + std::to_string(r.n) + ")"};
}

Claim claim_not_fewer_successes(const std::string& statement, const MethodRows* a, const MethodRows* b,
                                double margin) {
  if (!a || !b) return not_comparable(statement, "a method has no runs");
  const PairedRows p = pair_up(*a, *b);
  const PairedRates r = compare_paired_successes(row_successes(p.a), row_successes(p.b));
  return Claim{statement, verdict_greater(r.difference, -margin),
               a->name + " vs " + b->name + ": " + describe(r) + " (paired, n = " + std::to_string(r.n) +
                   "); needs > −" + format_number(margin, 2)};
}

Claim claim_similar_successes(const std::string& statement, const MethodRows* a, const MethodRows* b,
                              double margin) {
  if (!a || !b) return not_comparable(statement, "a method has no runs");
  const PairedRows p = pair_up(*a, *b);
  const PairedRates r = compare_paired_successes(row_successes(p.a), row_successes(p.b));
  return Claim{statement, verdict_in_band(r.difference, -margin, margin),
               a->name + " vs " + b->name + ": " + describe(r) + "; band ±" + format_number(margin, 2)};
}

Claim claim_speedup(const std::string& statement, const MethodRows* slow, const MethodRows* fast, double lo,
                    double hi, std::uint64_t seed, const char* time_key) {
  (void)seed;  // the interval is exact: no resampling
  if (!slow || !fast) return not_comparable(statement, "a method has no runs");
  // Paired: each pair registered by both methods is one observation (its time ratio).
  const PairedRows p = pair_up(*slow, *fast);
  const Interval ratio = paired_ratio_interval(row_values(p.a, time_key), row_values(p.b, time_key));
  const Verdict v = std::isfinite(hi) ? verdict_in_band(ratio, lo, hi) : verdict_greater(ratio, lo);
  const std::string band = std::isfinite(hi)
                               ? "band [" + format_number(lo, 1) + ", " + format_number(hi, 1) + "]"
                               : "needs > " + format_number(lo, 1);
  return Claim{statement, v,
               std::string("median per-pair ") +
                   (time_key == std::string(keys::kSecondsAlign) ? "matching " : "") + "time ratio " +
                   slow->name + " / " + fast->name + " = " + describe(ratio, "×") + "; " + band};
}

Claim claim_smaller_on_solved(const std::string& statement, const MethodRows* a, const MethodRows* b,
                              const std::string& key, const std::string& unit, std::uint64_t seed) {
  if (!a || !b) return not_comparable(statement, "a method has no runs");
  const PairedRows p = pair_up(*a, *b);
  std::vector<double> va, vb;
  for (std::size_t i = 0; i < p.a.size(); ++i) {
    if (p.a[i]->value(keys::kSuccess) > 0.5 && p.b[i]->value(keys::kSuccess) > 0.5) {
      va.push_back(p.a[i]->value(key));
      vb.push_back(p.b[i]->value(key));
    }
  }
  const Interval d = bootstrap_paired_mean_difference(va, vb, seed);
  return Claim{
      statement, verdict_less(d, 0.0),
      "mean " + key + " of " + a->name + " − " + b->name + " on the pairs both solved: " + describe(d, unit)};
}

double trimmed_mean(std::vector<double> values, double trim) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
               values.end());
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const auto cut = static_cast<std::size_t>(std::floor(trim * static_cast<double>(values.size())));
  if (2 * cut >= values.size()) return NAN;
  double sum = 0;
  for (std::size_t k = cut; k + cut < values.size(); ++k) sum += values[k];
  return sum / static_cast<double>(values.size() - 2 * cut);
}

Interval bootstrap_trimmed_mean(const std::vector<double>& values, double trim, std::uint64_t seed) {
  std::vector<double> v;
  for (const double x : values)
    if (std::isfinite(x)) v.push_back(x);
  if (v.size() < 2) return Interval{NAN, NAN, NAN, 0.95, v.size()};
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::size_t> pick(0, v.size() - 1);
  std::vector<double> draws, sample(v.size());
  for (int b = 0; b < 2000; ++b) {
    for (double& x : sample) x = v[pick(rng)];
    draws.push_back(trimmed_mean(sample, trim));
  }
  return percentile_interval(trimmed_mean(v, trim), draws, 0.95, v.size());
}

Claim claim_beats_guess(const MethodRows* m, const std::string& guess_name, std::uint64_t seed) {
  const std::string statement =
      (m ? m->name : std::string("method")) + " improves on the " + guess_name + " guess (translation error)";
  if (!m) return Claim{statement, Verdict::not_comparable, "no runs", ClaimKind::sanity};
  // The median of the paired differences: a few diverged registrations (metres off) must not hide
  // what the typical pair does.
  std::vector<double> difference;
  for (const RunRow* r : m->rows)
    difference.push_back(r->value(keys::kTranslationCm) - r->value(keys::kInitialTranslationCm));
  const Interval d = bootstrap_median(difference, seed);
  return Claim{statement, verdict_less(d, 0.0),
               "median of (error − guess error) per pair: " + describe(d, " cm"), ClaimKind::sanity};
}

std::string profile_note(const ExperimentConfig& config, const std::vector<MethodRows>& methods) {
  std::size_t lo = std::numeric_limits<std::size_t>::max(), hi = 0;
  for (const auto& m : methods) {
    lo = std::min(lo, m.rows.size());
    hi = std::max(hi, m.rows.size());
  }
  if (methods.empty()) lo = 0;
  const std::string n = lo == hi ? std::to_string(hi) : std::to_string(lo) + "–" + std::to_string(hi);
  return "Profile: " + std::string(config.quick ? "quick" : "full") + " (n = " + n + " runs per method)." +
         dataset_note(config);
}

std::string dataset_note(const ExperimentConfig& config) {
  if (config.dataset.source != DatasetSource::kFolder) return "";
  std::string note =
      " Dataset: the scans of " + config.dataset.path.filename().string() + " (a folder, not the campus)";
  if (config.dataset.simulates_odometry()) {
    const std::string model = simulated_odometry_settings(config).model;
    note += "; its odometry guess is simulated from the folder's reference with the campus' '" + model +
            "' error model (seed " + std::to_string(config.dataset.seed) + "), not measured";
  }
  return note + ".";
}

}  // namespace sextant
