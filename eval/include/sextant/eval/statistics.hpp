#pragma once
// Summary statistics of a sample, as the thesis' tables report them (mean / std / max).
#include <vector>

namespace sextant {

struct SampleStats {
  std::size_t count = 0;
  double mean = 0.0;
  double std = 0.0;  ///< sample standard deviation (n − 1); 0 for fewer than two values
  double min = 0.0;
  double max = 0.0;
  double rms = 0.0;
};

SampleStats summarize(const std::vector<double>& values);

}  // namespace sextant
