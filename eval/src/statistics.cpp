#include "sextant/eval/statistics.hpp"

#include <algorithm>
#include <cmath>

#include "sextant/core/units.hpp"

namespace sextant {

namespace {

std::vector<double> finite_only(const std::vector<double>& values) {
  std::vector<double> out;
  out.reserve(values.size());
  for (double v : values)
    if (std::isfinite(v)) out.push_back(v);
  return out;
}

}  // namespace

SampleStats summarize(const std::vector<double>& values) {
  std::vector<double> v = finite_only(values);
  SampleStats s;
  s.count = v.size();
  if (v.empty()) return s;
  double sum = 0.0, sum_sq = 0.0;
  for (double x : v) {
    sum += x;
    sum_sq += x * x;
  }
  const double n = static_cast<double>(v.size());
  s.mean = sum / n;
  s.rms = std::sqrt(sum_sq / n);
  if (v.size() > 1) {
    double ss = 0.0;
    for (double x : v) ss += (x - s.mean) * (x - s.mean);
    s.std = std::sqrt(ss / (n - 1.0));
  }
  std::sort(v.begin(), v.end());
  s.min = v.front();
  s.max = v.back();
  const std::size_t mid = v.size() / 2;
  s.median = v.size() % 2 == 1 ? v[mid] : 0.5 * (v[mid - 1] + v[mid]);
  return s;
}

double rms(const std::vector<double>& values) {
  return summarize(values).rms;
}

double mean_of(const std::vector<double>& values) {
  const SampleStats s = summarize(values);
  return s.count > 0 ? s.mean : kNaN;
}

double median_of(const std::vector<double>& values) {
  const SampleStats s = summarize(values);
  return s.count > 0 ? s.median : kNaN;
}

}  // namespace sextant
