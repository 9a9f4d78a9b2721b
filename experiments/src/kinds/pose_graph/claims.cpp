// E20 claims, decided on our rows (eval/verdict.hpp). Per-pose position errors (after alignment)
// are strongly correlated along the route, so they are averaged over batches of `batch_scans`
// consecutive scans first; the bootstrap resamples the paired batch means of all repetitions.
//   "Loop closure reduces ATE vs chained odometry": graph − chained < 0 on the interval;
//   sanity: a false closure with the robust loss moves the mean error by less than the tolerance,
//           and without it by more (the check is only meaningful when the latter holds);
//   sanity: the graph solve costs less than `solve_budget` of the registrations' time (measured:
//           its range over the repetitions).
#include <algorithm>
#include <cmath>

#include "kit/number_format.hpp"
#include "kit/row_codec.hpp"
#include "pose_graph/report.hpp"
#include "pose_graph/row_keys.hpp"
#include "sextant/eval/verdict.hpp"

namespace sextant {
namespace {

/// Means of consecutive batches of `size` (a last, shorter batch of ≥ size/2 kept).
std::vector<double> batch_means(const std::vector<double>& v, std::size_t size) {
  std::vector<double> out;
  for (std::size_t start = 0; start < v.size(); start += size) {
    const std::size_t end = std::min(v.size(), start + size);
    if (end - start < (size + 1) / 2 && !out.empty()) break;
    double sum = 0;
    for (std::size_t k = start; k < end; ++k) sum += v[k];
    out.push_back(sum / static_cast<double>(end - start));
  }
  return out;
}

/// Paired batch means of two trajectories' per-pose errors, pooled over the rows.
void paired_batches(const std::vector<const RunRow*>& rows, const std::string& a, const std::string& b,
                    std::size_t size, std::vector<double>& out_a, std::vector<double>& out_b) {
  for (const RunRow* r : rows) {
    const std::vector<double> ma = batch_means(series_or_empty(*r, a + keys::kAteErrors), size);
    const std::vector<double> mb = batch_means(series_or_empty(*r, b + keys::kAteErrors), size);
    const std::size_t n = std::min(ma.size(), mb.size());
    out_a.insert(out_a.end(), ma.begin(), ma.begin() + static_cast<std::ptrdiff_t>(n));
    out_b.insert(out_b.end(), mb.begin(), mb.begin() + static_cast<std::ptrdiff_t>(n));
  }
}

double median_value(const std::vector<const RunRow*>& rows, const std::string& key) {
  std::vector<double> v;
  for (const RunRow* r : rows) v.push_back(r->value(key));
  return median_finite(v);
}

std::string ate_text(const std::vector<const RunRow*>& rows, const std::string& prefix) {
  return format_number(median_value(rows, prefix + keys::kAteM), 2) + " m";
}

}  // namespace

std::vector<Claim> pose_graph_claims(const ExperimentConfig& config, const PoseGraphParams& params,
                                     const MethodRows& odometry) {
  std::vector<Claim> claims;
  const auto& rows = odometry.rows;
  const std::size_t B = params.batch_scans;
  const std::string reps = std::to_string(rows.size()) + " repetition(s)";

  std::vector<double> graph, chained;
  paired_batches(rows, "graph_", "chained_", B, graph, chained);
  const Interval gain = bootstrap_paired_mean_difference(graph, chained, config.seed);
  claims.push_back(
      {"Loop closure reduces ATE vs chained odometry (§7.2: globally consistent registration)",
       rows.empty() ? Verdict::not_comparable : verdict_less(gain, 0.0),
       "ATE " + ate_text(rows, "graph_") + " (pose graph) vs " + ate_text(rows, "chained_") +
           " (chained), medians over " + reps + "; mean position error difference graph − chained " +
           describe(gain, " m") + ", bootstrap over " + std::to_string(graph.size()) + " paired means of " +
           std::to_string(B) + "-scan batches; " + format_number(median_value(rows, keys::kAccepted), 0) +
           " of " + format_number(median_value(rows, keys::kCandidates), 0) +
           " candidate closures accepted (median)",
       ClaimKind::thesis});

  std::vector<double> robust, clean_r, plain, clean_p;
  paired_batches(rows, "false_robust_", "graph_", B, robust, clean_r);
  paired_batches(rows, "false_plain_", "graph_", B, plain, clean_p);
  const Interval robust_shift = bootstrap_paired_mean_difference(robust, clean_r, config.seed + 1);
  const Interval plain_shift = bootstrap_paired_mean_difference(plain, clean_p, config.seed + 2);
  const double tol = params.false_closure_tolerance_m;
  const bool injected = median_value(rows, keys::kFalseClosures) > 0;
  claims.push_back(
      {"The robust (" + to_string(params.graph.loss) +
           ") loss keeps a false loop closure from wrecking the map: the mean position error rises "
           "by less than " +
           format_number(tol, 2) + " m",
       injected ? verdict_less(robust_shift, tol) : Verdict::not_comparable,
       "ATE " + ate_text(rows, "false_robust_") + " with the false closure and the robust loss vs " +
           ate_text(rows, "graph_") + " without the false closure; paired difference of " +
           std::to_string(B) + "-scan batch means " + describe(robust_shift, " m") + ", " + reps,
       ClaimKind::sanity});
  claims.push_back(
      {"Without the robust loss the same false closure does wreck the map (the error rises by more "
       "than " +
           format_number(tol, 2) + " m), so the check above tests something",
       injected ? verdict_greater(plain_shift, tol) : Verdict::not_comparable,
       "ATE " + ate_text(rows, "false_plain_") + " with the false closure and no robust loss vs " +
           ate_text(rows, "graph_") + "; paired difference of batch means " + describe(plain_shift, " m") +
           ", " + reps,
       ClaimKind::sanity});

  std::vector<double> share;
  for (const RunRow* r : rows) {
    const double work = r->value(keys::kRegistrationSeconds) + r->value(keys::kClosureSeconds);
    share.push_back(r->value(keys::kGraphSolveSeconds) / work);
  }
  Interval cost{median_finite(share), NAN, NAN, 1.0, share.size()};
  if (!share.empty()) {
    cost.lo = *std::min_element(share.begin(), share.end());
    cost.hi = *std::max_element(share.begin(), share.end());
  }
  claims.push_back(
      {"The graph solve is cheap beside the registrations: under " +
           format_number(100 * params.solve_budget, 0) + " % of their time",
       rows.empty() ? Verdict::not_comparable : verdict_less(cost, params.solve_budget),
       "measured: graph solve " + format_number(median_value(rows, keys::kGraphSolveSeconds), 3) + " s (" +
           format_number(median_value(rows, keys::kGraphSolveIterations), 0) + " LM iterations) vs " +
           format_number(median_value(rows, keys::kRegistrationSeconds), 1) + " s of odometry and " +
           format_number(median_value(rows, keys::kClosureSeconds), 1) +
           " s of closure registrations (single-thread sums, medians); share " + describe(cost) +
           " — the range over " + reps + ", not a confidence interval",
       ClaimKind::sanity});
  return claims;
}

}  // namespace sextant
