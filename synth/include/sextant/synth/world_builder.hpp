#pragma once
// Builds the campus world from its settings: a 2×2 grid of city blocks (roads on the block
// edges, the trajectory follows them) surrounded by a built-up border.
#include "sextant/core/rng.hpp"
#include "sextant/synth/settings.hpp"
#include "sextant/synth/world.hpp"

namespace sextant::synth {

/// Road centre-line crossings are at x ∈ {0, L, 2L}, y ∈ {0, W, 2W} (L = block_length,
/// W = block_width). `start_clearance` keeps the west border free up to x = −start_clearance
/// (the trajectory's first leg approaches the origin from there).
World build_world(const WorldSettings& settings, double start_clearance, Rng& rng);

}  // namespace sextant::synth
