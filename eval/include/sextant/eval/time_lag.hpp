#pragma once
// The time lag between an estimated and a true 2D path (E8, fig. 5.18: "the lag between the real
// and the estimated position"): the shift τ minimising the mean squared distance
//   c(τ) = mean_k ‖ê(t_k) − p(t_k − τ)‖²,
// with p(t) the true path interpolated linearly between its samples. τ > 0: the estimate trails
// the truth. Searched on a grid of step `step` in [−max_lag, max_lag], refined by the vertex of
// the parabola through the three best grid points.
//
//   const TimedPath truth{t_true, x_true, y_true};
//   const TimeLag lag = estimate_time_lag(truth, t_est, x_est, y_est, 2.0, 0.02);
#include <vector>

namespace sextant {

/// A 2D path sampled at increasing times [s], positions [m].
struct TimedPath {
  std::vector<double> t, x, y;
  /// Linear interpolation at `time`; false outside [t.front(), t.back()] or for a malformed path.
  bool at(double time, double* px, double* py) const;
};

/// c(τ) over the estimates whose shifted time lies on the path; NaN when none does [m²].
double lag_alignment_cost(const TimedPath& truth, const std::vector<double>& t, const std::vector<double>& x,
                          const std::vector<double>& y, double tau);

struct TimeLag {
  double lag = 0.0;          ///< τ* [s]
  double rms_at_lag = 0.0;   ///< √c(τ*) on the grid point nearest τ* [m]
  double rms_at_zero = 0.0;  ///< √c(0) [m]
  std::vector<double> taus;  ///< the grid [s]
  std::vector<double> rms;   ///< √c(τ) on the grid [m]
};

/// Throws std::invalid_argument unless 0 < step ≤ max_lag.
TimeLag estimate_time_lag(const TimedPath& truth, const std::vector<double>& t, const std::vector<double>& x,
                          const std::vector<double>& y, double max_lag, double step);

}  // namespace sextant
