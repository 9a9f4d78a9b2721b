// Grid-based sampling (GBS, §2.2.3 and §5.1.2.2): the input is split into cubic cells; sparse
// cells are dropped, small cells kept whole, and dense cells give a fixed number of random points.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "sextant/core/settings_reader.hpp"
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

GridSampler::GridSampler(GridSamplerSettings settings) : settings_(settings) {}

std::vector<std::size_t> GridSampler::select(const PointCloud& input, Rng& rng) const {
  const double inv_cell = 1.0 / settings_.cell_size;
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
  keyed.reserve(input.size());
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (input[i].allFinite()) keyed.emplace_back(cell_key(input[i], inv_cell), i);
  }
  std::sort(keyed.begin(), keyed.end());  // cells in key order, points in index order

  std::vector<std::size_t> selected;
  selected.reserve(keyed.size() / 2);
  std::vector<std::size_t> cell;
  for (std::size_t begin = 0; begin < keyed.size();) {
    std::size_t end = begin;
    cell.clear();
    while (end < keyed.size() && keyed[end].first == keyed[begin].first) cell.push_back(keyed[end++].second);
    begin = end;
    if (cell.size() < settings_.min_per_cell) continue;
    const std::size_t keep = std::min(cell.size(), settings_.max_per_cell);
    for (std::size_t i = 0; i < keep; ++i) std::swap(cell[i], cell[i + rng.index(cell.size() - i)]);
    selected.insert(selected.end(), cell.begin(), cell.begin() + static_cast<std::ptrdiff_t>(keep));
  }
  std::sort(selected.begin(), selected.end());
  return selected;
}

GridSamplerSettings read_grid_sampler_settings(const YAML::Node& settings, const std::string& file) {
  SettingsReader in(settings, file);
  GridSamplerSettings s;
  in.read("cell_size", s.cell_size);
  in.read("max_per_cell", s.max_per_cell);
  in.read("min_per_cell", s.min_per_cell);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

std::unique_ptr<Sampler> create_grid_sampler(const YAML::Node& settings, const std::string& file) {
  return std::make_unique<GridSampler>(read_grid_sampler_settings(settings, file));
}

}  // namespace sextant
