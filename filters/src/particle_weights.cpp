#include "sextant/filters/particle_weights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sextant {

// Two subtractions, not one of m + log Σ: lw_i − m is exact for the largest entry (0), and the
// small log Σ is then removed exactly, so Σ exp(lw_i) = 1 to rounding even when the lw_i are
// −1e9 (an impossible observation), where subtracting m + log Σ in one go would leave an error
// of ulp(1e9) ≈ 1e-7 in every weight.
bool normalize_log_weights(std::vector<double>& log_weights) {
  double top = -std::numeric_limits<double>::infinity();
  for (double lw : log_weights)
    if (std::isfinite(lw)) top = std::max(top, lw);
  if (!std::isfinite(top)) return false;
  double sum = 0.0;  // ≥ 1: the largest entry contributes exp(0)
  for (double& lw : log_weights) {
    lw = std::isfinite(lw) ? lw - top : -std::numeric_limits<double>::infinity();
    sum += std::exp(lw);
  }
  const double log_sum = std::log(sum);
  for (double& lw : log_weights) lw -= log_sum;
  return true;
}

std::vector<double> weights_from_log(const std::vector<double>& log_weights) {
  std::vector<double> w(log_weights.size());
  std::transform(log_weights.begin(), log_weights.end(), w.begin(), [](double lw) { return std::exp(lw); });
  return w;
}

double effective_sample_size(const std::vector<double>& log_weights) {
  double squares = 0.0;
  for (double lw : log_weights) squares += std::exp(2.0 * lw);
  return squares > 0.0 ? 1.0 / squares : 0.0;
}

std::vector<std::size_t> systematic_resample(const std::vector<double>& log_weights, Rng& rng) {
  const std::size_t n = log_weights.size();
  std::vector<std::size_t> out;
  if (n == 0) return out;
  out.reserve(n);
  const double step = 1.0 / static_cast<double>(n);
  const double r = rng.uniform() * step;
  std::size_t i = 0;
  double cumulative = std::exp(log_weights[0]);
  for (std::size_t k = 0; k < n; ++k) {
    const double target = r + static_cast<double>(k) * step;
    while (target > cumulative && i + 1 < n) cumulative += std::exp(log_weights[++i]);
    out.push_back(i);
  }
  return out;
}

}  // namespace sextant
