// One libFuzzer harness per reader: every fuzz_<name> executable links this same object and picks
// its reader from its own name (fuzz_pcd → the PCD reader), so the file is compiled once. The readers take
// paths, so each input is written to a file (under /dev/shm when it exists) with the extension the reader
// expects. A reader may refuse an input only with sextant::InputError; any other exception, a crash, a leak
// or a sanitizer report is a finding. Accepted clouds must hold only finite points and account for every
// point read.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

#include "sextant/core/error.hpp"
#include "sextant/core/geo.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/core/io/uos.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/recordings/recording.hpp"

namespace {

enum Target {
  uos_3d,
  uos_pose,
  uos_frames,
  kitti_bin,
  xyz32,
  kitti_poses,
  kitti_calib,
  pcd,
  ply,
  csv,
  tum,
  kitti_traj,
  oxts,
  rosbag1,
  mcap,
  config
};

const char* const kNames[] = {"uos_3d",      "uos_pose", "uos_frames", "kitti_bin", "xyz32", "kitti_poses",
                              "kitti_calib", "pcd",      "ply",        "csv",       "tum",   "kitti_traj",
                              "oxts",        "rosbag1",  "mcap",       "config"};

Target kTarget = pcd;

const char* extension() {
  switch (kTarget) {
    case uos_3d: return ".3d";
    case uos_pose: return ".pose";
    case uos_frames: return ".frames";
    case kitti_bin: return ".bin";
    case xyz32: return ".xyz32.bin";
    case pcd: return ".pcd";
    case ply: return ".ply";
    case csv: return ".csv";
    case rosbag1: return ".bag";
    case mcap: return ".mcap";
    case config: return ".yaml";
    default: return ".txt";
  }
}

const std::filesystem::path& input_file() {
  static const std::filesystem::path file = [] {
    const std::filesystem::path dir =
        std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    return dir / ("sextant-fuzz-" + std::to_string(::getpid()) + extension());
  }();
  return file;
}

void check_cloud(const sextant::PointCloud& cloud, const sextant::ScanLoadReport& report) {
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!cloud[i].allFinite()) std::abort();
  }
  if (cloud.size() + report.non_finite_dropped + report.no_return_dropped != report.points_read) std::abort();
}

/// A recording: described, then every scan of its only point-cloud topic read and checked.
void read_recording(const std::filesystem::path& file) {
  (void)sextant::describe_recording(file);
  const std::unique_ptr<sextant::Dataset> scans = sextant::open_recording(file);
  for (std::size_t i = 0; i < scans->size(); ++i) {
    sextant::ScanLoadReport report;
    check_cloud(scans->scan(i, &report), report);
    (void)scans->stamp(i);
  }
}

void read_input(const std::filesystem::path& file) {
  using namespace sextant;
  ScanLoadReport report;
  switch (kTarget) {
    case uos_3d:
    case kitti_bin:
    case xyz32:
    case pcd:
    case ply:
    case csv: check_cloud(read_cloud(file, &report), report); break;
    case uos_pose: read_uos_pose(file); break;
    case uos_frames: read_uos_frames(file); break;
    case kitti_poses: read_kitti_poses(file); break;
    case kitti_calib: read_kitti_calib_tr(file); break;
    case tum: read_tum_trajectory(file); break;
    case kitti_traj: read_kitti_trajectory(file); break;
    case oxts: oxts_to_poses(read_oxts_file(file)); break;
    case rosbag1:
    case mcap: read_recording(file); break;
    case config:
      read_experiment_config(file, false);
      read_experiment_config(file, true);
      break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  (void)argc;
  const std::string exe = std::filesystem::path((*argv)[0]).filename().string();  // fuzz_<name>
  for (int t = 0; t <= config; ++t) {
    if (exe == std::string("fuzz_") + kNames[t]) {
      kTarget = static_cast<Target>(t);
      return 0;
    }
  }
  std::fprintf(stderr, "%s: not a harness name (fuzz_pcd, fuzz_ply, …)\n", exe.c_str());
  std::abort();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path& file = input_file();
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    read_input(file);
  } catch (const sextant::InputError&) {
    // a clear refusal is the expected answer to bad input
  }
  return 0;
}
