// KITTI odometry files; layout in docs/formats.md.
#include "sextant/core/io/kitti.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "text_parse.hpp"

namespace sextant {
namespace {

static_assert(sizeof(float) == 4, "KITTI binaries hold IEEE float32");

/// Reads float records of `floats_per_point` values; the 4th (when present) is intensity.
PointCloud read_float_records(const std::filesystem::path& file, std::size_t floats_per_point,
                              ScanLoadReport* report) {
  const std::string bytes = detail::read_file_bytes(file);
  const std::size_t record = floats_per_point * sizeof(float);
  if (bytes.size() % record != 0) {
    const std::size_t offset = bytes.size() - bytes.size() % record;
    std::string hint = floats_per_point == 4 ? " (a .xyz32.bin file of 12-byte x y z points?)"
                                             : " (a KITTI .bin file of 16-byte x y z intensity points?)";
    if (bytes.size() % (16 + 12 - record) == 0) hint += ", the size fits that layout";
    throw InputError(file.string(), at_byte(static_cast<long long>(offset)),
                     "truncated: " + std::to_string(bytes.size()) + " bytes is not a multiple of the " +
                         std::to_string(record) + "-byte point record" + hint);
  }
  const std::size_t n = bytes.size() / record;
  ScanLoadReport local;
  local.points_read = n;
  PointCloud cloud;
  cloud.mutable_points().reserve(n);
  if (floats_per_point == 4) cloud.intensity().reserve(n);
  float v[4] = {0, 0, 0, 0};
  std::size_t negative_intensity = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::memcpy(v, bytes.data() + i * record, record);
    if (floats_per_point == 4 && v[3] < 0.0f) ++negative_intensity;
    const Eigen::Vector3f p(v[0], v[1], v[2]);
    if (!p.allFinite() || (floats_per_point == 4 && !std::isfinite(v[3]))) {
      ++local.non_finite_dropped;
      continue;
    }
    if (floats_per_point == 4) {
      cloud.push_back(p, v[3]);
    } else {
      cloud.push_back(p);
    }
  }
  // A file of 12-byte points whose size is a multiple of 48 also reads as 16-byte points: its
  // "intensity" is then a coordinate, often negative, which no lidar's intensity is.
  if (negative_intensity > 0)
    local.warnings.push_back(std::to_string(negative_intensity) + " of " + std::to_string(n) +
                             " points have a negative fourth value, which is no intensity: is this a "
                             "file of 12-byte x y z points (rename it .xyz32.bin)?");
  if (report) *report = local;
  return cloud;
}

void write_float_records(const std::filesystem::path& file, const PointCloud& cloud, bool with_intensity) {
  std::string bytes;
  bytes.reserve(cloud.size() * (with_intensity ? 16 : 12));
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const float v[4] = {cloud[i].x(), cloud[i].y(), cloud[i].z(),
                        cloud.has_intensity() ? cloud.intensity()[i] : 0.0f};
    bytes.append(reinterpret_cast<const char*>(v), with_intensity ? 16 : 12);
  }
  write_file_atomically(file, bytes);
}

Eigen::Isometry3d isometry_from_row_major(const std::vector<double>& v, std::size_t first) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) T.matrix()(r, c) = v[first + 4 * r + c];
  }
  return T;
}

void check_finite(const std::filesystem::path& file, long line, const std::vector<double>& v) {
  for (double x : v) {
    if (!std::isfinite(x)) throw InputError(file.string(), at_line(line), "non-finite value");
  }
}

}  // namespace

PointCloud read_kitti_velodyne(const std::filesystem::path& file, ScanLoadReport* report) {
  return read_float_records(file, 4, report);
}
void write_kitti_velodyne(const std::filesystem::path& file, const PointCloud& cloud) {
  write_float_records(file, cloud, true);
}
PointCloud read_xyz32(const std::filesystem::path& file, ScanLoadReport* report) {
  return read_float_records(file, 3, report);
}
void write_xyz32(const std::filesystem::path& file, const PointCloud& cloud) {
  write_float_records(file, cloud, false);
}

std::vector<Eigen::Isometry3d> read_kitti_poses(const std::filesystem::path& file) {
  const std::string text = detail::read_file_bytes(file);
  std::vector<Eigen::Isometry3d> poses;
  std::vector<double> values;
  std::string bad;
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (detail::is_blank(line)) return;
    if (!detail::parse_numbers(line, values, &bad)) {
      throw InputError(file.string(), at_line(number), detail::bad_number_problem(bad));
    }
    if (values.size() != 12) {
      throw InputError(file.string(), at_line(number),
                       "expected 12 numbers (a 3×4 row-major pose), found " + std::to_string(values.size()));
    }
    check_finite(file, number, values);
    const Eigen::Isometry3d T = isometry_from_row_major(values, 0);
    if (const std::string why = rigid_problem(T.linear(), T.translation()); !why.empty())
      throw InputError(file.string(), at_line(number), "not a rigid transform: " + why);
    poses.push_back(T);
  });
  return poses;
}

void write_kitti_poses(const std::filesystem::path& file, const std::vector<Eigen::Isometry3d>& poses) {
  std::string text;
  for (const Eigen::Isometry3d& T : poses) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) {
        if (r + c > 0) text += ' ';
        detail::append_number(text, T.matrix()(r, c));
      }
    }
    text += '\n';
  }
  write_file_atomically(file, text);
}

Eigen::Isometry3d read_kitti_calib_tr(const std::filesystem::path& file) {
  const std::string text = detail::read_file_bytes(file);
  bool found = false;
  Eigen::Isometry3d Tr = Eigen::Isometry3d::Identity();
  std::vector<double> values;
  std::string bad;
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (found || line.substr(0, 3) != "Tr:") return;
    if (!detail::parse_numbers(line.substr(3), values, &bad)) {
      throw InputError(file.string(), at_line(number), detail::bad_number_problem(bad));
    }
    if (values.size() != 12) {
      throw InputError(
          file.string(), at_line(number),
          "the Tr line needs 12 numbers (3×4 row-major), found " + std::to_string(values.size()));
    }
    check_finite(file, number, values);
    Tr = isometry_from_row_major(values, 0);
    found = true;
  });
  if (!found) throw InputError(file.string(), "", "no 'Tr:' line (the Velodyne → camera 0 calibration)");
  return Tr;
}

std::vector<Eigen::Isometry3d> kitti_velodyne_poses(const std::vector<Eigen::Isometry3d>& camera_poses,
                                                    const Eigen::Isometry3d& Tr) {
  std::vector<Eigen::Isometry3d> out;
  if (camera_poses.empty()) return out;
  // The published matrices are rounded (not exactly orthonormal), so invert them as general 4×4
  // matrices, as the devkit does: the result then equals Tr⁻¹·P0⁻¹·Pi·Tr of the raw numbers.
  const Eigen::Matrix4d P0_inv = camera_poses.front().matrix().inverse();
  const Eigen::Matrix4d Tr_inv = Tr.matrix().inverse();
  out.reserve(camera_poses.size());
  for (const Eigen::Isometry3d& P : camera_poses) {
    out.emplace_back(Eigen::Isometry3d(Tr_inv * P0_inv * P.matrix() * Tr.matrix()));
  }
  return out;
}

std::string scan_time_problem(std::optional<double> previous, double time) {
  if (!std::isfinite(time)) return "expected one finite time [s] per scan";
  if (previous && !(time > *previous))
    return "the time " + std::to_string(time) + " s is not after the previous scan's (" +
           std::to_string(*previous) + " s): a scan's time comes after the one before it";
  return "";
}

std::vector<double> read_kitti_times(const std::filesystem::path& file) {
  const std::string text = detail::read_file_bytes(file);
  std::vector<double> times;
  std::vector<double> values;
  std::string bad;
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (detail::is_blank(line)) return;
    if (!detail::parse_numbers(line, values, &bad)) {
      throw InputError(file.string(), at_line(number), detail::bad_number_problem(bad));
    }
    if (values.size() != 1)
      throw InputError(file.string(), at_line(number), "expected one time [s] per line");
    const std::optional<double> previous = times.empty() ? std::nullopt : std::optional<double>(times.back());
    if (const std::string problem = scan_time_problem(previous, values[0]); !problem.empty())
      throw InputError(file.string(), at_line(number),
                       problem + " (times.txt lists the scans' times in order)");
    times.push_back(values[0]);
  });
  return times;
}

}  // namespace sextant
