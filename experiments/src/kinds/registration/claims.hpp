#pragma once
// Claims of the registration layouts on the verdict model (eval/verdict.hpp): the runs of each
// method grouped by sweep point (kit/row_groups.hpp: two methods are compared on the same pairs), and the
// claim shapes the thesis makes again and again — more successes (paired McNemar / Newcombe), faster by a
// stated factor (bootstrap ratio of median times within a band), fewer iterations and smaller errors
// (bootstrap paired mean difference on the pairs both methods solved), and the sanity check "beats the
// initial guess". Bootstrap seeds derive from the config seed.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "kit/row_groups.hpp"
#include "registration/report.hpp"
#include "registration/row_keys.hpp"
#include "sextant/eval/verdict.hpp"

namespace sextant {

/// success > 0.5 of each row.
std::vector<bool> row_successes(const std::vector<const RunRow*>& rows);

/// A deterministic bootstrap seed for claim number `k` of an experiment.
std::uint64_t claim_seed(const ExperimentConfig& config, std::uint64_t k);

/// "a succeeds more often than b": Newcombe interval of rate(a) − rate(b) > 0.
Claim claim_more_successes(const std::string& statement, const MethodRows* a, const MethodRows* b);
/// "a succeeds at least as often as b": non-inferiority, the Newcombe interval of rate(a) − rate(b)
/// above −margin (does not hold when it lies wholly below). For thesis differences of a few points
/// that no test on ~100 pairs can resolve as "more often".
Claim claim_not_fewer_successes(const std::string& statement, const MethodRows* a, const MethodRows* b,
                                double margin);
/// "a's success rate is about b's": the difference within ±margin.
Claim claim_similar_successes(const std::string& statement, const MethodRows* a, const MethodRows* b,
                              double margin);
/// "fast is `band` times faster than slow": the median over the pairs both registered of
/// slow time / fast time ∈ [lo, hi] (lo only, hi = ∞, for "faster" without a magnitude), with the
/// exact order-statistic interval (paired_ratio_interval). `time_key`: the row's time compared
/// (default the whole registration: sampling + reference model + alignment).
Claim claim_speedup(const std::string& statement, const MethodRows* slow, const MethodRows* fast, double lo,
                    double hi, std::uint64_t seed, const char* time_key = keys::kSecondsRegistration);
/// "a needs fewer / a is more accurate": paired mean of a − b of `key` < 0 on the pairs both solved.
Claim claim_smaller_on_solved(const std::string& statement, const MethodRows* a, const MethodRows* b,
                              const std::string& key, const std::string& unit, std::uint64_t seed);
/// Mean of the finite values after dropping the lowest and highest ⌊trim · n⌋ (NaN when none remain).
double trimmed_mean(std::vector<double> values, double trim);
/// Percentile bootstrap (2000 resamples, 95 %) of the trimmed mean of the finite values.
Interval bootstrap_trimmed_mean(const std::vector<double>& values, double trim, std::uint64_t seed);
/// Sanity: the method's translation error is below its initial guess' (median of the paired
/// differences over all pairs).
Claim claim_beats_guess(const MethodRows* m, const std::string& guess_name, std::uint64_t seed);

/// "Profile: quick|full (n = …)" for section notes.
std::string profile_note(const ExperimentConfig& config, const std::vector<MethodRows>& methods);
/// " Dataset: the scans of <folder> (…); its odometry guess is simulated …" for a folder dataset
/// (empty for the campus); profile_note ends with it.
std::string dataset_note(const ExperimentConfig& config);

}  // namespace sextant
