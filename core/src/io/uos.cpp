// The uos format (3DTK, hannover1 layout), see data/README.md and docs/formats.md.
#include "sextant/core/io/uos.hpp"

#include <cmath>
#include <string>

#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "text_parse.hpp"

namespace sextant {
namespace {

/// uos axes → internal axes: x_int = z_uos, y_int = −x_uos, z_int = y_uos (det −1: handedness flips).
Eigen::Matrix3d uos_axes() {
  Eigen::Matrix3d P;
  P << 0, 0, 1,  //
      -1, 0, 0,  //
      0, 1, 0;
  return P;
}

constexpr double kCentimetresPerMetre = 100.0;
/// Lines before the first point that do not parse as numbers (e.g. "360 x 225") are a header.
constexpr long kMaxHeaderLines = 2;

/// Reads the non-blank lines of a small text file as rows of numbers.
struct NumberRow {
  long line = 0;
  std::vector<double> values;
};

std::vector<NumberRow> read_number_rows(const std::filesystem::path& file) {
  const std::string text = detail::read_file_bytes(file);
  std::vector<NumberRow> rows;
  std::string bad;
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (detail::is_blank(line)) return;
    NumberRow row;
    row.line = number;
    if (!detail::parse_numbers(line, row.values, &bad)) {
      throw InputError(file.string(), at_line(number), detail::bad_number_problem(bad));
    }
    rows.push_back(std::move(row));
  });
  return rows;
}

void require_finite(const std::filesystem::path& file, const NumberRow& row) {
  for (double v : row.values) {
    if (!std::isfinite(v)) throw InputError(file.string(), at_line(row.line), "non-finite value in a pose");
  }
}

}  // namespace

Eigen::Vector3d uos_to_internal(const Eigen::Vector3d& p_uos_cm) {
  return uos_axes() * p_uos_cm / kCentimetresPerMetre;
}

Eigen::Vector3d internal_to_uos(const Eigen::Vector3d& p_m) {
  return uos_axes().transpose() * p_m * kCentimetresPerMetre;
}

// T_internal = A·M·A⁻¹ with A = the uos → internal linear map (axes and cm → m).
Eigen::Isometry3d uos_pose_to_internal(const Eigen::Matrix4d& T_uos) {
  const Eigen::Matrix3d P = uos_axes();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = P * T_uos.topLeftCorner<3, 3>() * P.transpose();
  T.translation() = P * T_uos.topRightCorner<3, 1>() / kCentimetresPerMetre;
  return T;
}

Eigen::Matrix4d internal_pose_to_uos(const Eigen::Isometry3d& T) {
  const Eigen::Matrix3d P = uos_axes();
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  M.topLeftCorner<3, 3>() = P.transpose() * T.linear() * P;
  M.topRightCorner<3, 1>() = P.transpose() * T.translation() * kCentimetresPerMetre;
  return M;
}

Eigen::Matrix4d uos_euler_to_matrix(const Eigen::Vector3d& t_cm, const Eigen::Vector3d& theta_rad) {
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  M.topLeftCorner<3, 3>() = rotation_from_euler(theta_rad[0], theta_rad[1], theta_rad[2]);  // eq. (3.8)
  M.topRightCorner<3, 1>() = t_cm;
  return M;
}

bool is_uos_no_return(const Eigen::Vector3d& p_uos_cm) {
  return p_uos_cm.norm() >= kUosNoReturnRangeCm;
}

PointCloud read_uos_scan(const std::filesystem::path& file, ScanLoadReport* report) {
  const std::string text = detail::read_file_bytes(file);
  ScanLoadReport local;
  PointCloud cloud;
  cloud.reserve(text.size() / 24);
  std::vector<double> values;
  std::string bad;
  std::size_t columns = 0;  // fixed by the first point line: 3 (x y z) or more (4th = intensity)
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (detail::is_blank(line)) return;
    const bool parsed = detail::parse_numbers(line, values, &bad);
    if (columns == 0 && (!parsed || values.size() < 3)) {
      if (number <= kMaxHeaderLines) {
        ++local.header_lines_skipped;
        return;
      }
    }
    if (!parsed) throw InputError(file.string(), at_line(number), detail::bad_number_problem(bad));
    if (values.size() < 3) {
      throw InputError(file.string(), at_line(number),
                       "expected at least 3 numbers (x y z in cm), found " + std::to_string(values.size()));
    }
    if (columns == 0) columns = values.size();
    if ((columns > 3) != (values.size() > 3)) {
      throw InputError(file.string(), at_line(number),
                       "found " + std::to_string(values.size()) + " numbers, but earlier lines had " +
                           std::to_string(columns));
    }
    ++local.points_read;
    const Eigen::Vector3d p(values[0], values[1], values[2]);
    // NaN, ±Inf and values outside float's range (1e308) are dropped alike.
    const bool finite = detail::fits_float(p.x()) && detail::fits_float(p.y()) && detail::fits_float(p.z()) &&
                        (columns == 3 || detail::fits_float(values[3]));
    if (!finite) {
      ++local.non_finite_dropped;
      return;
    }
    if (is_uos_no_return(p)) {
      ++local.no_return_dropped;
      return;
    }
    const Eigen::Vector3f q = uos_to_internal(p).cast<float>();
    if (columns > 3) {
      cloud.push_back(q, static_cast<float>(values[3]));
    } else {
      cloud.push_back(q);
    }
  });
  if (report) *report = local;
  return cloud;
}

void write_uos_scan(const std::filesystem::path& file, const PointCloud& cloud) {
  std::string text;
  text.reserve(cloud.size() * 32);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = internal_to_uos(cloud[i].cast<double>());
    detail::append_number(text, p.x());
    text += ' ';
    detail::append_number(text, p.y());
    text += ' ';
    detail::append_number(text, p.z());
    if (cloud.has_intensity()) {
      text += ' ';
      detail::append_number(text, cloud.intensity()[i]);
    }
    text += '\n';
  }
  write_file_atomically(file, text);
}

Eigen::Isometry3d read_uos_pose(const std::filesystem::path& file) {
  const std::vector<NumberRow> rows = read_number_rows(file);
  if (rows.size() < 2) {
    throw InputError(
        file.string(), "",
        "expected 2 lines (x y z in cm, then θx θy θz in degrees), found " + std::to_string(rows.size()));
  }
  for (int r = 0; r < 2; ++r) {
    if (rows[r].values.size() != 3) {
      throw InputError(file.string(), at_line(rows[r].line),
                       "expected 3 numbers, found " + std::to_string(rows[r].values.size()));
    }
    require_finite(file, rows[r]);
  }
  const Eigen::Vector3d t(rows[0].values[0], rows[0].values[1], rows[0].values[2]);
  const Eigen::Vector3d theta =
      Eigen::Vector3d(rows[1].values[0], rows[1].values[1], rows[1].values[2]) * M_PI / 180.0;
  return uos_pose_to_internal(uos_euler_to_matrix(t, theta));
}

void write_uos_pose(const std::filesystem::path& file, const Eigen::Isometry3d& pose) {
  const Eigen::Matrix4d M = internal_pose_to_uos(pose);
  const Eigen::Vector3d theta = euler_from_rotation(M.topLeftCorner<3, 3>()) * 180.0 / M_PI;
  std::string text;
  for (int row = 0; row < 2; ++row) {
    for (int k = 0; k < 3; ++k) {
      if (k > 0) text += ' ';
      detail::append_number(text, row == 0 ? M(k, 3) : theta[k]);
    }
    text += '\n';
  }
  write_file_atomically(file, text);
}

std::vector<Eigen::Isometry3d> read_uos_frames(const std::filesystem::path& file) {
  const std::vector<NumberRow> rows = read_number_rows(file);
  if (rows.empty()) throw InputError(file.string(), "", "no frames (empty file)");
  std::vector<Eigen::Isometry3d> frames;
  frames.reserve(rows.size());
  for (const NumberRow& row : rows) {
    if (row.values.size() != 16 && row.values.size() != 17) {
      throw InputError(file.string(), at_line(row.line),
                       "expected 16 matrix entries (column-major) and a type code, found " +
                           std::to_string(row.values.size()) + " numbers");
    }
    require_finite(file, row);
    const Eigen::Matrix4d M = Eigen::Map<const Eigen::Matrix4d>(row.values.data());  // column-major
    if (const std::string why = rigid_problem(M.topLeftCorner<3, 3>(), M.topRightCorner<3, 1>());
        !why.empty())
      throw InputError(file.string(), at_line(row.line), "not a rigid transform: " + why);
    frames.push_back(uos_pose_to_internal(M));
  }
  return frames;
}

void write_uos_frames(const std::filesystem::path& file, const std::vector<Eigen::Isometry3d>& frames) {
  std::string text;
  for (const Eigen::Isometry3d& T : frames) {
    const Eigen::Matrix4d M = internal_pose_to_uos(T);
    for (int k = 0; k < 16; ++k) {
      detail::append_number(text, M.data()[k]);  // column-major, as 3DTK writes it
      text += ' ';
    }
    text += std::to_string(kUosFrameTypeCode) + "\n";
  }
  write_file_atomically(file, text);
}

}  // namespace sextant
