#include "sextant/eval/time_lag.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sextant {

bool TimedPath::at(double time, double* px, double* py) const {
  if (t.empty() || x.size() != t.size() || y.size() != t.size() || !(time >= t.front()) ||
      !(time <= t.back()))
    return false;
  const auto it = std::upper_bound(t.begin(), t.end(), time);
  const std::size_t j = it == t.end() ? t.size() - 1 : static_cast<std::size_t>(it - t.begin());
  const std::size_t i = j == 0 ? 0 : j - 1;
  const double w = t[j] > t[i] ? (time - t[i]) / (t[j] - t[i]) : 0.0;
  *px = x[i] + w * (x[j] - x[i]);
  *py = y[i] + w * (y[j] - y[i]);
  return true;
}

double lag_alignment_cost(const TimedPath& truth, const std::vector<double>& t, const std::vector<double>& x,
                          const std::vector<double>& y, double tau) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < std::min({t.size(), x.size(), y.size()}); ++k) {
    double px = 0, py = 0;
    if (!truth.at(t[k] - tau, &px, &py)) continue;
    sum += (x[k] - px) * (x[k] - px) + (y[k] - py) * (y[k] - py);
    ++n;
  }
  return n > 0 ? sum / static_cast<double>(n) : std::numeric_limits<double>::quiet_NaN();
}

TimeLag estimate_time_lag(const TimedPath& truth, const std::vector<double>& t, const std::vector<double>& x,
                          const std::vector<double>& y, double max_lag, double step) {
  if (!(step > 0.0) || !(step <= max_lag)) throw std::invalid_argument("time lag: needs 0 < step <= max_lag");
  TimeLag out;
  const int steps = static_cast<int>(std::floor(max_lag / step + 1e-9));
  std::vector<double> costs;
  for (int i = -steps; i <= steps; ++i) {
    out.taus.push_back(i * step);
    costs.push_back(lag_alignment_cost(truth, t, x, y, out.taus.back()));
    out.rms.push_back(std::sqrt(costs.back()));
  }
  std::size_t b = 0;
  for (std::size_t i = 1; i < costs.size(); ++i)
    if (costs[i] < costs[b] || std::isnan(costs[b])) b = i;
  out.lag = out.taus[b];
  out.rms_at_lag = out.rms[b];
  out.rms_at_zero = out.rms[static_cast<std::size_t>(steps)];
  if (b > 0 && b + 1 < costs.size()) {  // vertex of the parabola through the three best points
    const double curvature = costs[b - 1] - 2 * costs[b] + costs[b + 1];
    if (curvature > 0) out.lag += 0.5 * step * (costs[b - 1] - costs[b + 1]) / curvature;
  }
  return out;
}

}  // namespace sextant
