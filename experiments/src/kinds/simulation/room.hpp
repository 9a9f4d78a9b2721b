#pragma once
// E8's fig. 5.17 (one scan match of the room simulation): recorded by the run of repetition 0,
// drawn by the report as a figure and a 3D scene (simulation/room_scan_match.cpp).
#include <cstdint>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/matchers/matcher.hpp"
#include "simulation/room_sim_2d.hpp"

namespace sextant {

/// Picks the updated scan with the sharpest true turn since the scan before it, re-simulates both
/// scans at their true poses (range noise from Rng(seed)), matches the new scan into the previous
/// one from the dead-reckoning increment as in the run (eq. 3.46), and stores the three point sets
/// in the previous scan's frame as series `match_*` (and the scan's index and errors as values).
void record_scan_match(const RoomSim2dSettings& settings, const RoomSim2dRun& run, Matcher& matcher,
                       std::uint64_t seed, RunRow& row);

/// Fig. 5.17 from the series record_scan_match wrote; a figure with an empty id when they are missing.
ReportFigure scan_match_figure(const RunRow& row);
/// Fig. 5.17 as a 3D scene (the previous scan, and the new scan at the dead-reckoning guess and after
/// ML-NDT, one state each); a scene with an empty id when the series are missing.
ReportScene scan_match_scene(const RunRow& row);

}  // namespace sextant
