// Remembered ML-NDT runs (run_memo.hpp).
#include "mlndt/run_memo.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

namespace sextant::mlndt_detail {

namespace {

/// The same bits (a run from −0 and one from +0 could differ in the sign of a zero).
bool same_points(const std::vector<Eigen::Vector3f>& a, PointsView b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]) == 0);
}

}  // namespace

void RunMemo::keep_only(const std::shared_ptr<const MlndtModel>& model, const PointCloud& input) {
  if (model == model_ && same_points(input_, input.points())) return;
  runs_.clear();
  model_ = model;
  input_.assign(input.points().begin(), input.points().end());
}

const RegistrationResult* RunMemo::find(int objective, const Eigen::Isometry3d& start) const {
  const auto hit = std::find_if(runs_.begin(), runs_.end(), [&](const Run& r) {
    return r.objective == objective && r.start.matrix() == start.matrix();
  });
  return hit == runs_.end() ? nullptr : &hit->result;
}

void RunMemo::add(int objective, const Eigen::Isometry3d& start, RegistrationResult result) {
  if (find(objective, start) != nullptr) return;
  if (runs_.size() >= kCapacity) runs_.erase(runs_.begin());
  result.alternatives.clear();
  runs_.push_back(Run{objective, start, std::move(result)});
}

void RunMemo::clear() {
  runs_.clear();
  model_.reset();
  input_.clear();
}

}  // namespace sextant::mlndt_detail
