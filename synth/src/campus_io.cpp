#include "sextant/synth/campus_io.hpp"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <ctime>
#include <string>
#include <system_error>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/core/io/uos.hpp"

namespace sextant::synth {
namespace {

std::string scan_stem(std::size_t i) {
  return fmt::format("scan{:03d}", i);
}

Trajectory as_trajectory(const std::vector<Eigen::Isometry3d>& poses, const std::vector<double>& stamps) {
  Trajectory t;
  for (std::size_t i = 0; i < poses.size(); ++i) t.push_back({stamps[i], poses[i]});
  return t;
}

std::string landmarks_text(const World& world) {
  std::string out =
      "# Synthetic campus planar landmarks, world frame (x east, y north, z up) [m].\n"
      "# id kind area_m2 nx ny nz d vertex_count x1 y1 z1 x2 y2 z2 ...   (plane: n.x = d)\n";
  for (const Landmark& lm : world.landmarks) {
    out += fmt::format("{} {} {:.4f} {:.9f} {:.9f} {:.9f} {:.6f} {}", lm.id, kind_name(lm.kind), lm.area,
                       lm.normal.x(), lm.normal.y(), lm.normal.z(), lm.d, lm.polygon.size());
    for (const auto& v : lm.polygon) out += fmt::format(" {:.6f} {:.6f} {:.6f}", v.x(), v.y(), v.z());
    out += '\n';
  }
  return out;
}

/// KITTI raw timestamps: a fixed, fictitious date plus the scan time.
std::string kitti_timestamp(double stamp) {
  const long long whole = static_cast<long long>(std::floor(stamp));
  const long long nanos = static_cast<long long>(std::llround((stamp - whole) * 1e9));
  const long long day = whole / 86400, rest = whole % 86400;
  return fmt::format("2012-01-{:02d} {:02d}:{:02d}:{:02d}.{:09d}", 1 + day % 28, rest / 3600, rest / 60 % 60,
                     rest % 60, nanos);
}

void write_oxts(const Campus& campus, const std::filesystem::path& folder) {
  const std::filesystem::path oxts = folder / "oxts";
  std::string stamps;
  for (std::size_t i = 0; i < campus.gnss.size(); ++i) {
    write_file_atomically(oxts / "data" / fmt::format("{:010d}.txt", i), oxts_line(campus.gnss[i]) + "\n");
    stamps += kitti_timestamp(campus.gnss[i].stamp) + "\n";
  }
  write_file_atomically(oxts / "timestamps.txt", stamps);
  write_file_atomically(
      oxts / "dataformat.txt",
      "lat: latitude of the oxts-unit (deg)\nlon: longitude of the oxts-unit (deg)\n"
      "alt: altitude of the oxts-unit (m)\nroll: roll angle (rad), 0 = level, positive = left side up\n"
      "pitch: pitch angle (rad), 0 = level, positive = front side down\n"
      "yaw: heading (rad), 0 = east, positive = counter clockwise\n"
      "vn ve vf vl vu: velocities (m/s), 0 (stop-and-go: the vehicle stands still while scanning)\n"
      "ax ay az af al au: accelerations (m/s^2), 0\nwx wy wz wf wl wu: angular rates (rad/s), 0\n"
      "pos_accuracy: position accuracy (m)\nvel_accuracy: velocity accuracy (m/s)\n"
      "navstat: navigation status\nnumsats: number of satellites tracked\n"
      "posmode velmode orimode: position, velocity, orientation mode\n");
}

}  // namespace

void write_campus(const Campus& campus, const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  const std::size_t n = campus.size();
  std::vector<std::vector<LandmarkVisibility>> visible(n);
  std::vector<ScanStatistics> stats(n);
  SimulatedScan first;
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    SimulatedScan scan = campus.scan(i);
    const std::string stem = scan_stem(i);
    write_uos_scan(folder / (stem + ".3d"), scan.cloud);
    write_uos_pose(folder / (stem + ".pose"), campus.odometry[i]);            // odometry, as in hannover1
    write_uos_frames(folder / (stem + ".frames"), {campus.ground_truth[i]});  // ground truth (last line)
    visible[i] = std::move(scan.visible);
    stats[i] = scan.stats;
    if (i == 0) first = std::move(scan);
  });
  std::string vis = "# scan landmark_id points   (true planar landmarks hit by each scan)\n";
  std::string st = "# scan rays returns no_return self_hits\n";
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto& v : visible[i]) vis += fmt::format("{} {} {}\n", i, v.landmark, v.points);
    st += fmt::format("{} {} {} {} {}\n", i, stats[i].rays, stats[i].returns, stats[i].no_return,
                      stats[i].self_hits);
  }
  write_file_atomically(folder / "visibility.txt", vis);
  write_file_atomically(folder / "scan_statistics.txt", st);
  write_file_atomically(folder / "landmarks.txt", landmarks_text(*campus.world));
  write_tum_trajectory(folder / "ground_truth.tum", as_trajectory(campus.ground_truth, campus.stamps));
  write_tum_trajectory(folder / "odometry.tum", as_trajectory(campus.odometry, campus.stamps));
  write_oxts(campus, folder);
  if (n > 0) write_campus_preview_svg(campus, 0, first, folder / "preview.svg");
  // Written last: its presence marks a complete campus.
  write_file_atomically(folder / "campus.yaml", campus_settings_yaml(campus.settings, campus.seed));
}

std::filesystem::path ensure_campus(const CampusSettings& settings, std::uint64_t seed,
                                    const std::filesystem::path& cache_root) {
  const std::string name = fmt::format("campus-{:016x}", campus_hash(settings, seed));
  const std::filesystem::path target = cache_root / name;
  if (std::filesystem::exists(target / "campus.yaml")) return target;
  static std::atomic<unsigned> counter{0};
  const std::filesystem::path temp =
      cache_root / fmt::format(".{}.tmp-{}-{}", name, static_cast<long>(::getpid()), counter++);
  std::filesystem::remove_all(temp);
  write_campus(generate_campus(settings, seed), temp);
  std::error_code ec;
  std::filesystem::rename(temp, target, ec);
  if (ec) {
    // Another process finished first (or a stale incomplete folder is in the way).
    if (std::filesystem::exists(target / "campus.yaml")) {
      std::filesystem::remove_all(temp);
      return target;
    }
    std::filesystem::remove_all(target);
    std::filesystem::rename(temp, target, ec);
    if (ec)
      throw InputError(target.string(), "", "cannot move the generated campus into place: " + ec.message());
  }
  return target;
}

void write_campus_preview_svg(const Campus& campus, std::size_t scan_index,
                              const std::filesystem::path& file) {
  write_campus_preview_svg(campus, scan_index, campus.scan(scan_index), file);
}

void write_campus_preview_svg(const Campus& campus, std::size_t scan_index, const SimulatedScan& scan,
                              const std::filesystem::path& file) {
  const World& w = *campus.world;
  constexpr double kScale = 4.0;  // px per metre
  const double width = (w.max.x() - w.min.x()) * kScale, height = (w.max.y() - w.min.y()) * kScale;
  const auto X = [&](double x) { return (x - w.min.x()) * kScale; };
  const auto Y = [&](double y) { return (w.max.y() - y) * kScale; };
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" viewBox=\"0 0 {:.0f} "
      "{:.0f}\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"#f4f1ea\"/>\n",
      width, height, width, height);
  for (const Footprint& f : w.footprints) {
    const char* fill = f.kind == ObjectKind::kCar    ? "#6b8fb5"
                       : f.kind == ObjectKind::kWall ? "#5a4a3a"
                                                     : "#b9b0a2";
    svg += "<polygon fill=\"" + std::string(fill) + "\" stroke=\"#555\" stroke-width=\"0.5\" points=\"";
    for (const auto& p : f.outline) svg += fmt::format("{:.1f},{:.1f} ", X(p.x()), Y(p.y()));
    svg += "\"/>\n";
  }
  for (const Primitive& p : w.primitives) {
    if (const auto* e = std::get_if<Ellipsoid>(&p.shape)) {
      svg += fmt::format(
          "<ellipse cx=\"{:.1f}\" cy=\"{:.1f}\" rx=\"{:.1f}\" ry=\"{:.1f}\" fill=\"#4f8a3c\" "
          "opacity=\"0.35\"/>\n",
          X(e->center.x()), Y(e->center.y()), e->radii.x() * kScale, e->radii.y() * kScale);
    } else if (const auto* c = std::get_if<Cylinder>(&p.shape); c && p.kind == ObjectKind::kPole) {
      svg += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"1.5\" fill=\"#222\"/>\n", X(c->center.x()),
                         Y(c->center.y()));
    }
  }
  if (scan_index < campus.size()) {
    const Eigen::Isometry3d& T = campus.ground_truth[scan_index];
    for (std::size_t i = 0; i < scan.cloud.size(); i += 3) {
      const Eigen::Vector3d p = T * scan.cloud[i].cast<double>();
      svg += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"0.6\" fill=\"#1f5fbf\"/>\n", X(p.x()),
                         Y(p.y()));
    }
  }
  const auto polyline = [&](const std::vector<Eigen::Isometry3d>& poses, const char* colour) {
    svg += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\" points=\"", colour);
    for (const auto& T : poses)
      svg += fmt::format("{:.1f},{:.1f} ", X(T.translation().x()), Y(T.translation().y()));
    svg += "\"/>\n";
  };
  polyline(campus.odometry, "#e08a1e");
  polyline(campus.ground_truth, "#1d9a3a");
  svg += fmt::format(
      "<text x=\"8\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">synthetic campus, seed {}: "
      "ground truth (green), odometry (orange), scan {} (blue)</text>\n</svg>\n",
      campus.seed, scan_index);
  write_file_atomically(file, svg);
}

}  // namespace sextant::synth
