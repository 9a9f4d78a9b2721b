// Chained registrations over a sequence (§5.1.3: dead reckoning by a matcher). Each step
// registers scan i (sampled) against scan i − 1 or the local map in scan i − 1's frame, from the
// guess mode's start, and chains the result: pose_i = pose_{i−1} · relative_i.
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "chain_deskew.hpp"
#include "scan_handout.hpp"
#include "sequence_inputs.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/registration_centre.hpp"
#include "sextant/odometry/common_view.hpp"
#include "sextant/odometry/local_map.hpp"
#include "sextant/odometry/odometry.hpp"
#include "sextant/odometry/sequence_trust.hpp"
#include "step_frame.hpp"
#include "step_worker.hpp"

namespace sextant {
namespace {

using namespace odometry_detail;  // this module's private parts (src/*.hpp)

/// Scans loaded and registered together on the parallel path (bounds the memory held).
constexpr std::size_t kChunk = 16;

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

/// With `common_view`, the reference and the input cut to what both sensors see from `guess`
/// (common_view.hpp; `reference_view` is the view of the scan whose sensor stands at the reference's
/// origin). Nothing otherwise, and for scans not in their sensor's frame (no sensor could stand at the
/// origin: registration_centre.hpp): the step registers the clouds as they are, without a copy.
std::optional<std::pair<PointCloud, PointCloud>> what_both_see(
    const PointCloud& reference, const SensorView& reference_view, const PointCloud& input,
    const SensorView& input_view, const Eigen::Isometry3d& guess, bool common_view) {
  if (!common_view || !registration_centre(reference).isZero()) return std::nullopt;
  return sextant::common_view(reference, reference_view, input, input_view, guess);
}

/// The view of each scan where the steps cut to what both sensors see (default views otherwise,
/// which nothing reads).
std::vector<SensorView> views_of(const std::vector<PointCloud>& scans, bool common_view, SensorKind sensor) {
  std::vector<SensorView> views(scans.size());
  if (common_view)
    tbb::parallel_for(std::size_t{0}, views.size(),
                      [&](std::size_t k) { views[k] = sensor_view(scans[k], sensor); });
  return views;
}

/// Guess odometry + map scan: the registrations are independent; scans are loaded and registered
/// kChunk at a time, in parallel. Per-step seeds make the result independent of the thread count.
std::vector<OdometryStep> parallel_steps(const Dataset& dataset, const OdometrySettings& s, std::size_t first,
                                         std::size_t count, const std::vector<Eigen::Isometry3d>& odometry,
                                         const std::vector<std::uint64_t>& seeds, StepCounter& counter,
                                         ScanHandout& handout, OdometryResult& result) {
  std::vector<OdometryStep> steps(count - 1);
  SequenceTrust trust;
  PointCloud previous = load_sequence_scan(dataset, first, s.min_range, &result.loads[0]);
  result.sensor = resolve_sensor(s.sensor, previous);
  // Scan k's sweep at the odometry's velocity from scan k − 1 (scan 0: to scan 1).
  const auto deskew_by_odometry = [&](std::size_t k, PointCloud& scan) {
    if (!s.deskew) return;
    const std::size_t from = k == 0 ? 0 : k - 1;
    result.sweeps[k] = sweep_between(dataset, first + from, first + from + 1, scan,
                                     relative(odometry[from], odometry[from + 1]));
    scan = deskew_scan(scan, result.sweeps[k]);
  };
  // The odometry tells the typical step before any registration: the median of its increments.
  MotionScale scale(count);
  for (std::size_t k = 1; k < count; ++k) scale.record(relative(odometry[k - 1], odometry[k]));
  result.typical_step = scale.typical_step();
  StepContext defaults;
  defaults.rings = result.sensor.kind == SensorKind::spinning;
  defaults.quality = platform_tolerance(s.quality, s.platform, result.typical_step);
  SensorView previous_view = s.common_view ? sensor_view(previous, result.sensor.kind) : SensorView{};
  result.timed_scans += previous.has_time() ? 1 : 0;
  deskew_by_odometry(0, previous);
  handout.first(previous);
  for (std::size_t begin = 1; begin < count; begin += kChunk) {
    const std::size_t end = std::min(count, begin + kChunk);
    std::vector<PointCloud> chunk(end - begin);
    tbb::parallel_for(begin, end, [&](std::size_t k) {
      chunk[k - begin] = load_sequence_scan(dataset, first + k, s.min_range, &result.loads[k]);
    });
    // Each sensor's view from the scan as it was taken, then the scans deskewed.
    const std::vector<SensorView> views = views_of(chunk, s.common_view, result.sensor.kind);
    for (const PointCloud& scan : chunk) result.timed_scans += scan.has_time() ? 1 : 0;
    tbb::parallel_for(begin, end, [&](std::size_t k) { deskew_by_odometry(k, chunk[k - begin]); });
    // Each step's clouds cut to what both sensors see (with common_view) and its frame, until its
    // recovery is done (step_frame.hpp).
    std::vector<std::optional<std::pair<PointCloud, PointCloud>>> seen(end - begin);
    std::vector<std::unique_ptr<StepFrame>> frames(end - begin);
    tbb::parallel_for(begin, end, [&](std::size_t k) {
      const Eigen::Isometry3d guess = relative(odometry[k - 1], odometry[k]);
      const PointCloud& reference = k == begin ? previous : chunk[k - 1 - begin];
      const PointCloud& input = chunk[k - begin];
      const SensorView& reference_view = k == begin ? previous_view : views[k - 1 - begin];
      const auto& cut = seen[k - begin] =
          what_both_see(reference, reference_view, input, views[k - begin], guess, s.common_view);
      auto& frame = frames[k - begin];
      frame = std::make_unique<StepFrame>(cut ? cut->first : reference, cut ? cut->second : input);
      StepWorker worker(s);
      StepContext context = defaults;
      context.sensor_frame = frame->sensor_frame();
      steps[k - 1] =
          worker.first_try(frame->reference(), frame->input(), frame->local(guess), seeds[k], context);
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
      const StepFrame& frame = *frames[k - begin];
      StepWorker worker(s);
      StepContext context = defaults;
      context.sensor_frame = frame.sensor_frame();
      worker.set_context(std::move(context));
      worker.recover(steps[k - 1], frame.reference(), frame.input(), {steps[k - 1].guess}, seeds[k], trust);
    });
    for (std::size_t k = begin; k < end; ++k) frames[k - begin]->to_coordinates(steps[k - 1]);
    for (std::size_t k = begin; k < end; ++k) handout.next(k, chunk[k - begin], steps[k - 1]);
    previous = std::move(chunk.back());
    previous_view = views.back();
  }
  result.tolerance = *defaults.quality;
  return steps;
}

/// One step of the sequential path in its frame (step_frame.hpp): the first try from `guess` (and
/// the context's other priors, in the scans' coordinates), the sequence check, the recovery from
/// `starts`; the step comes back in the scans' coordinates.
OdometryStep register_step(StepWorker& worker, const SequenceTrust& trust, const PointCloud& reference,
                           const PointCloud& input, const Eigen::Isometry3d& guess, StepContext context,
                           const std::vector<Eigen::Isometry3d>& starts, std::uint64_t seed) {
  const StepFrame frame(reference, input);
  context.other_priors = frame.local(std::move(context.other_priors));
  context.sensor_frame = frame.sensor_frame();
  OdometryStep step =
      worker.first_try(frame.reference(), frame.input(), frame.local(guess), seed, std::move(context));
  trust.check(step.quality);
  worker.recover(step, frame.reference(), frame.input(), frame.local(starts), seed, trust);
  frame.to_coordinates(step);
  return step;
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
                                           const std::vector<std::uint64_t>& seeds, StepCounter& counter,
                                           ScanHandout& handout, OdometryResult& result) {
  StepWorker worker(s);
  SequenceTrust trust;
  MotionScale scale;  // the platform's typical step, from its trusted steps
  // The motion constant velocity continues: the last trusted one; with --no-recover the last chained
  // one, as a plain chain continues it (its trust is counted, not acted on).
  Eigen::Isometry3d last_motion = Eigen::Isometry3d::Identity();
  bool any_trusted = false;
  std::vector<OdometryStep> steps;
  std::deque<PointCloud> window;               // the last scans, oldest first
  std::deque<Eigen::Isometry3d> window_poses;  // their chained poses (frame of the sequence's first scan)
  // A scan and its sensor's view (where the steps cut to what both sensors see), loaded ahead.
  const auto load = [&](std::size_t k, PointCloud& scan, SensorView& view) {
    scan = load_sequence_scan(dataset, first + k, s.min_range, &result.loads[k]);
    if (s.common_view) view = sensor_view(scan, result.sensor.kind);
  };
  SensorView last_view, next_view;  // of window.back() and of `next`
  window.push_back(load_sequence_scan(dataset, first, s.min_range, &result.loads[0]));
  window_poses.push_back(Eigen::Isometry3d::Identity());
  result.sensor = resolve_sensor(s.sensor, window.back());
  if (s.common_view) last_view = sensor_view(window.back(), result.sensor.kind);
  // Scans whose points carry time deskewed by the odometry's motion, else by the velocity learned.
  ChainDeskew deskew(dataset, first, s.deskew, result);
  const bool odometer = s.guess == OdometryGuess::odometry;
  window.back() =
      deskew.take(0, std::move(window.back()),
                  odometer && count > 1 ? std::optional(relative(odometry[0], odometry[1])) : std::nullopt);
  handout.first(window.back());  // as registered: deskewed when a velocity is known by now
  PointCloud next;
  if (count > 1) load(1, next, next_view);
  for (std::size_t k = 1; k < count; ++k) {
    PointCloud input = std::move(next);
    const SensorView input_view = next_view;
    tbb::task_group prefetch;
    const WaitOnExit wait_on_exit{prefetch};
    if (k + 1 < count) prefetch.run([&] { load(k + 1, next, next_view); });
    Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
    if (s.guess == OdometryGuess::odometry) guess = relative(odometry[k - 1], odometry[k]);
    // Constant velocity: no motion is known before the first trusted step, and after an untrusted step
    // (with recovery on) the motion the guess continues is an older one's, not the last step's; so an
    // answer of no motion needs confirming (and, with recovery on, the first registration searches):
    // MulRan 0–107 as 16 rings counted 3 on, seed 3, after seven untrusted steps continued 2.7 m per
    // keyframe where the car moved 5.7, and the registration from there was trusted 3.6 m short. Unless
    // every registration is to be chained as it comes (--no-recover), where velocity × Δt lies far from
    // the last motion per scan (the vehicle accelerated, or the keyframes follow distance, not time)
    // both are priors.
    StepContext context;
    context.rings = result.sensor.kind == SensorKind::spinning;
    context.quality = platform_tolerance(s.quality, s.platform, scale.typical_step());
    // The fit bar was measured on spinning lidars, whose right poses fit about as predicted; another
    // sensor's is in the units of its own right steps: raised by the median fit of its trusted steps,
    // never lowered (fit_bar).
    if (!context.rings) context.quality->max_fit_ratio = fit_bar(s.quality.max_fit_ratio, trust.median_fit());
    if (s.guess == OdometryGuess::constant_velocity) {
      guess = scale_motion(last_motion, time_ratio(dataset, first + k));
      context.search = !any_trusted || (s.recover && !steps.back().trusted());
      // The velocity is the previous step's when that step is trusted: then the platform's acceleration
      // bounds how far this step can depart from the guess.
      if (!steps.empty() && steps.back().trusted()) {
        context.reach = step_reach(dataset, first + k, s.max_acceleration);
        context.last_turn = last_motion.linear();
      }
      if (s.recover && any_trusted && far_apart(guess, last_motion, *context.quality))
        context.other_priors.push_back(last_motion);
    }
    // An odometer's guess is a prior of its own; the platform's reach bounds a step after a trusted one.
    context.unbounded = s.guess != OdometryGuess::odometry && !std::isfinite(context.reach);
    input = deskew.take(k, std::move(input), odometer ? std::optional(guess) : std::nullopt);
    const Eigen::Isometry3d& previous_pose = window_poses.back();
    // The reference: the local map of the window in scan i − 1's frame, or scan i − 1.
    const bool local_map = s.map == OdometryMap::local_map && window.size() > 1;
    const auto merge_map = [&] {
      std::vector<const PointCloud*> clouds;
      std::vector<Eigen::Isometry3d> poses;  // scan i − 1 ← scan j
      for (std::size_t j = 0; j < window.size(); ++j) {
        clouds.push_back(&window[j]);
        poses.push_back(relative(previous_pose, window_poses[j]));
      }
      return merge_local_map(clouds, poses, s.local_map_max_points, s.local_map_voxel);
    };
    PointCloud map = local_map ? merge_map() : PointCloud();
    const auto register_input = [&](const PointCloud& scan, const Eigen::Isometry3d& from) {
      const PointCloud& reference = local_map ? map : window.back();
      const auto cut = what_both_see(reference, last_view, scan, input_view, from, s.common_view);
      return register_step(worker, trust, cut ? cut->first : reference, cut ? cut->second : scan, from,
                           context, recovery_starts(s, from, last_motion), seeds[k]);
    };
    steps.push_back(register_input(input, guess));
    // The velocity the step measured, when it departs from the one the scan was deskewed by: the scan
    // deskewed by it and registered again from the step (chain_deskew.hpp).
    const bool believed = steps.back().trusted() || !s.recover;
    bool map_changed = false;
    if (believed && !odometer)
      if (std::optional<PointCloud> again =
              deskew.deskewed_again(k, steps.back().relative, window, map_changed)) {
        if (map_changed && local_map) map = merge_map();
        OdometryStep second = register_input(*again, steps.back().relative);
        ++result.registered_again;
        if (second.trusted() || !s.recover) {
          second.guess = steps.back().guess;
          second.seconds += steps.back().seconds;
          steps.back() = std::move(second);
          input = std::move(*again);
        } else {
          deskew.keep_first(k);
        }
      }
    trust.record(steps.back().quality);
    if (steps.back().trusted()) scale.record(steps.back().relative);
    if (steps.back().trusted() || !s.recover) last_motion = steps.back().relative;
    any_trusted = any_trusted || steps.back().trusted();
    // An untrusted step places its scan by a registration we do not believe: the older scans of the
    // window are then placed against it by that same doubtful motion, so the map starts again from
    // this scan alone (a wrong step would otherwise fit the map it made and pass the trust checks).
    const std::size_t keep =
        s.map == OdometryMap::local_map && steps.back().trusted() ? s.local_map_scans : 1;
    window_poses.push_back(previous_pose * steps.back().relative);
    handout.next(k, input, steps.back());
    window.push_back(std::move(input));
    if (steps.back().trusted() || !s.recover) deskew.learn(k, steps.back().relative, window);
    last_view = input_view;
    while (window.size() > keep) {
      window.pop_front();
      window_poses.pop_front();
    }
    deskew.keep_last(window.size());
    counter.tick();
    prefetch.wait();
  }
  result.typical_step = scale.typical_step();
  result.tolerance = platform_tolerance(s.quality, s.platform, result.typical_step);
  return steps;
}

}  // namespace

OdometryResult run_odometry(const Dataset& dataset, const OdometrySettings& settings, std::size_t first,
                            std::size_t count, const OdometryProgress& progress,
                            const OdometryScanObserver& observe) {
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
  result.loads.resize(count);
  const Eigen::Isometry3d start = start_pose(dataset, settings, first);
  ScanHandout handout(observe, start);
  if (settings.deskew) result.sweeps.resize(count);
  if (count > 1) {
    const bool independent =
        settings.parallel && settings.guess == OdometryGuess::odometry && settings.map == OdometryMap::scan;
    result.steps =
        independent
            ? parallel_steps(dataset, settings, first, count, odometry, seeds, counter, handout, result)
            : sequential_steps(dataset, settings, first, count, odometry, seeds, counter, handout, result);
  } else {
    const PointCloud scan = load_sequence_scan(dataset, first, settings.min_range, &result.loads[0]);
    handout.first(scan);
    result.sensor = resolve_sensor(settings.sensor, scan);
    result.timed_scans = scan.has_time() ? 1 : 0;
    result.tolerance = platform_tolerance(settings.quality, settings.platform, std::nullopt);
  }
  result.poses.push_back(start);
  for (const OdometryStep& step : result.steps) result.poses.push_back(result.poses.back() * step.relative);
  return result;
}

}  // namespace sextant
