// read_cloud / write_cloud: dispatch by file extension.
#include "sextant/core/io/cloud_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "formats.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/core/io/uos.hpp"
#include "text_parse.hpp"

namespace sextant {
namespace {

enum class Kind { uos, kitti_bin, xyz32, pcd, ply, csv, xyz, txt };

struct Entry {
  Kind kind;
  CloudFormat format;
};

// Longest extensions first, so ".xyz32.bin" wins over ".bin".
const std::vector<Entry>& entries() {
  static const std::vector<Entry> table = {
      {Kind::xyz32,
       {".xyz32.bin", "KITTI velodyne x y z float32 (12 bytes/point)",
        "metres, x forward, y left, z up (as internal)"}},
      {Kind::kitti_bin,
       {".bin", "KITTI velodyne x y z intensity float32 (16 bytes/point)",
        "metres, x forward, y left, z up (as internal)"}},
      {Kind::uos,
       {".3d", "uos (3DTK) ASCII x y z",
        "centimetres, left-handed, y up, z forward; converted to internal metres, z up"}},
      {Kind::pcd, {".pcd", "PCL PCD", "as stored (assumed internal: metres, right-handed, z up)"}},
      {Kind::ply, {".ply", "PLY", "as stored (assumed internal: metres, right-handed, z up)"}},
      {Kind::csv,
       {".csv", "CSV x,y,z[,intensity]", "as stored (assumed internal: metres, right-handed, z up)"}},
      {Kind::xyz,
       {".xyz", "ASCII x y z [intensity]", "as stored (assumed internal: metres, right-handed, z up)"}},
      {Kind::txt,
       {".txt", "ASCII x y z [intensity]", "as stored (assumed internal: metres, right-handed, z up)"}},
  };
  return table;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

const Entry& entry_for(const std::filesystem::path& file) {
  std::string name = file.filename().string();
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const Entry& e : entries()) {
    if (ends_with(name, e.format.extension)) return e;
  }
  std::string known;
  for (const Entry& e : entries()) known += " " + e.format.extension;
  throw InputError(file.string(), "",
                   "unknown point-cloud extension '" + file.extension().string() + "' (known:" + known + ")");
}

PointCloud read_by_kind(Kind kind, const std::filesystem::path& file, ScanLoadReport* report) {
  switch (kind) {
    case Kind::uos: return read_uos_scan(file, report);
    case Kind::kitti_bin: return read_kitti_velodyne(file, report);
    case Kind::xyz32: return read_xyz32(file, report);
    case Kind::pcd: return detail::read_pcd(file, report);
    case Kind::ply: return detail::read_ply(file, report);
    case Kind::csv:
    case Kind::xyz:
    case Kind::txt: return detail::read_point_list(file, report);
  }
  return {};
}

}  // namespace

CloudFormat cloud_format(const std::filesystem::path& file) {
  return entry_for(file).format;
}

std::vector<CloudFormat> cloud_formats() {
  std::vector<CloudFormat> out;
  for (const Entry& e : entries()) out.push_back(e.format);
  return out;
}

namespace {

/// Points are floats: 8 km from the origin their spacing reaches 1 mm, 5,000 km away (UTM
/// northings) 0.5 m. Beyond 1 mm the reader says what the file's coordinates lost.
void warn_if_far_from_origin(const PointCloud& cloud, ScanLoadReport& report) {
  constexpr float kMillimetreSpacing = 8192.0f;  // 2¹³ m: float spacing 2¹³ · 2⁻²³ m ≈ 0.98 mm
  const Bounds box = cloud.bounds();
  const float farthest = std::max(box.min.cwiseAbs().maxCoeff(), box.max.cwiseAbs().maxCoeff());
  if (!(farthest >= kMillimetreSpacing)) return;
  const double spacing = std::nextafter(farthest, std::numeric_limits<float>::infinity()) - farthest;
  std::ostringstream text;
  text << "coordinates reach " << std::fixed << std::setprecision(0) << farthest
       << " m from the origin, where Sextant's float points are " << std::setprecision(3) << 1000.0 * spacing
       << " mm apart: finer positions are lost on reading; move the clouds near their origin (subtract a "
          "common offset) first";
  report.warnings.push_back(text.str());
}

}  // namespace

PointCloud read_cloud(const std::filesystem::path& file, ScanLoadReport* report) {
  const Entry& e = entry_for(file);
  detail::require_regular_file(file);
  ScanLoadReport local;
  PointCloud cloud = read_by_kind(e.kind, file, &local);
  warn_if_far_from_origin(cloud, local);
  if (report) *report = local;
  if (cloud.empty()) {
    std::error_code ec;
    const auto size = std::filesystem::file_size(file, ec);
    throw InputError(file.string(), at_byte(ec ? 0 : static_cast<long long>(size)),
                     "no points (" + std::to_string(local.points_read) + " read, " +
                         std::to_string(local.non_finite_dropped) + " non-finite and " +
                         std::to_string(local.no_return_dropped) + " no-return dropped)");
  }
  return cloud;
}

CloudWriteReport write_cloud(const std::filesystem::path& file, const PointCloud& cloud) {
  const Kind kind = entry_for(file).kind;
  CloudWriteReport report;
  report.points = cloud.size();
  report.times_dropped = cloud.has_time() && kind != Kind::pcd && kind != Kind::ply;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!cloud[i].allFinite())
      ++report.non_finite;
    else if (kind == Kind::uos && is_uos_no_return(internal_to_uos(cloud[i].cast<double>())))
      ++report.beyond_no_return_range;
  }
  switch (kind) {
    case Kind::uos: write_uos_scan(file, cloud); break;
    case Kind::kitti_bin: write_kitti_velodyne(file, cloud); break;
    case Kind::xyz32: write_xyz32(file, cloud); break;
    case Kind::pcd: detail::write_pcd(file, cloud); break;
    case Kind::ply: detail::write_ply(file, cloud); break;
    case Kind::csv: detail::write_point_list(file, cloud, true); break;
    case Kind::xyz:
    case Kind::txt: detail::write_point_list(file, cloud, false); break;
  }
  return report;
}

std::string dropped_on_reading_note(const std::filesystem::path& file, const CloudWriteReport& report) {
  std::string note;
  const std::string of = " of " + std::to_string(report.points) + " points written to " + file.string();
  if (report.beyond_no_return_range > 0)
    note = std::to_string(report.beyond_no_return_range) + of +
           " lie at or beyond 32.75 m: a .3d reader takes them for the SICK's \"no return\" and drops them "
           "(write .pcd, .ply or .bin to keep them)";
  if (report.non_finite > 0)
    note +=
        (note.empty() ? std::to_string(report.non_finite) + of : "; " + std::to_string(report.non_finite)) +
        (report.non_finite == 1 ? " has" : " have") + " a non-finite coordinate, which every reader drops";
  if (report.times_dropped)
    note += std::string(note.empty() ? "" : "; ") + "the points' own times are not written to " +
            file.string() + " (only .pcd and .ply keep them)";
  return note;
}

}  // namespace sextant
