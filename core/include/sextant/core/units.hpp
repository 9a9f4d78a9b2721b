#pragma once
// Numeric constants shared by every module: π, the degree ↔ radian factors, and the quiet NaN
// that stands for "no value" in results and tables.
#include <limits>

namespace sextant {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kRadPerDeg = kPi / 180.0;  ///< degrees × kRadPerDeg = radians
inline constexpr double kDegPerRad = 180.0 / kPi;  ///< radians × kDegPerRad = degrees
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// The largest length a geometry or noise setting may take [m]. A lidar sees a few hundred metres;
/// a cell, a correspondence distance or a σ beyond a kilometre is a typo, which would otherwise run
/// "ok" with nonsense results (docs/bad_input.md).
inline constexpr double kMaxSettingLength = 1000.0;

}  // namespace sextant
