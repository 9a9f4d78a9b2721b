#include "sextant/eval/statistics.hpp"

#include <algorithm>
#include <cmath>

namespace sextant {

SampleStats summarize(const std::vector<double>& values) {
  SampleStats s;
  s.count = values.size();
  if (values.empty()) return s;
  double sum = 0.0, sum_sq = 0.0;
  for (double v : values) {
    sum += v;
    sum_sq += v * v;
  }
  s.mean = sum / values.size();
  s.rms = std::sqrt(sum_sq / values.size());
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  s.min = *lo;
  s.max = *hi;
  if (values.size() > 1) {
    double ss = 0.0;
    for (double v : values) ss += (v - s.mean) * (v - s.mean);
    s.std = std::sqrt(ss / (values.size() - 1));
  }
  return s;
}

}  // namespace sextant
