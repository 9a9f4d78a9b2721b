#pragma once
// The wide basin's settings (key `wide_basin:` of mlndt and fbmlndt; absent = off, the thesis'
// registration). What the search does: matchers/src/mlndt/mlndt_global_init.hpp and docs/wide_basin.md.
//
//   wide_basin: {yaw_step_deg: 10, yaw_range_deg: 180, translation_step: 2,
//                translation_range: 16, sample_points: 512, prescreen_points: 128,
//                prescreen_keep: 512, candidates: 4, horizon_candidates: 4, max_distance: 16,
//                tilt_step_deg: 10, tilt_range_deg: 20, tilt_candidates: 2}
#include <string>

namespace sextant {

struct WideBasinSettings {
  bool enabled = false;             ///< set by the presence of the `wide_basin` key
  double yaw_step_deg = 10.0;       ///< spacing of the yaw hypotheses [°, > 0]
  double yaw_range_deg = 180.0;     ///< hypotheses over ±range around the guess [°, 0..180]
  double translation_step = 2.0;    ///< spacing of the x/y offset grid [m, > 0]
  double translation_range = 16.0;  ///< offsets over ±range in x and y around the guess [m, ≥ 0]
  /// Spacing of the tilt hypotheses about the input's own x and y axes (roll, pitch) [°, (0, 90]]
  double tilt_step_deg = 10.0;
  /// Tilts over ±range about x and y, each with every yaw, at the guess' position: a sensor that is not
  /// level, or turns fast about every axis (a hand-held one), moves little meanwhile [°, 0..90]
  double tilt_range_deg = 20.0;
  /// The best tilted hypotheses, refined only for a narrow view when no run from the guess or the level
  /// hypotheses passes the trust checks (docs/wide_basin.md). 0: no tilts [count, ≥ 0]
  int tilt_candidates = 2;
  int sample_points = 512;  ///< input points scored per hypothesis (evenly strided) [count]
  /// Every hypothesis is first scored with this many points (a strided subset of the sample),
  /// the best `prescreen_keep` are rescored with all `sample_points`; 0 scores all with all [count]
  int prescreen_points = 128;
  int prescreen_keep = 512;  ///< hypotheses rescored after the prescreen [count, ≥ candidates]
  int candidates = 4;        ///< best hypotheses refined by the full registration [count]
  /// Further hypotheses refined, the best by the input's points above the horizon alone (z > 0 in the
  /// input's frame, where a level spinning lidar's ground rings are not), distinct from the others;
  /// none when fewer than `prescreen_points` (without a prescreen `sample_points`) of the input lie
  /// there [count, ≥ 0]
  int horizon_candidates = 4;
  double max_distance = 16.0;  ///< τ of the hypothesis score [Mahalanobis units]
  bool valid(std::string* why) const;
  /// Level hypotheses (yaw × x/y) scored per registration.
  long hypotheses() const;
  /// Tilted hypotheses (yaw × roll × pitch, the level ones left out) scored when they are needed.
  long tilted_hypotheses() const;
};

}  // namespace sextant
