// FbML-NDT (fbmlndt_matcher.hpp): ML-NDT on the plane inliers, with its fallbacks.
#include "sextant/matchers/fbmlndt_matcher.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <utility>

#include <fmt/format.h>

#include "sextant/core/checked_settings.hpp"
#include "sextant/matchers/registration_quality.hpp"

namespace sextant {

bool FbmlndtSettings::valid(std::string* why) const {
  return mlndt.valid(why) && features.valid(why) && constraints.valid(why) && fallback_gbs.valid(why);
}

FbmlndtMatcher::FbmlndtMatcher(FbmlndtSettings settings)
    : settings_(checked(std::move(settings), "fbmlndt")), mlndt_(settings_.mlndt) {}

RegistrationResult FbmlndtMatcher::align(const PointCloud& input, const Eigen::Isometry3d& initial) {
  const auto start = std::chrono::steady_clock::now();
  Rng rng(settings_.seed);
  const PlaneExtraction features = extract_cell_planes(input, settings_.features, rng);
  std::vector<std::size_t> indices = features.cell_inlier_indices();
  // Fail safe: a feature sample that leaves a pose direction unconstrained gets GBS points.
  last_check_ = check_plane_constraints(features.cell_planes, input, settings_.constraints);
  std::string fallback;
  bool gbs_only = false;  // the sample is the GBS sample (nothing left to verify)
  if (!last_check_.constrains_all && settings_.fallback != FbsFallback::kNone && !input.empty()) {
    const std::vector<std::size_t> gbs = GridSampler(settings_.fallback_gbs).select(input, rng);
    const std::size_t features_kept = indices.size();
    if (settings_.fallback == FbsFallback::kGbs) {
      indices = gbs;
      gbs_only = true;
    } else {
      std::vector<std::size_t> both;
      std::set_union(indices.begin(), indices.end(), gbs.begin(), gbs.end(), std::back_inserter(both));
      indices.swap(both);
    }
    fallback =
        "feature sample degenerate (" + last_check_.reason + "): " +
        (settings_.fallback == FbsFallback::kGbs ? "matched " + std::to_string(indices.size()) + " GBS points"
                                                 : "added " + std::to_string(indices.size() - features_kept) +
                                                       " GBS points to " + std::to_string(features_kept));
  }
  const PointCloud sample = input.subset(indices);
  last_sample_size_ = sample.size();
  RegistrationResult result;
  if (sample.empty()) {
    result.T = initial;
    result.why = input.empty() ? Termination::kEmptyInput : Termination::kTooFewCorrespondences;
  } else {
    result = mlndt_.align(sample, initial);
  }
  result.input_points = sample.size();
  if (settings_.verify && !input.empty() && !gbs_only) verify_on_gbs(input, initial, rng, result, fallback);
  result.fallback = fallback;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void FbmlndtMatcher::verify_on_gbs(const PointCloud& input, const Eigen::Isometry3d& initial, Rng& rng,
                                   RegistrationResult& result, std::string& fallback) {
  const PointCloud gbs = input.subset(GridSampler(settings_.fallback_gbs).select(input, rng));
  if (gbs.empty()) return;
  const auto with = [&](RegistrationResult r) {  // a registration of the GBS points, assessed
    r.input_points = gbs.size();
    r.quality = assess_registration(r, gbs);
    return r;
  };
  const RegistrationResult refined = with(mlndt_.align(gbs, is_finite(result.T) ? result.T : initial));
  const std::string note = fallback.empty() ? "" : fallback + "; ";
  if (refined.quality.trusted()) {
    const double moved = translation_norm(relative(result.T, refined.T));
    if (moved > 0.1)
      fallback =
          note + fmt::format("the feature sample's pose moved {:.2f} m on {} GBS points", moved, gbs.size());
    result = refined;
    return;
  }
  const RegistrationResult plain = with(mlndt_.align(gbs, initial));
  if (plain.quality.trusted()) {
    fallback = note + "the feature sample's pose is not trusted on GBS points (" + refined.quality.reason +
               "): ML-NDT on " + std::to_string(gbs.size()) + " GBS points";
    result = plain;
  }
}

}  // namespace sextant
