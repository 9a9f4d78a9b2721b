#pragma once
// The runs of an ML-NDT matcher's registrations of one input on one reference model, remembered for
// the next registration of that input on that model (mlndt_matcher.cpp). A run is the optimisation of
// one objective from one start: the same objective, start, optimiser settings, input and model give
// the same result, bit for bit, so a remembered result stands in for repeating it. Odometry's
// wide-basin recovery from the guess repeats the first try's pyramid, last-layer and precision runs
// (docs/matcher_defaults.md, "The recovery repeats no run").
#include <cstddef>
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/registration_result.hpp"

namespace sextant::mlndt_detail {

class RunMemo {
 public:
  /// Keeps the runs only when they were made on `model` with `input`'s points; else forgets them and
  /// remembers this model and input for the runs to come.
  void keep_only(const std::shared_ptr<const MlndtModel>& model, const PointCloud& input);
  /// The result of the run of `objective` from `start` (exactly that pose), null when not remembered.
  /// `objective` names the objective within one matcher's settings: its first stage's label (the
  /// start layer; n + 1 for the precision stage).
  const RegistrationResult* find(int objective, const Eigen::Isometry3d& start) const;
  /// Remembers a run (without its alternatives); the oldest is forgotten beyond kCapacity.
  void add(int objective, const Eigen::Isometry3d& start, RegistrationResult result);
  void clear();

  /// Runs kept per input: more than an odometry step's registrations of one input make (its first
  /// try and the recovery's starts, each up to seven runs and a precision stage) [count]
  static constexpr std::size_t kCapacity = 64;

 private:
  struct Run {
    int objective;
    Eigen::Isometry3d start;
    RegistrationResult result;
  };
  std::shared_ptr<const MlndtModel> model_;  ///< held: a new model never reuses the old one's address
  std::vector<Eigen::Vector3f> input_;
  std::vector<Run> runs_;
};

}  // namespace sextant::mlndt_detail
