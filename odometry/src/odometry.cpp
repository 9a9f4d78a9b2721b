// Chained registrations over a sequence (§5.1.3: dead reckoning by a matcher). Each step
// registers scan i (sampled) against scan i − 1 or the local map in scan i − 1's frame, from the
// guess mode's start, and chains the result: pose_i = pose_{i−1} · relative_i.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "sextant/core/error.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/odometry/local_map.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/odometry/sequence_trust.hpp"
#include "sextant/odometry/suspect_choice.hpp"

namespace sextant {
namespace {

/// Scans loaded and registered together on the parallel path (bounds the memory held).
constexpr std::size_t kChunk = 16;

/// Fits within this factor of each other count as equal when no registration is trusted: the
/// sequence check's own tolerance (SequenceTrustSettings::fit_factor) [ratio].
constexpr double kSuspectFitBand = SequenceTrustSettings{}.fit_factor;

std::string dataset_label(const Dataset& dataset) {
  const DatasetMetadata& m = dataset.metadata();
  if (!m.path.empty()) return m.path.string();
  return m.name.empty() ? std::string("<dataset>") : m.name;
}

/// Δt_i / Δt_{i−1} around scan i (the constant-velocity guess's scale), 1 without usable times.
double time_ratio(const Dataset& dataset, std::size_t i) {
  if (i < 2) return 1.0;
  const auto t0 = dataset.stamp(i - 2), t1 = dataset.stamp(i - 1), t2 = dataset.stamp(i);
  if (!t0 || !t1 || !t2) return 1.0;
  const double before = *t1 - *t0, now = *t2 - *t1;
  if (!(before > 0.0 && now > 0.0) || !std::isfinite(now / before)) return 1.0;
  return now / before;
}

/// The odometry poses the guess mode needs (empty unless guess = odometry).
std::vector<Eigen::Isometry3d> odometry_poses(const Dataset& dataset, const OdometrySettings& s,
                                              std::size_t first, std::size_t count) {
  if (s.guess != OdometryGuess::odometry) return {};
  if (!s.odometry.empty()) {
    if (s.odometry.size() < count)
      throw InputError("odometry settings", "",
                       "the given odometry has " + std::to_string(s.odometry.size()) +
                           " poses, fewer than the " + std::to_string(count) + " scans");
    return {s.odometry.begin(), s.odometry.begin() + static_cast<std::ptrdiff_t>(count)};
  }
  std::vector<Eigen::Isometry3d> poses;
  for (std::size_t k = 0; k < count; ++k) {
    const auto pose = dataset.odometry(first + k);
    if (!pose)
      throw InputError(dataset_label(dataset), "",
                       "scan " + std::to_string(first + k) + " has no odometry (this " +
                           dataset.metadata().format +
                           " dataset has none): the odometry guess needs it; use the constant_velocity "
                           "guess (or identity) instead");
    poses.push_back(*pose);
  }
  return poses;
}

Eigen::Isometry3d start_pose(const Dataset& dataset, const OdometrySettings& s, std::size_t first) {
  if (s.initial_pose) return *s.initial_pose;
  if (const auto truth = dataset.ground_truth(first)) return *truth;
  if (const auto odometry = dataset.odometry(first)) return *odometry;
  return Eigen::Isometry3d::Identity();
}

/// The matcher and sampler of one worker, and the wide-basin matcher it recovers with.
struct Worker {
  std::unique_ptr<Matcher> matcher;
  /// What recovers an untrusted step: the matcher with its wide basin (mlndt, fbmlndt), else the
  /// matcher itself from the other starts; null when recovery is off.
  std::unique_ptr<Matcher> recovery;
  bool wide_basin = false;
  std::unique_ptr<Sampler> sampler;
  const OdometrySettings& settings;
  const PointCloud* matcher_reference = nullptr;  ///< what `matcher` was last given (its model's source)

  explicit Worker(const OdometrySettings& s)
      : matcher(s.registration.matcher.make()), sampler(s.registration.sampler()), settings(s) {
    if (!s.recover) return;
    const MatcherFactory& wide = s.registration.matcher.make_wide;
    wide_basin = static_cast<bool>(wide);
    recovery = wide ? wide() : s.registration.matcher.make();
  }

  /// The first registration from `guess`, assessed on its own (absolute checks).
  OdometryStep first_try(const PointCloud& reference, const PointCloud& input, const Eigen::Isometry3d& guess,
                         std::uint64_t seed) {
    Rng rng(seed);
    const PairMatch m = match_pair(*matcher, *sampler, reference, input, guess, rng, settings.quality);
    matcher_reference = &reference;
    OdometryStep step = to_step(m, reference, guess);
    step.first_trust = step.quality.trust;
    return step;
  }

  /// An untrusted step: the wide basin from each of `starts` (the guess first) until a registration
  /// is trusted; when none is, the step chains one of the registrations whose only flaw is their fit
  /// (suspect_choice.hpp), else `starts.back()` (the last trusted motion), and stays untrusted. The sequence
  /// check only triggers this search: the wide basin's answer is judged on its own
  /// (registration_quality.hpp), since a step may rightly overlap less than its neighbours (a corner, an open
  /// space; measured on the campus: right poses 0.70 where the median is 0.87).
  void recover(OdometryStep& step, const PointCloud& reference, const PointCloud& input,
               const std::vector<Eigen::Isometry3d>& starts, std::uint64_t seed) {
    if (step.trusted() || !recovery || starts.empty()) return;  // recovery: null when it is off
    double seconds = step.seconds;
    // The registrations whose only flaw is their fit: converged, enough overlap, every direction
    // constrained. The first registration counts as it was judged on its own (a sequence check may
    // have flagged an absolutely sound one).
    std::vector<OdometryStep> suspects;
    const auto consider = [&](const OdometryStep& candidate, Trust absolute) {
      if (candidate.converged && (absolute == Trust::kSuspect || absolute == Trust::kOk))
        suspects.push_back(candidate);
    };
    consider(step, step.first_trust);
    std::vector<Eigen::Isometry3d> tries;
    for (const Eigen::Isometry3d& start : starts)
      if (wide_basin || !start.isApprox(step.guess, 1e-12)) tries.push_back(start);  // else tried already
    // One sample for every start (the first try's: the same seed) and one reference model: the first
    // try's when the recovery matcher builds the same one.
    SampledInput sample;
    if (!tries.empty()) {
      Rng rng(seed);
      sample = sample_input(*sampler, input, rng);
      const auto model_start = std::chrono::steady_clock::now();
      if (&reference != matcher_reference || !recovery->share_reference(*matcher))
        recovery->set_reference(reference);
      seconds += sample.seconds +
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - model_start).count();
    }
    for (const Eigen::Isometry3d& start : tries) {
      const PairMatch w = align_sample(*recovery, sample, start, settings.quality);
      OdometryStep again = to_step(w, reference, step.guess);
      seconds += again.seconds;
      if (again.trusted()) {
        again.first_trust = step.first_trust;
        again.recovery = wide_basin ? "wide_basin" : "restart";
        again.seconds = seconds;
        step = std::move(again);
        return;
      }
      consider(again, again.quality.trust);
    }
    if (!suspects.empty()) {
      // Nothing trusted, but registrations whose only flaw is their fit: evidence from the scans,
      // where the prior (the guess, the last trusted motion) has none. The scans choose a band of
      // fits, the prior chooses inside it (suspect_choice.hpp). The step stays untrusted.
      std::vector<SuspectCandidate> candidates;
      for (const OdometryStep& s : suspects) candidates.push_back({s.relative, s.quality.fit_ratio});
      const std::size_t chosen = choose_suspect(candidates, input, step.guess, kSuspectFitBand);
      const Trust first = step.first_trust;
      step = std::move(suspects[chosen]);
      step.first_trust = first;
      step.quality.trust = Trust::kSuspect;
      step.recovery = "least_suspect";
    } else {
      step.recovery = starts.back().isApprox(step.guess, 1e-12) ? "guess" : "last_motion";
      step.relative = starts.back();
    }
    step.seconds = seconds;
  }

 private:
  OdometryStep to_step(const PairMatch& m, const PointCloud& reference,
                       const Eigen::Isometry3d& guess) const {
    OdometryStep step;
    step.relative = m.result.T;
    step.guess = guess;
    step.hessian = m.result.H;
    step.converged = m.result.converged;
    step.iterations = m.result.iterations;
    step.score = m.result.score;
    step.matched_points = m.result.matched_points;
    step.reference_points = reference.size();
    step.seconds = m.result.seconds + m.reference_seconds + m.sampling_seconds;
    step.status = to_string(m.result.why);
    step.fallback = m.result.fallback;
    step.quality = m.result.quality;
    if (!step.relative.matrix().allFinite()) {  // never chain NaN: keep the guess, say so
      step.relative = guess;
      step.converged = false;
      step.status += " (non-finite result replaced by the guess)";
      step.quality.trust = Trust::kNotConverged;
      step.quality.reason = "non-finite result";
    }
    return step;
  }
};

/// Where the recovery of step k starts its wide-basin searches: the guess, then (constant velocity)
/// no motion (a vehicle that stopped between keyframes) and the last trusted motion unscaled, which is
/// also the motion chained when nothing is trusted (the guess for the odometry guess). Consecutive
/// repeats are left out.
std::vector<Eigen::Isometry3d> recovery_starts(const OdometrySettings& s, const Eigen::Isometry3d& guess,
                                               const Eigen::Isometry3d& last_motion) {
  std::vector<Eigen::Isometry3d> starts{guess};
  if (s.guess == OdometryGuess::odometry) return starts;
  for (const Eigen::Isometry3d& other : {Eigen::Isometry3d(Eigen::Isometry3d::Identity()), last_motion})
    if (!other.isApprox(starts.back(), 1e-9)) starts.push_back(other);
  return starts;
}

/// Calls the progress callback one finished step at a time.
class StepCounter {
 public:
  StepCounter(const OdometryProgress& progress, std::size_t total) : progress_(progress), total_(total) {}
  void tick() {
    if (!progress_) return;
    const std::lock_guard<std::mutex> lock(mutex_);
    progress_(++done_, total_);
  }

 private:
  const OdometryProgress& progress_;
  std::size_t total_;
  std::size_t done_ = 0;
  std::mutex mutex_;
};

/// Guess odometry + map scan: the registrations are independent; scans are loaded and registered
/// kChunk at a time, in parallel. Per-step seeds make the result independent of the thread count.
std::vector<OdometryStep> parallel_steps(const Dataset& dataset, const OdometrySettings& s, std::size_t first,
                                         std::size_t count, const std::vector<Eigen::Isometry3d>& odometry,
                                         const std::vector<std::uint64_t>& seeds, StepCounter& counter) {
  std::vector<OdometryStep> steps(count - 1);
  SequenceTrust trust;
  PointCloud previous = load_sequence_scan(dataset, first, s.min_range);
  for (std::size_t begin = 1; begin < count; begin += kChunk) {
    const std::size_t end = std::min(count, begin + kChunk);
    std::vector<PointCloud> chunk(end - begin);
    tbb::parallel_for(begin, end, [&](std::size_t k) {
      chunk[k - begin] = load_sequence_scan(dataset, first + k, s.min_range);
    });
    tbb::parallel_for(begin, end, [&](std::size_t k) {
      const PointCloud& reference = k == begin ? previous : chunk[k - 1 - begin];
      Worker worker(s);
      steps[k - 1] =
          worker.first_try(reference, chunk[k - begin], relative(odometry[k - 1], odometry[k]), seeds[k]);
      counter.tick();
    });
    // The sequence check in sequence order, then the recovery of what is not trusted (independent
    // steps again: the wide basin's answer is judged on its own).
    std::vector<std::size_t> untrusted;
    for (std::size_t k = begin; k < end; ++k) {
      trust.check(steps[k - 1].quality);
      trust.record(steps[k - 1].quality);
      if (!steps[k - 1].trusted()) untrusted.push_back(k);
    }
    tbb::parallel_for(std::size_t{0}, untrusted.size(), [&](std::size_t u) {
      const std::size_t k = untrusted[u];
      const PointCloud& reference = k == begin ? previous : chunk[k - 1 - begin];
      Worker worker(s);
      worker.recover(steps[k - 1], reference, chunk[k - begin], {steps[k - 1].guess}, seeds[k]);
    });
    previous = std::move(chunk.back());
  }
  return steps;
}

/// Waits for a prefetch on every way out, so that an exception never destroys a running task_group.
struct WaitOnExit {
  tbb::task_group& group;
  ~WaitOnExit() {
    try {
      group.wait();
    } catch (...) {  // the exception that is already on its way matters more
    }
  }
};

/// Any guess and map: one registration after the other (the guess or the map needs the previous
/// result); the next scan is loaded while the current one is registered.
std::vector<OdometryStep> sequential_steps(const Dataset& dataset, const OdometrySettings& s,
                                           std::size_t first, std::size_t count,
                                           const std::vector<Eigen::Isometry3d>& odometry,
                                           const std::vector<std::uint64_t>& seeds, StepCounter& counter) {
  Worker worker(s);
  SequenceTrust trust;
  Eigen::Isometry3d last_trusted = Eigen::Isometry3d::Identity();  // the last trusted relative motion
  std::vector<OdometryStep> steps;
  std::deque<PointCloud> window;               // the last scans, oldest first
  std::deque<Eigen::Isometry3d> window_poses;  // their chained poses (frame of the sequence's first scan)
  window.push_back(load_sequence_scan(dataset, first, s.min_range));
  window_poses.push_back(Eigen::Isometry3d::Identity());
  PointCloud next;
  if (count > 1) next = load_sequence_scan(dataset, first + 1, s.min_range);
  for (std::size_t k = 1; k < count; ++k) {
    PointCloud input = std::move(next);
    tbb::task_group prefetch;
    const WaitOnExit wait_on_exit{prefetch};
    if (k + 1 < count) prefetch.run([&] { next = load_sequence_scan(dataset, first + k + 1, s.min_range); });
    Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
    if (s.guess == OdometryGuess::odometry) guess = relative(odometry[k - 1], odometry[k]);
    if (s.guess == OdometryGuess::constant_velocity)
      guess = scale_motion(last_trusted, time_ratio(dataset, first + k));
    const Eigen::Isometry3d& previous_pose = window_poses.back();
    if (s.map == OdometryMap::local_map && window.size() > 1) {
      std::vector<const PointCloud*> clouds;
      std::vector<Eigen::Isometry3d> poses;  // scan i − 1 ← scan j
      for (std::size_t j = 0; j < window.size(); ++j) {
        clouds.push_back(&window[j]);
        poses.push_back(relative(previous_pose, window_poses[j]));
      }
      const PointCloud map = merge_local_map(clouds, poses, s.local_map_max_points, s.local_map_voxel);
      steps.push_back(worker.first_try(map, input, guess, seeds[k]));
      trust.check(steps.back().quality);
      worker.recover(steps.back(), map, input, recovery_starts(s, guess, last_trusted), seeds[k]);
    } else {
      steps.push_back(worker.first_try(window.back(), input, guess, seeds[k]));
      trust.check(steps.back().quality);
      worker.recover(steps.back(), window.back(), input, recovery_starts(s, guess, last_trusted), seeds[k]);
    }
    trust.record(steps.back().quality);
    if (steps.back().trusted()) last_trusted = steps.back().relative;
    // An untrusted step places its scan by a registration we do not believe: the older scans of the
    // window are then placed against it by that same doubtful motion, so the map starts again from
    // this scan alone (a wrong step would otherwise fit the map it made and pass the trust checks).
    const std::size_t keep =
        s.map == OdometryMap::local_map && steps.back().trusted() ? s.local_map_scans : 1;
    window_poses.push_back(previous_pose * steps.back().relative);
    window.push_back(std::move(input));
    while (window.size() > keep) {
      window.pop_front();
      window_poses.pop_front();
    }
    counter.tick();
    prefetch.wait();
  }
  return steps;
}

}  // namespace

PointCloud load_sequence_scan(const Dataset& dataset, std::size_t i, double min_range) {
  PointCloud scan = dataset.scan(i);
  if (!(min_range > 0.0)) return scan;
  const float squared = static_cast<float>(min_range * min_range);
  std::vector<std::size_t> keep;
  keep.reserve(scan.size());
  for (std::size_t j = 0; j < scan.size(); ++j)
    if (scan[j].squaredNorm() >= squared) keep.push_back(j);
  return scan.subset(keep);
}

std::size_t OdometryResult::untrusted() const {
  return static_cast<std::size_t>(
      std::count_if(steps.begin(), steps.end(), [](const OdometryStep& s) { return !s.trusted(); }));
}

std::size_t OdometryResult::recovered() const {
  return static_cast<std::size_t>(std::count_if(steps.begin(), steps.end(), [](const OdometryStep& s) {
    return s.recovery == "wide_basin" || s.recovery == "restart";
  }));
}

OdometryResult run_odometry(const Dataset& dataset, const OdometrySettings& settings, std::size_t first,
                            std::size_t count, const OdometryProgress& progress) {
  if (const std::string why = settings.problem(); !why.empty())
    throw InputError("odometry settings", "", why);
  if (std::string why; !settings.quality.valid(&why)) throw InputError("odometry settings", "", why);
  if (count < 1) throw InputError(dataset_label(dataset), "", "an odometry run needs at least one scan");
  if (first >= dataset.size() || count > dataset.size() - first)
    throw InputError(dataset_label(dataset), "",
                     "scans " + std::to_string(first) + "–" + std::to_string(first + count - 1) +
                         " go past the dataset's " + std::to_string(dataset.size()) + " scans");
  const std::vector<Eigen::Isometry3d> odometry = odometry_poses(dataset, settings, first, count);
  std::vector<std::uint64_t> seeds = settings.seeds;
  if (seeds.empty()) {
    Rng master(settings.seed);
    seeds.resize(count);
    for (auto& seed : seeds) seed = master.bits();
  } else if (seeds.size() < count) {
    throw InputError("odometry settings", "",
                     "the given seeds are " + std::to_string(seeds.size()) + ", fewer than the " +
                         std::to_string(count) + " scans");
  }

  StepCounter counter(progress, count - 1);
  OdometryResult result;
  if (count > 1) {
    const bool independent =
        settings.parallel && settings.guess == OdometryGuess::odometry && settings.map == OdometryMap::scan;
    result.steps = independent ? parallel_steps(dataset, settings, first, count, odometry, seeds, counter)
                               : sequential_steps(dataset, settings, first, count, odometry, seeds, counter);
  }
  result.poses.push_back(start_pose(dataset, settings, first));
  for (const OdometryStep& step : result.steps) result.poses.push_back(result.poses.back() * step.relative);
  return result;
}

}  // namespace sextant
