#pragma once
// Summary statistics of a sample, as the thesis' tables report them (mean / std / max).
#include <cstddef>
#include <vector>

namespace sextant {

struct SampleStats {
  std::size_t count = 0;  ///< number of finite values summarised (NaN/inf are skipped)
  double mean = 0.0;
  double std = 0.0;  ///< sample standard deviation (n − 1); 0 for fewer than two values
  double min = 0.0;
  double max = 0.0;
  double rms = 0.0;     ///< sqrt(mean of squares)
  double median = 0.0;  ///< middle value (mean of the two middle ones for an even count)
};

/// Summarises the finite values of `values`; non-finite entries are skipped (count says how many
/// were used), an empty input gives count = 0 and zeros.
SampleStats summarize(const std::vector<double>& values);

/// Root mean square of the finite values (0 when there are none).
double rms(const std::vector<double>& values);

/// Mean of the finite values; NaN when there are none.
double mean_of(const std::vector<double>& values);
/// Median of the finite values (mean of the two middle ones for an even count); NaN when there are none.
double median_of(const std::vector<double>& values);

}  // namespace sextant
