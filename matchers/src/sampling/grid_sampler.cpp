// Grid-based sampling (GBS, §2.2.3 and §5.1.2.2): the input is split into cubic cells; sparse
// cells are dropped, small cells kept whole, and dense cells give a fixed number of random points.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#include "sextant/core/checked_settings.hpp"
#include "sextant/matchers/samplers.hpp"

namespace sextant {

namespace {

/// A cell key that orders cells deterministically (21 bits per axis, wrapping far away).
std::uint64_t cell_key(const Eigen::Vector3f& p, double inv_cell) {
  const auto axis = [inv_cell](float v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v * inv_cell)) & 0x1FFFFF);
  };
  return (axis(p.x()) << 42) | (axis(p.y()) << 21) | axis(p.z());
}

}  // namespace

bool GridSamplerSettings::valid(std::string* why) const {
  const char* problem = nullptr;
  if (!(cell_size > 0.0) || !std::isfinite(cell_size))
    problem = "cell_size must be a positive number of metres";
  else if (max_per_cell < 1)
    problem = "max_per_cell must be at least 1";
  else if (min_per_cell > max_per_cell)
    problem = "min_per_cell must not exceed max_per_cell";
  if (problem && why) *why = problem;
  return problem == nullptr;
}

GridSampler::GridSampler(GridSamplerSettings settings) : settings_(checked(settings, "gbs")) {}

std::vector<std::size_t> GridSampler::select(const PointCloud& input, Rng& rng) const {
  const double inv_cell = 1.0 / settings_.cell_size;
  // The points grouped by cell, cells in key order and points in index order: each cell's key is
  // numbered in a hash table, the few distinct keys are sorted, and a counting sort by the keys'
  // ranks groups the points (the order of sorting (key, index) pairs, in linear time).
  std::vector<std::size_t> order;  // finite points, then grouped
  order.reserve(input.size());
  std::vector<std::uint64_t> keys;  // distinct keys, by first appearance
  std::vector<std::uint32_t> cell_of_point;
  cell_of_point.reserve(input.size());
  std::size_t capacity = 64;
  while (capacity < 2 * input.size()) capacity *= 2;
  constexpr std::uint32_t kEmpty = 0xffffffffu;
  std::vector<std::uint32_t> table(capacity, kEmpty);  // open addressing: slot → index into keys
  const std::size_t mask = capacity - 1;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (!input[i].allFinite()) continue;
    const std::uint64_t key = cell_key(input[i], inv_cell);
    std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask;
    while (table[slot] != kEmpty && keys[table[slot]] != key) slot = (slot + 1) & mask;
    if (table[slot] == kEmpty) {
      table[slot] = static_cast<std::uint32_t>(keys.size());
      keys.push_back(key);
    }
    order.push_back(i);
    cell_of_point.push_back(table[slot]);
  }
  std::vector<std::uint32_t> by_key(keys.size());
  std::iota(by_key.begin(), by_key.end(), 0u);
  std::sort(by_key.begin(), by_key.end(),
            [&keys](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
  std::vector<std::size_t> start(keys.size(), 0);  // first position of each cell, by cell number
  std::vector<std::size_t> count(keys.size(), 0);
  for (const std::uint32_t c : cell_of_point) ++count[c];
  std::size_t at = 0;
  for (const std::uint32_t c : by_key) start[c] = at, at += count[c];
  std::vector<std::size_t> grouped(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) grouped[start[cell_of_point[k]]++] = order[k];

  std::vector<std::size_t> selected;
  selected.reserve(grouped.size() / 2);
  std::size_t begin = 0;  // each cell's points, drawn from in place
  for (const std::uint32_t c : by_key) {
    const std::size_t n = count[c];
    if (n >= settings_.min_per_cell) {
      const std::size_t keep = std::min(n, settings_.max_per_cell);
      for (std::size_t i = 0; i < keep; ++i)
        std::swap(grouped[begin + i], grouped[begin + i + rng.index(n - i)]);
      selected.insert(selected.end(), grouped.begin() + static_cast<std::ptrdiff_t>(begin),
                      grouped.begin() + static_cast<std::ptrdiff_t>(begin + keep));
    }
    begin += n;
  }
  std::sort(selected.begin(), selected.end());
  return selected;
}

}  // namespace sextant
