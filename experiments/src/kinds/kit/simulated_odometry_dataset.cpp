#include "kit/simulated_odometry_dataset.hpp"

#include "sextant/core/error.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/synth/odometry.hpp"

namespace sextant {

SimulatedOdometryDataset::SimulatedOdometryDataset(std::unique_ptr<Dataset> inner,
                                                   const synth::OdometrySettings& settings,
                                                   std::uint64_t seed)
    : inner_(std::move(inner)), metadata_(inner_->metadata()) {
  std::vector<Eigen::Isometry3d> reference;
  for (std::size_t i = 0; i < inner_->size(); ++i) {
    const std::optional<Eigen::Isometry3d> pose = inner_->ground_truth(i);
    if (!pose)
      throw InputError(metadata_.path.string(), "",
                       "simulated_odometry needs a reference pose for every scan; scan " + std::to_string(i) +
                           " has none");
    reference.push_back(*pose);
  }
  Rng rng(seed);
  odometry_ = synth::simulate_odometry(reference, settings, rng);
  if (metadata_.has_odometry)
    metadata_.notes.push_back("the folder's own odometry is replaced by the simulated one");
  metadata_.has_odometry = true;
  metadata_.notes.push_back("odometry simulated from the reference with the '" + settings.model +
                            "' error model (seed " + std::to_string(seed) + "), not measured");
}

std::optional<Eigen::Isometry3d> SimulatedOdometryDataset::odometry(std::size_t i) const {
  if (i >= odometry_.size()) return std::nullopt;
  return odometry_[i];
}

}  // namespace sextant
