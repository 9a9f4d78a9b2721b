#pragma once
// The shared real pairs of data/ (data/README.md) and campus pairs, with each pair's reference pose
// and the guess a user has, for the benchmark programs that compare whole registrations. Reference
// poses: ground truth for the Velodyne pair, the uos scans (3DTK's .frames) and the campus; the
// cross-method consensus (point-to-plane ICP from the guess, which tests/matchers/real_pairs_test.cpp
// shows agrees with ML-NDT and PCL's GICP to 3 cm / 0.1°) for the KITTI pair, whose derived ground
// truth is withdrawn, and for PCL's room scans, which have none.
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/uos.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/sampler.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant::bench {

struct Pair {
  std::string name;
  PointCloud reference, input;
  Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();  ///< p_ref = truth · p_input
};

inline std::string data(const std::string& path) {
  return std::string(SEXTANT_DATA_DIR) + "/" + path;
}

inline Eigen::Isometry3d read_matrix(const std::string& file) {
  std::ifstream in(file);
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) in >> M(r, c);
  if (!in) throw std::runtime_error("cannot read the 4×4 matrix in " + file);
  return Eigen::Isometry3d(M);
}

/// Point-to-plane ICP from the pair's guess: the consensus reference pose of pairs without ground truth.
inline Eigen::Isometry3d consensus(const Pair& pair) {
  Rng rng(1);
  const auto icp = make_matcher("icp_p2l", YAML::Load("{max_correspondence_distance: 1.0}"), "bench");
  const auto gbs = make_sampler("gbs", YAML::Load("{cell_size: 0.3, max_per_cell: 3}"));
  return match_pair(*icp, *gbs, pair.reference, pair.input, pair.guess, rng).result.T;
}

/// Velodyne, KITTI* (consensus), uos 000-001, room* (consensus, from the tutorial's guess).
inline std::vector<Pair> real_pairs() {
  std::vector<Pair> out;
  out.push_back({"Velodyne", read_cloud(data("velodyne_pair/fast_gicp_251370668.pcd")),
                 read_cloud(data("velodyne_pair/fast_gicp_251371071.pcd")), Eigen::Isometry3d::Identity(),
                 read_matrix(data("velodyne_pair/fast_gicp_relative.txt"))});
  Pair kitti{"KITTI*", read_cloud(data("kitti00_pair/000000.xyz32.bin")),
             read_cloud(data("kitti00_pair/000001.xyz32.bin"))};
  kitti.truth = consensus(kitti);
  out.push_back(kitti);
  const auto frame = [](const char* scan) {
    return read_uos_frames(data(std::string("uos_3dtk/") + scan)).back();
  };
  out.push_back({"uos 000-001", read_uos_scan(data("uos_3dtk/scan000.3d")),
                 read_uos_scan(data("uos_3dtk/scan001.3d")), Eigen::Isometry3d::Identity(),
                 frame("scan000.frames").inverse() * frame("scan001.frames")});
  Pair room{"room*", read_cloud(data("pcl_room_scan/room_scan1.pcd")),
            read_cloud(data("pcl_room_scan/room_scan2.pcd")),
            Eigen::Translation3d(1.79387, 0.720047, 0) * Eigen::AngleAxisd(0.6931, Eigen::Vector3d::UnitZ())};
  room.truth = consensus(room);
  out.push_back(room);
  return out;
}

/// Consecutive scans i → i + 1 of the built-in campus (seed 7) with their ground truth.
inline std::vector<Pair> campus_pairs(const std::vector<std::size_t>& scans) {
  std::vector<Pair> out;
  const synth::Campus campus = synth::generate_campus(synth::CampusSettings{}, 7);
  for (const std::size_t i : scans) {
    out.push_back({"campus " + std::to_string(i), campus.scan(i).cloud, campus.scan(i + 1).cloud,
                   Eigen::Isometry3d::Identity(),
                   relative(campus.ground_truth[i], campus.ground_truth[i + 1])});
  }
  return out;
}

}  // namespace sextant::bench
