#pragma once
// The built-in samplers (§2.2.3, §5.1.2.2) with their settings. Build them directly (or by name from
// YAML: make_sampler() of matchers/yaml.hpp).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sextant/matchers/sampler.hpp"

namespace sextant {

/// `all` has nothing to set.
struct AllPointsSettings {
  bool valid(std::string* /*why*/) const { return true; }
};

/// Keeps every point.
class AllSampler final : public Sampler {
 public:
  std::string name() const override { return "all"; }
  std::vector<std::size_t> select(const PointCloud& input, Rng& rng) const override;
};

struct RegularSamplerSettings {
  std::size_t step = 10;  ///< keep every step-th point (indices 0, step, 2·step, …) [count ≥ 1]
  bool valid(std::string* why) const;
};

/// Every k-th point in storage order.
class RegularSampler final : public Sampler {
 public:
  explicit RegularSampler(RegularSamplerSettings settings = {});
  std::string name() const override { return "regular"; }
  std::vector<std::size_t> select(const PointCloud& input, Rng& rng) const override;

 private:
  RegularSamplerSettings settings_;
};

struct RandomSamplerSettings {
  double fraction = 0.1;  ///< share of the points kept, drawn uniformly without replacement [0, 1]
  bool valid(std::string* why) const;
};

/// A uniform random subset of round(fraction · n) points (partial Fisher–Yates with the Rng).
class RandomSampler final : public Sampler {
 public:
  explicit RandomSampler(RandomSamplerSettings settings = {});
  std::string name() const override { return "random"; }
  std::vector<std::size_t> select(const PointCloud& input, Rng& rng) const override;

 private:
  RandomSamplerSettings settings_;
};

struct GridSamplerSettings {
  double cell_size = 1.0;        ///< edge of the cubic sampling cells [m]
  std::size_t max_per_cell = 5;  ///< cells with more points give this many random ones [count]
  std::size_t min_per_cell = 3;  ///< cells with fewer points are dropped (thesis: n > 2) [count]
  bool valid(std::string* why) const;
};

/// Grid-based sampling (GBS, §2.2.3): at most `max_per_cell` random points per cell, all points
/// of cells with min_per_cell ≤ n ≤ max_per_cell, none from sparser cells.
class GridSampler final : public Sampler {
 public:
  explicit GridSampler(GridSamplerSettings settings = {});
  std::string name() const override { return "gbs"; }
  std::vector<std::size_t> select(const PointCloud& input, Rng& rng) const override;

 private:
  GridSamplerSettings settings_;
};

}  // namespace sextant
