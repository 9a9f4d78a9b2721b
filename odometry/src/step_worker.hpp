#pragma once
// One odometry step's registrations (odometry.cpp): the first try from the guess, and the recovery of
// an untrusted step with the wide basin from the guess and the other starts.
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/odometry/sequence_trust.hpp"

namespace sextant::odometry_detail {

/// What the sequence knows about one step besides its guess (StepWorker::first_try).
struct StepContext {
  /// Further starts the sequence offers (constant velocity: the last motion unscaled, where velocity ×
  /// Δt lies far from it), registered too and kept as the result's alternatives, so that two priors
  /// leading to two trusted poses far apart make the step ambiguous.
  std::vector<Eigen::Isometry3d> other_priors;
  /// There is no prior (no motion known yet, or the motion the guess continues is not the last step's):
  /// an answer of no motion needs confirming (check_unconfirmed_no_motion), and with recovery on the first
  /// registration is the wide basin's, as `sextant match`'s without --init.
  bool search = false;
  /// How far from the guess the platform could move in this step (reachable_departure; ∞: unknown);
  /// every answer of the step farther away is not trusted (check_reachable_motion).
  double reach = std::numeric_limits<double>::infinity();
  /// The rotation of the last motion, which the guess continues: that velocity held in the world instead
  /// of the platform's frame is the guess's translation turned back by it (check_reachable_motion).
  Eigen::Matrix3d last_turn = Eigen::Matrix3d::Identity();
  /// Nothing bounds an answer that moves: no odometer's guess, and no trusted velocity just before it
  /// (`reach` unknown), so that the points above the horizon confirm it (check_motion_above_horizon).
  bool unbounded = false;
  /// The scans lie in their sensor's frame (step_frame.hpp), so that an answer without translation, and
  /// an unbounded one, is confirmed by the points above the horizon (horizon_check.hpp).
  bool sensor_frame = true;
  /// The sensor draws rings (a spinning lidar, sensor_kind.hpp): an answer without translation needs
  /// confirming (check_unconfirmed_no_motion), and the points above the horizon are asked (`sensor_frame`)
  bool rings = true;
  /// The step's checks, with the platform's tolerance (platform_tolerance); unset: OdometrySettings'
  std::optional<QualitySettings> quality;
};

/// The matcher and sampler of one worker, and the wide-basin matcher it recovers with.
class StepWorker {
 public:
  explicit StepWorker(const OdometrySettings& s);

  /// What the sequence knows about the next step, for a recover() without a first_try on this worker.
  void set_context(StepContext context) { context_ = std::move(context); }

  /// The first registration from `guess`, assessed on its own (absolute checks), with what the sequence
  /// knows about the step (StepContext).
  OdometryStep first_try(const PointCloud& reference, const PointCloud& input, const Eigen::Isometry3d& guess,
                         std::uint64_t seed, StepContext context = {});

  /// An untrusted step: the wide basin from each of `starts` (the guess first) until a registration
  /// is trusted; when none is, the step chains one of the registrations whose only flaw is their fit
  /// (suspect_choice.hpp), else `starts.back()` (the last trusted motion), and stays untrusted. The wide
  /// basin's answer is judged on its own (registration_quality.hpp; an answer of no motion by
  /// check_unconfirmed_no_motion too) and by `sequence`, the check that flagged the first try: an answer
  /// the sequence check flags is trusted only when it confirms the first registration (within
  /// QualitySettings' ambiguity tolerance: two searches agree) and, where the first was sound on its
  /// own, its points above the horizon confirm it (MulRan as 16 rings: the search scored the same rings
  /// that held the first registration 1.03 m past a braking car's motion), since a step may rightly
  /// overlap less than its neighbours (a corner, an open space; measured on the campus: right poses 0.70
  /// where the median is 0.87), but a search that lands somewhere new with such an overlap has nothing
  /// to back it (the campus route in 150 scans, 9 m apart, with constant velocity: trusted 8.2 m off at
  /// overlap 0.59 where its neighbours matched 0.66–0.77). Every registration of the step is an answer (the
  /// first, its alternatives, each recovery): a trusted recovery far from an answer (QualitySettings'
  /// ambiguity tolerance) that does not fit clearly better than it is a second answer, and so is one that
  /// reaches a pose already in dispute (an ambiguous registration's, or the alternative that made it so);
  /// when nothing else is trusted the step is chained as the least suspect and says it is ambiguous.
  void recover(OdometryStep& step, const PointCloud& reference, const PointCloud& input,
               const std::vector<Eigen::Isometry3d>& starts, std::uint64_t seed,
               const SequenceTrust& sequence);

 private:
  OdometryStep to_step(const PairMatch& m, const PointCloud& reference, const Eigen::Isometry3d& guess) const;
  /// A trusted answer in the sensor's frame, without translation, unbounded (StepContext) or `doubted`
  /// (a sound first registration the sequence check flagged, which the recovery found again): the input's
  /// points above the horizon registered alone from it by `matcher_` (with the reference model of `built`,
  /// which registered the step), for no translation searched for by `recovery_` where that tells nothing,
  /// for one that moves followed by the whole scan's `sample` from where they rest, and the answer suspect
  /// when they do not confirm it (horizon_check.hpp). A refuted answer is no answer of the step (remember),
  /// and where those points rest instead the recovery starts too.
  void confirm_above_horizon(OdometryStep& step, const PointCloud& reference, const PointCloud& input,
                             const PointCloud& sample, const Matcher& built, bool doubted = false);
  /// An ambiguous first registration `m` (of `sample`, by `matcher`): each rival registered again from
  /// where it ended; one the registration brings back within the tolerance of `m`'s pose was no second
  /// minimum, and is dropped (then `m` is assessed again). A rival of the pyramid may have stopped where
  /// its coarsest cells no longer tell poses apart, tenths of a metre from the answer on a sparse scan,
  /// and only the chosen pose went through the precision stage; two answers are two when each is where
  /// the registration ends.
  void settle_rivals(Matcher& matcher, const SampledInput& sample, PairMatch& m) const;
  /// `matcher_` holding the model of `reference` (shared from `built`, which holds it, where it can be).
  Matcher& local(const PointCloud& reference, const Matcher& built);
  /// Whether `pose` lies within the ambiguity tolerance of an answer its points above the horizon refuted.
  bool refuted(const Eigen::Isometry3d& pose) const;
  /// Drops the alternatives of `m` (a registration of `sample`) that lie at a refuted answer, and assesses
  /// it again without them: a refuted answer cannot make another ambiguous.
  void drop_refuted(PairMatch& m, const PointCloud& sample) const;
  /// Keeps the answers of `m`, a registration of `sample`: its pose when it converged and at most its
  /// fit is poor, and its alternatives that pass the trust checks; none at a refuted answer.
  void remember(const PairMatch& m, const PointCloud& sample);

  /// A pose one registration of this step reached, with its fit ratio.
  struct Answer {
    Eigen::Isometry3d relative;
    double fit_ratio = 0.0;
  };

  /// The checks of this step (StepContext::quality).
  const QualitySettings& quality() const { return context_.quality ? *context_.quality : settings_.quality; }

  std::unique_ptr<Matcher> matcher_;
  /// What recovers an untrusted step: the matcher with its wide basin (mlndt, fbmlndt), else the
  /// matcher itself from the other starts; null when recovery is off.
  std::unique_ptr<Matcher> recovery_;
  bool wide_basin_ = false;
  bool searched_ = false;        ///< this step's first registration was the wide basin's
  StepContext context_;          ///< first_try's, for this step
  std::vector<Answer> answers_;  ///< this step's answers so far (first_try, recover)
  /// The poses of this step's ambiguous registrations and of the alternatives that made them so
  std::vector<Eigen::Isometry3d> disputed_;
  std::vector<Eigen::Isometry3d> refuted_;    ///< this step's answers its points above the horizon refuted
  std::vector<Eigen::Isometry3d> elsewhere_;  ///< where those points rest instead (recovery starts)
  std::unique_ptr<Sampler> sampler_;
  const OdometrySettings& settings_;
  const PointCloud* matcher_reference_ = nullptr;   ///< what `matcher_` was last given (its model's source)
  const PointCloud* recovery_reference_ = nullptr;  ///< what `recovery_` was last given, this step
};

}  // namespace sextant::odometry_detail
