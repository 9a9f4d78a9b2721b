// SEIF's covariance for data association (§4.2.4; Thrun et al., "Simultaneous localization and
// mapping with sparse extended information filters", 2004, correspondence test): the pose and
// the landmarks asked for, conditioned on everything outside their Markov blanket.
#include <Eigen/Cholesky>

#include <algorithm>
#include <deque>
#include <map>
#include <stdexcept>
#include <string>

#include "information_ops.hpp"
#include "sextant/filters/seif.hpp"

namespace sextant {
namespace {

using detail::kPose;

bool contains(const std::vector<int>& set, int v) {
  return std::find(set.begin(), set.end(), v) != set.end();
}

void insert(std::vector<int>& set, int v) {
  if (!contains(set, v)) set.push_back(v);
}

/// The variables on a shortest path (breadth first over links) from `from` to any member of
/// `targets`, excluding both ends; empty when they are linked or not connected at all.
std::vector<int> path_between(const BlockInformationMatrix& omega, int from,
                              const std::vector<int>& targets) {
  std::map<int, int> parent{{from, from}};
  std::deque<int> queue{from};
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop_front();
    for (int n : omega.neighbours(v)) {
      if (parent.count(n)) continue;
      parent[n] = v;
      if (contains(targets, n)) {
        std::vector<int> path;
        for (int k = v; k != from; k = parent[k]) path.push_back(k);
        return path;
      }
      queue.push_back(n);
    }
  }
  return {};
}

}  // namespace

std::vector<int> Seif::markov_blanket(const std::vector<int>& landmarks) const {
  std::vector<int> blanket{kPose};
  for (int j : landmarks) {
    if (j < 0 || j >= num_landmarks())
      throw std::out_of_range("markov_blanket: no landmark " + std::to_string(j));
    insert(blanket, j + 1);
  }
  for (int n : omega_.neighbours(kPose)) insert(blanket, n);
  const std::vector<int> core = blanket;  // the pose, the landmarks asked for, the active landmarks
  for (int j : landmarks) {
    const std::vector<int> neighbours = omega_.neighbours(j + 1);
    std::vector<int> others = core;
    others.erase(std::find(others.begin(), others.end(), j + 1));
    const bool joined =
        std::any_of(neighbours.begin(), neighbours.end(), [&](int n) { return contains(others, n); });
    for (int n : neighbours) insert(blanket, n);
    if (!joined)
      for (int v : path_between(omega_, j + 1, others)) insert(blanket, v);
  }
  return blanket;
}

FilterDiagnostics Seif::diagnostics() const {
  FilterDiagnostics d;
  d.information = &omega_;
  d.approximate_covariance = true;
  return d;
}

Eigen::MatrixXd Seif::joint_covariance(const std::vector<int>& landmarks) const {
  const std::vector<int> blanket = markov_blanket(landmarks);
  const Eigen::MatrixXd omega_bb = omega_.gather(blanket, false);
  const Eigen::MatrixXd sigma_bb =
      omega_bb.llt().solve(Eigen::MatrixXd::Identity(omega_bb.rows(), omega_bb.cols()));
  std::map<int, Eigen::Index> local;  // variable → first row in the gathered block
  Eigen::Index row = 0;
  for (int v : blanket) local[v] = row, row += omega_.dim(v);
  std::vector<Eigen::Index> rows;
  for (int k = 0; k < model_->pose_dim(); ++k) rows.push_back(k);
  for (int j : landmarks)
    for (int k = 0; k < model_->landmark_dim(); ++k) rows.push_back(local[j + 1] + k);
  return sigma_bb(rows, rows);
}

}  // namespace sextant
