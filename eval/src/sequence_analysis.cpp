#include "sextant/eval/sequence_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sextant/core/rng.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/statistics.hpp"

namespace sextant {
namespace {

struct Pairs {
  std::vector<double> x, y;
};

Pairs finite_pairs(const std::vector<double>& x, const std::vector<double>& y) {
  Pairs p;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
    p.x.push_back(x[i]);
    p.y.push_back(y[i]);
  }
  return p;
}

LineFit fit(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit f;
  f.n = x.size();
  if (f.n < 2) return f;
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < f.n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(f.n);
  my /= static_cast<double>(f.n);
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < f.n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
  }
  if (!(sxx > 0.0)) {
    f.slope = f.intercept = kNaN;
    return f;
  }
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  return f;
}

}  // namespace

bool LineFit::defined() const {
  return n >= 2 && std::isfinite(slope) && std::isfinite(intercept);
}

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const Pairs p = finite_pairs(x, y);
  return fit(p.x, p.y);
}

Interval bootstrap_slope(const std::vector<double>& x, const std::vector<double>& y, std::uint64_t seed,
                         double confidence, int resamples) {
  const Pairs p = finite_pairs(x, y);
  const LineFit whole = fit(p.x, p.y);
  if (!whole.defined() || resamples < 1) return {kNaN, kNaN, kNaN, confidence, p.x.size()};
  Rng rng(seed);
  std::vector<double> draws, bx(p.x.size()), by(p.x.size());
  draws.reserve(static_cast<std::size_t>(resamples));
  for (int k = 0; k < resamples; ++k) {
    for (std::size_t i = 0; i < bx.size(); ++i) {
      const std::size_t j = rng.index(p.x.size());
      bx[i] = p.x[j];
      by[i] = p.y[j];
    }
    const LineFit f = fit(bx, by);
    if (f.defined()) draws.push_back(f.slope);
  }
  if (draws.empty()) return {whole.slope, whole.slope, whole.slope, confidence, p.x.size()};
  return percentile_interval(whole.slope, draws, confidence, p.x.size());
}

std::vector<std::size_t> robust_spikes(const std::vector<double>& values, double threshold,
                                       std::size_t separation) {
  std::vector<double> finite;
  for (double v : values)
    if (std::isfinite(v)) finite.push_back(v);
  if (finite.empty()) return {};
  const double median = median_of(finite);
  for (double& v : finite) v = std::abs(v - median);
  const double scale = 1.4826 * median_of(finite);
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (!std::isfinite(v) || v <= median) continue;
    if (scale > 0.0 && (v - median) / scale <= threshold) continue;
    const std::size_t lo = i >= separation ? i - separation : 0;
    const std::size_t hi = std::min(values.size() - 1, i + separation);
    bool largest = true;
    for (std::size_t j = lo; j <= hi && largest; ++j) {
      if (j == i || !std::isfinite(values[j])) continue;
      if (values[j] > v || (values[j] == v && j < i)) largest = false;
    }
    if (largest) out.push_back(i);
  }
  return out;
}

std::vector<std::size_t> revisit_starts(const std::vector<Eigen::Vector3d>& positions, double radius,
                                        std::size_t min_gap) {
  std::vector<std::size_t> starts;
  bool previous = false;
  for (std::size_t k = 0; k < positions.size(); ++k) {
    bool revisit = false;
    for (std::size_t j = 0; j + min_gap <= k && !revisit; ++j)
      revisit = (positions[k] - positions[j]).norm() < radius;
    if (revisit && !previous) starts.push_back(k);
    previous = revisit;
  }
  return starts;
}

std::vector<std::size_t> distance_to_nearest(const std::vector<std::size_t>& indices,
                                             const std::vector<std::size_t>& events) {
  std::vector<std::size_t> out;
  for (std::size_t i : indices) {
    std::size_t best = std::numeric_limits<std::size_t>::max();
    for (std::size_t e : events) best = std::min(best, i > e ? i - e : e - i);
    out.push_back(best);
  }
  return out;
}

}  // namespace sextant
