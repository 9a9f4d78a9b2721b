#pragma once
// What the sensor is carried by, and the size of a wrong step in that platform's units (issue 62).
// QualitySettings' ambiguity tolerance (1 m or 5°) is the size of error the trust status exists to
// catch, and "no motion" means within it (check_unconfirmed_no_motion, answer_without_translation). On
// a car whose keyframes lie metres apart that is a fraction of a step; on a person who walks a fraction
// of a metre per keyframe it is several steps: every right step is then "no motion", and an answer two
// steps off is within the tolerance of the right one. The tolerance follows the platform's own motion
// instead: half the median length of its last trusted steps (two answers farther apart disagree on the
// motion by more than half of it), between the bar of a sequence carried on foot (0.3 m or 3°) and a
// car's (1 m or 5°), the degrees following the metres on the line between the two.
#include <cstddef>
#include <deque>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "sextant/core/enum_names.hpp"
#include "sextant/matchers/registration_quality.hpp"

namespace sextant {

enum class Platform {
  automatic,  ///< the tolerance follows the sequence's typical step (MotionScale): half of it
  car,        ///< a car's tolerance, whatever the steps: QualitySettings' 1 m or 5°
  handheld,   ///< carried on foot: 0.3 m or 3°, whatever the steps
};

/// "auto" | "car" | "handheld"; InputError(`what`) naming the choices otherwise.
inline constexpr EnumNames<Platform, 3> kPlatformNames{
    "platform", {{{Platform::automatic, "auto"}, {Platform::car, "car"}, {Platform::handheld, "handheld"}}}};
bool from_string(const std::string& text, Platform* out);
std::string to_string(Platform platform);

/// The bounds of the tolerance: a sequence carried on foot's bar, and a car's (QualitySettings).
inline constexpr double kHandheldToleranceMetres = 0.3, kHandheldToleranceDegrees = 3.0;

/// `base` with its ambiguity tolerance for `platform`: a car's is base's; a handheld one's the
/// handheld bar (never above base's); automatic, half the `typical_step` clamped to [handheld bar, base]
/// and the degrees on the line between the two bars, base's while the typical step is unknown.
QualitySettings platform_tolerance(const QualitySettings& base, Platform platform,
                                   std::optional<double> typical_step);

/// The typical step of a sequence: the median translation of its last `window` trusted steps, known
/// from `min_history` of them on.
class MotionScale {
 public:
  explicit MotionScale(std::size_t window = 10, std::size_t min_history = 3)
      : window_(window), min_history_(min_history) {}
  void record(const Eigen::Isometry3d& trusted_step);
  std::optional<double> typical_step() const;  ///< [m]

 private:
  std::size_t window_, min_history_;
  std::deque<double> lengths_;
};

}  // namespace sextant
