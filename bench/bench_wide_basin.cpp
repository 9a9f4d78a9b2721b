// Basin map of ML-NDT (issue 14): success over offset × yaw from the identity, plain ML-NDT versus
// the wide-basin option (mlndt_global_init.hpp), per pair. Each pair's input is displaced
// artificially on top of its reference pose T (ground truth for the Velodyne and campus pairs; a
// converged point-to-plane ICP from the usual guess for the KITTI pair and PCL's room scans, whose
// ground truth is withdrawn or absent): the displaced input x' = T⁻¹·D⁻¹·T·x has the known pose
// T' = D·T, D = translation (offset, 0, 0) · yaw about z. Success: ‖t error‖ < 10 cm and rotation
// error < 0.5°. Cells read plain/wide ("+" success, "." failure); the time is per registration.
//
//   build/bench/bench_wide_basin [pair substring] [wide_basin settings, default {}] > basin.md
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/match_pair.hpp"
#include "sextant/matchers/samplers.hpp"
#include "sextant/matchers/yaml.hpp"
#include "sextant/synth/campus.hpp"

namespace {

using namespace sextant;

const char* const kPlain = "{solver: lm, layers: 6, max_distance: 16, unmatched_penalty: 16}";

struct Pair {
  std::string name;
  PointCloud reference, input;
  Eigen::Isometry3d guess = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();  ///< p_ref = truth · p_input
};

std::string data(const std::string& path) {
  return std::string(SEXTANT_DATA_DIR) + "/" + path;
}

Eigen::Isometry3d read_matrix(const std::string& file) {
  std::ifstream in(file);
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) in >> M(r, c);
  if (!in) throw std::runtime_error("cannot read the 4×4 matrix in " + file);
  return Eigen::Isometry3d(M);
}

/// Point-to-plane ICP from `guess`: the reference pose of pairs without ground truth.
Eigen::Isometry3d consensus(const Pair& pair) {
  Rng rng(1);
  const auto icp = make_matcher("icp_p2l", YAML::Load("{max_correspondence_distance: 1.0}"), "bench");
  const auto gbs = make_sampler("gbs", YAML::Load("{cell_size: 0.3, max_per_cell: 3}"));
  return match_pair(*icp, *gbs, pair.reference, pair.input, pair.guess, rng).result.T;
}

std::vector<Pair> pairs(const std::string& filter) {
  std::vector<Pair> out;
  const auto wanted = [&](const std::string& name) { return name.find(filter) != std::string::npos; };
  if (wanted("campus")) {
    const synth::Campus campus = synth::generate_campus(synth::CampusSettings{}, 7);
    out.push_back({"campus 150", campus.scan(150).cloud, campus.scan(151).cloud,
                   Eigen::Isometry3d::Identity(),
                   relative(campus.ground_truth[150], campus.ground_truth[151])});
  }
  if (wanted("Velodyne"))
    out.push_back({"Velodyne", read_cloud(data("velodyne_pair/fast_gicp_251370668.pcd")),
                   read_cloud(data("velodyne_pair/fast_gicp_251371071.pcd")), Eigen::Isometry3d::Identity(),
                   read_matrix(data("velodyne_pair/fast_gicp_relative.txt"))});
  if (wanted("room")) {
    Pair room{
        "room*", read_cloud(data("pcl_room_scan/room_scan1.pcd")),
        read_cloud(data("pcl_room_scan/room_scan2.pcd")),
        Eigen::Translation3d(1.79387, 0.720047, 0) * Eigen::AngleAxisd(0.6931, Eigen::Vector3d::UnitZ())};
    room.truth = consensus(room);
    out.push_back(room);
  }
  if (wanted("KITTI")) {
    Pair kitti{"KITTI*", read_cloud(data("kitti00_pair/000000.xyz32.bin")),
               read_cloud(data("kitti00_pair/000001.xyz32.bin"))};
    kitti.truth = consensus(kitti);
    out.push_back(kitti);
  }
  return out;
}

PointCloud transformed(const PointCloud& cloud, const Eigen::Isometry3d& M) {
  PointCloud out;
  out.reserve(cloud.size());
  const Eigen::Isometry3f Mf = M.cast<float>();
  for (const Eigen::Vector3f& p : cloud.points()) out.push_back(Mf * p);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string filter = argc > 1 ? argv[1] : "";
  const std::string wide_basin = argc > 2 ? argv[2] : "{}";
  std::string wide_settings = kPlain;
  wide_settings.insert(wide_settings.size() - 1, ", wide_basin: " + wide_basin);
  const std::vector<double> offsets = {0, 4, 8, 12, 16}, yaws = {0, 15, 30, 45, 60, 75, 90};
  std::printf(
      "Success (< 10 cm, < 0.5°) from the identity, plain / wide basin; ML-NDT %s; wide: wide_basin: %s\n\n",
      kPlain, wide_basin.c_str());
  for (const Pair& pair : pairs(filter)) {
    const auto plain = make_matcher("mlndt", YAML::Load(kPlain), "bench");
    const auto wide = make_matcher("mlndt", YAML::Load(wide_settings), "bench");
    const auto gbs = make_sampler("gbs", YAML::Node());
    Rng rng(1);
    const PointCloud sample = pair.input.subset(gbs->select(pair.input, rng));
    const auto seconds_of = [](const auto& work) {
      const auto start = std::chrono::steady_clock::now();
      work();
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const double build = seconds_of([&] { plain->set_reference(pair.reference); });
    wide->set_reference(pair.reference);
    // The cost where plain ML-NDT converges: the undisplaced input from its reference pose.
    const double at_truth[2] = {seconds_of([&] { plain->align(sample, pair.truth); }),
                                seconds_of([&] { wide->align(sample, pair.truth); })};
    std::printf(
        "### %s (%zu reference points, %zu GBS input points; reference pose T: %.2f m, %.1f°, under D)\n\n"
        "| offset m \\ yaw ° |",
        pair.name.c_str(), pair.reference.size(), sample.size(), translation_norm(pair.truth),
        rotation_angle(pair.truth) / kRadPerDeg);
    for (double yaw : yaws) std::printf(" %.0f |", yaw);
    std::printf("\n|---|");
    for (std::size_t k = 0; k < yaws.size(); ++k) std::printf("---|");
    std::printf("\n");
    double seconds[2] = {0, 0};
    int successes[2] = {0, 0}, runs = 0;
    for (double offset : offsets) {
      std::printf("| %.0f |", offset);
      for (double yaw : yaws) {
        const Eigen::Isometry3d D = Eigen::Translation3d(offset, 0, 0) *
                                    Eigen::AngleAxisd(yaw * kRadPerDeg, Eigen::Vector3d::UnitZ());
        const Eigen::Isometry3d truth = D * pair.truth;
        const PointCloud input = transformed(sample, truth.inverse() * pair.truth);
        std::string cell;
        for (int m = 0; m < 2; ++m) {
          Matcher& matcher = m == 0 ? *plain : *wide;
          const auto start = std::chrono::steady_clock::now();
          const RegistrationResult r = matcher.align(input, Eigen::Isometry3d::Identity());
          seconds[m] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const Eigen::Isometry3d E = truth.inverse() * r.T;
          const bool ok = translation_norm(E) < 0.10 && rotation_angle(E) < 0.5 * kRadPerDeg;
          successes[m] += ok;
          cell += ok ? "+" : ".";
          if (m == 0) cell += "/";
        }
        ++runs;
        std::printf(" %s |", cell.c_str());
        std::fflush(stdout);
      }
      std::printf("\n");
    }
    std::printf(
        "\nsuccess: plain %d of %d, wide %d of %d; time per registration: plain %.3f s, wide %.3f s\n",
        successes[0], runs, successes[1], runs, seconds[0] / runs, seconds[1] / runs);
    std::printf("pyramid build %.3f s; from the reference pose T itself: plain %.3f s, wide %.3f s\n\n",
                build, at_truth[0], at_truth[1]);
  }
}
