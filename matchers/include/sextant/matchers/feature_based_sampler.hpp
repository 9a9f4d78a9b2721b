#pragma once
// Feature-based sampling and FbML-NDT (§3.3.1.3, Table 3.2): the input scan is split into cells,
// RANSAC finds the plane inliers in each cell, and only those points are matched by ML-NDT.
//
//   sampler `fbs`:     settings = plane extraction settings (features/extraction.hpp)
//   matcher `fbmlndt`: the mlndt keys, plus `features:` (plane extraction settings) and `seed`
//                      (the RANSAC stream, fixed per align call so results are deterministic).
//                      align() takes the whole input scan and samples it with fbs itself.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sextant/features/extraction.hpp"
#include "sextant/matchers/matcher.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/sampler.hpp"

namespace sextant {

/// `fbs`: the indices of the per-cell RANSAC plane inliers (Table 3.2, feature extraction process).
class FeatureBasedSampler final : public Sampler {
 public:
  explicit FeatureBasedSampler(PlaneExtractionSettings settings = {});
  std::string name() const override { return "fbs"; }
  std::vector<std::size_t> select(const PointCloud& input, Rng& rng) const override;

 private:
  PlaneExtractionSettings settings_;
};

std::unique_ptr<Sampler> create_feature_based_sampler(const YAML::Node& settings, const std::string& file);

struct FbmlndtSettings {
  MlndtSettings mlndt;               ///< the registration process (Table 3.2)
  PlaneExtractionSettings features;  ///< the feature extraction process
  std::uint64_t seed = 1;            ///< RANSAC seed used at every align() call
  bool valid(std::string* why) const;
};

FbmlndtSettings read_fbmlndt_settings(const YAML::Node& node, const std::string& file);

/// ML-NDT whose input points are the fbs sample of the input scan.
class FbmlndtMatcher final : public Matcher {
 public:
  explicit FbmlndtMatcher(FbmlndtSettings settings = {});
  std::string name() const override { return "fbmlndt"; }
  void set_reference(const PointCloud& reference) override { mlndt_.set_reference(reference); }
  /// `input` is the whole scan; an input without planes gives a result with converged = false.
  RegistrationResult align(const PointCloud& input, const Eigen::Isometry3d& initial) override;
  /// Points of the last input that were matched (the fbs sample).
  std::size_t last_sample_size() const { return last_sample_size_; }

 private:
  FbmlndtSettings settings_;
  MlndtMatcher mlndt_;
  std::size_t last_sample_size_ = 0;
};

std::unique_ptr<Matcher> create_fbmlndt_matcher(const YAML::Node& settings, const std::string& file);

}  // namespace sextant
