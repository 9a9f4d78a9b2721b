#pragma once
// The one random-number type of the project. Every random choice draws from an Rng passed in
// explicitly and seeded from the config; the distributions are implemented here (not taken
// from <random>'s distributions, whose output differs between standard libraries) so the same
// seed gives the same numbers everywhere.
#include <cstdint>
#include <random>

namespace sextant {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  /// Uniform 64-bit integer.
  std::uint64_t bits() { return engine_(); }
  /// Uniform in [0, 1).
  double uniform();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n), n > 0 (unbiased).
  std::uint64_t index(std::uint64_t n);
  /// Standard normal (Marsaglia polar method).
  double normal();
  double normal(double mean, double stddev) { return mean + stddev * normal(); }
  /// A new, independent generator seeded from this one (for per-run / per-thread streams).
  Rng split() { return Rng(bits() ^ 0x9E3779B97F4A7C15ULL); }

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace sextant
