#pragma once
// Importance weights of a particle filter kept as logarithms, and resampling by the effective
// sample size: N_eff = 1/Σw² (Kong, Liu and Wong 1994), resampling only when it falls below a
// fraction of N (the selective resampling of Doucet et al. 2000 and Grisetti, Stachniss and
// Burgard 2007, used with FastSLAM 2.0 instead of its resampling at every step), by systematic
// (low-variance) resampling (Thrun, Burgard and Fox, Probabilistic Robotics 2005, Table 4.4).
//
//   normalize_log_weights(lw);                     // lw_i ← lw_i − log Σ exp(lw_j)
//   if (effective_sample_size(lw) < 0.5 * n) indices = systematic_resample(lw, rng);
//
// Working in logarithms is what keeps a very unlikely observation (a heavy-tailed odometry
// step, an outlier) from underflowing every weight to 0 and the normalisation to 0/0.
#include <cstddef>
#include <vector>

#include "sextant/core/rng.hpp"

namespace sextant {

/// Subtracts log Σ_j exp(lw_j) (computed as m + log Σ exp(lw_j − m), m = max lw) so that the
/// weights exp(lw_i) sum to 1. Entries of −∞ (particles with zero weight) stay −∞. Returns false
/// and leaves lw unchanged when no entry is finite (nothing to normalise).
bool normalize_log_weights(std::vector<double>& log_weights);

/// exp(lw_i) of normalised log weights.
std::vector<double> weights_from_log(const std::vector<double>& log_weights);

/// N_eff = 1 / Σ w_i² of normalised log weights (Kong, Liu and Wong 1994): N for equal weights,
/// 1 when one particle has all the weight.
double effective_sample_size(const std::vector<double>& log_weights);

/// Systematic (low-variance) resampling: one uniform draw r ∈ [0, 1/N), then the particle whose
/// cumulative weight interval holds r + k/N for k = 0…N−1. Every particle i is drawn
/// ⌊N w_i⌋ or ⌈N w_i⌉ times, and N w_i times on average. Takes normalised log weights and
/// returns N source indices, ascending.
std::vector<std::size_t> systematic_resample(const std::vector<double>& log_weights, Rng& rng);

}  // namespace sextant
