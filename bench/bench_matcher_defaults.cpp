// The measured table behind the defaults of `mlndt` and `sextant match` (issue 14,
// docs/matcher_defaults.md): every combination of solver × layers × start layer × truncation (τ and how many
// of the finest layers it applies to) × sampling on every shared real pair and on campus pairs, from the
// guess a user has (identity; the tutorial guess for PCL's room scans). Errors against each pair's reference
// pose: ground truth (Velodyne, campus, uos .frames); cross-method consensus for the KITTI pair (its derived
// ground truth is withdrawn) and the room scans (no ground truth): point-to-plane ICP, which the real-pair
// tests show agrees with ML-NDT.
//
//   build/bench/bench_matcher_defaults [solvers=newton,lm] > table.md
#include <chrono>
#include <cstdio>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench_pairs.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/yaml.hpp"

namespace {

using namespace sextant;
using bench::Pair;

std::vector<Pair> pairs() {
  std::vector<Pair> out = bench::real_pairs();
  for (Pair& p : bench::campus_pairs({20, 150, 300})) out.push_back(std::move(p));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> solvers;
  std::stringstream list(argc > 1 ? argv[1] : "newton,lm");
  for (std::string item; std::getline(list, item, ',');) solvers.push_back(item);
  const std::vector<Pair> all = pairs();
  std::printf("| solver | layers | start layer | truncation | sampling |");
  for (const Pair& p : all) std::printf(" %s cm / ° |", p.name.c_str());
  std::printf(" worst cm | within 5 cm & 0.5° | total s |\n|---|---|---|---|");
  for (std::size_t k = 0; k < all.size() + 4; ++k) std::printf("---|");
  std::printf("\n");
  // Samplers: every point, GBS at its defaults (1 m cells, 5 points each), a denser GBS.
  const std::vector<std::pair<std::string, std::string>> samplings = {
      {"all", "all"}, {"gbs", "gbs"}, {"gbs 0.5 m × 10", "gbs"}};
  for (const std::string& solver : solvers) {
    for (int layers : {4, 5, 6}) {
      for (int start_layer : {2, 1}) {
        // Truncation at τ = 16 in the finest 1, 2 or 3 layers (truncated_layers), or off.
        for (int truncated : {0, 1, 2, 3}) {
          if (truncated > layers - start_layer + 1) continue;
          for (const auto& [label, sampling] : samplings) {
            std::string settings = "{solver: " + solver + ", layers: " + std::to_string(layers) +
                                   ", start_layer: " + std::to_string(start_layer);
            // The library's defaults truncate: "off" has to say so.
            settings += truncated > 0 ? ", max_distance: 16, unmatched_penalty: 16, truncated_layers: " +
                                            std::to_string(truncated)
                                      : std::string(", max_distance: .inf");
            settings += "}";
            const auto matcher = make_matcher("mlndt", YAML::Load(settings), "bench");
            const auto sampler = make_sampler(sampling, label == "gbs 0.5 m × 10"
                                                            ? YAML::Load("{cell_size: 0.5, max_per_cell: 10}")
                                                            : YAML::Node());
            const std::string truncation = truncated == 0 ? "off" : "16 in last " + std::to_string(truncated);
            std::printf("| %s | %d | %d | %s | %s |", solver.c_str(), layers, start_layer, truncation.c_str(),
                        label.c_str());
            double worst = 0.0, seconds = 0.0;
            int good = 0;
            for (const Pair& p : all) {
              Rng rng(1);
              const auto start = std::chrono::steady_clock::now();
              const RegistrationResult r =
                  match_pair(*matcher, *sampler, p.reference, p.input, p.guess, rng).result;
              seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
              const Eigen::Isometry3d E = p.truth.inverse() * r.T;
              const double cm = 100.0 * translation_norm(E), deg = rotation_angle(E) * 180.0 / M_PI;
              worst = std::max(worst, cm);
              good += cm < 5.0 && deg < 0.5;
              std::printf(" %.1f / %.2f |", cm, deg);
            }
            std::printf(" %.1f | %d of %zu | %.2f |\n", worst, good, all.size(), seconds);
            std::fflush(stdout);
          }
        }
      }
    }
  }
}
