#include "sextant/matchers/feature_based_sampler.hpp"

#include <chrono>
#include <utility>

#include "sextant/core/settings_reader.hpp"

namespace sextant {

FeatureBasedSampler::FeatureBasedSampler(PlaneExtractionSettings settings) : settings_(std::move(settings)) {
  std::string why;
  if (!settings_.valid(&why)) throw std::invalid_argument("fbs sampler: " + why);
}

// Table 3.2, feature extraction process: split S into cells, RANSAC per cell, F = the inliers.
std::vector<std::size_t> FeatureBasedSampler::select(const PointCloud& input, Rng& rng) const {
  return extract_cell_planes(input, settings_, rng).cell_inlier_indices();
}

std::unique_ptr<Sampler> create_feature_based_sampler(const YAML::Node& settings, const std::string& file) {
  return std::make_unique<FeatureBasedSampler>(read_plane_extraction_settings(settings, file));
}

bool FbmlndtSettings::valid(std::string* why) const {
  return mlndt.valid(why) && features.valid(why);
}

FbmlndtSettings read_fbmlndt_settings(const YAML::Node& node, const std::string& file) {
  FbmlndtSettings s;
  YAML::Node rest;
  if (node && node.IsMap()) {
    SettingsReader in(node, file);
    in.read("seed", s.seed);
    if (in.has("features")) s.features = read_plane_extraction_settings(in.child("features"), file);
    rest = YAML::Clone(node);  // the remaining keys belong to mlndt (which rejects unknown ones)
    rest.remove("seed");
    rest.remove("features");
  }
  s.mlndt = read_mlndt_settings(rest, file);
  return s;
}

FbmlndtMatcher::FbmlndtMatcher(FbmlndtSettings settings)
    : settings_(std::move(settings)), mlndt_(settings_.mlndt) {
  std::string why;
  if (!settings_.features.valid(&why)) throw std::invalid_argument("fbmlndt: " + why);
}

RegistrationResult FbmlndtMatcher::align(const PointCloud& input, const Eigen::Isometry3d& initial) {
  const auto start = std::chrono::steady_clock::now();
  Rng rng(settings_.seed);
  const PointCloud sample =
      input.subset(extract_cell_planes(input, settings_.features, rng).cell_inlier_indices());
  last_sample_size_ = sample.size();
  RegistrationResult result;
  if (sample.empty()) {
    result.T = initial;
    result.why = input.empty() ? Termination::kEmptyInput : Termination::kTooFewCorrespondences;
  } else {
    result = mlndt_.align(sample, initial);
  }
  result.input_points = sample.size();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::unique_ptr<Matcher> create_fbmlndt_matcher(const YAML::Node& settings, const std::string& file) {
  return std::make_unique<FbmlndtMatcher>(read_fbmlndt_settings(settings, file));
}

}  // namespace sextant
