#pragma once
// Writing the campus to disk in the uos layout (docs/synthetic_campus.md lists every file),
// a cache of generated campuses keyed by a hash of settings + seed, and a top-down preview.
#include <cstdint>
#include <filesystem>

#include "sextant/synth/campus.hpp"

namespace sextant::synth {

/// Writes every file of the campus into `folder` (created; existing files are overwritten).
/// Scans are generated and written in parallel; the bytes do not depend on the thread count.
void write_campus(const Campus& campus, const std::filesystem::path& folder);

/// cache_root/campus-<hash of settings and seed>/, generated on first use (into a temporary
/// folder renamed into place, so a killed run leaves no half-written campus) and reused after.
std::filesystem::path ensure_campus(const CampusSettings& settings, std::uint64_t seed,
                                    const std::filesystem::path& cache_root);

/// Top-down SVG: buildings, walls, cars, trees and poles; the true (green) and odometry
/// (orange) trajectories; scan `scan_index` in the world frame (blue dots) from its true pose.
void write_campus_preview_svg(const Campus& campus, std::size_t scan_index,
                              const std::filesystem::path& file);
/// Same, with the scan already generated.
void write_campus_preview_svg(const Campus& campus, std::size_t scan_index, const SimulatedScan& scan,
                              const std::filesystem::path& file);

}  // namespace sextant::synth
