// GNSS conversions through GeographicLib (only this file includes it).
#include "sextant/core/geo.hpp"

#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/UTMUPS.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

#include "datasets/scan_files.hpp"
#include "io/text_parse.hpp"
#include "sextant/core/error.hpp"

namespace sextant {
namespace {

void check_fix(const GeoFix& fix) {
  if (!std::isfinite(fix.latitude) || !std::isfinite(fix.longitude) || !std::isfinite(fix.altitude)) {
    throw std::invalid_argument("GNSS fix with a non-finite coordinate");
  }
  if (std::abs(fix.latitude) > 90.0) {
    throw std::invalid_argument("latitude " + std::to_string(fix.latitude) + "° outside [−90°, 90°]");
  }
}

}  // namespace

struct LocalEnu::Impl {
  GeographicLib::LocalCartesian frame;
};

LocalEnu::LocalEnu(const GeoFix& origin) : origin_(origin) {
  check_fix(origin);
  impl_ = std::make_unique<Impl>(
      Impl{GeographicLib::LocalCartesian(origin.latitude, origin.longitude, origin.altitude)});
}
LocalEnu::~LocalEnu() = default;
LocalEnu::LocalEnu(LocalEnu&&) noexcept = default;
LocalEnu& LocalEnu::operator=(LocalEnu&&) noexcept = default;

Eigen::Vector3d LocalEnu::to_enu(const GeoFix& fix) const {
  check_fix(fix);
  Eigen::Vector3d enu;
  impl_->frame.Forward(fix.latitude, fix.longitude, fix.altitude, enu.x(), enu.y(), enu.z());
  return enu;
}

GeoFix LocalEnu::to_geodetic(const Eigen::Vector3d& enu) const {
  GeoFix fix;
  impl_->frame.Reverse(enu.x(), enu.y(), enu.z(), fix.latitude, fix.longitude, fix.altitude);
  return fix;
}

UtmCoordinate to_utm(const GeoFix& fix) {
  check_fix(fix);
  UtmCoordinate utm;
  try {
    GeographicLib::UTMUPS::Forward(fix.latitude, fix.longitude, utm.zone, utm.northern, utm.easting,
                                   utm.northing);
  } catch (const GeographicLib::GeographicErr& e) {
    throw std::invalid_argument(std::string("UTM conversion failed: ") + e.what());
  }
  return utm;
}

GeoFix from_utm(const UtmCoordinate& utm) {
  GeoFix fix;
  try {
    GeographicLib::UTMUPS::Reverse(utm.zone, utm.northern, utm.easting, utm.northing, fix.latitude,
                                   fix.longitude);
  } catch (const GeographicLib::GeographicErr& e) {
    throw std::invalid_argument(std::string("UTM conversion failed: ") + e.what());
  }
  return fix;
}

std::vector<OxtsRecord> read_oxts_file(const std::filesystem::path& file) {
  const std::string text = detail::read_file_bytes(file);
  std::vector<OxtsRecord> records;
  std::vector<double> v;
  std::string bad;
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (detail::is_blank(line)) return;
    if (!detail::parse_numbers(line, v, &bad)) {
      throw InputError(file.string(), at_line(number), detail::bad_number_problem(bad));
    }
    if (v.size() != OxtsRecord::kFieldCount) {
      throw InputError(
          file.string(), at_line(number),
          "expected 30 OXTS fields (lat lon alt roll pitch yaw …), found " + std::to_string(v.size()));
    }
    for (int k = 0; k < 6; ++k) {
      if (!std::isfinite(v[k]))
        throw InputError(file.string(), at_line(number), "non-finite position or attitude");
    }
    if (std::abs(v[0]) > 90.0) {
      throw InputError(file.string(), at_line(number),
                       "latitude " + std::to_string(v[0]) + " outside [−90, 90]");
    }
    OxtsRecord r;
    std::copy(v.begin(), v.end(), r.fields.begin());
    r.fix = {v[0], v[1], v[2]};
    r.roll = v[3];
    r.pitch = v[4];
    r.yaw = v[5];
    records.push_back(r);
  });
  return records;
}

std::vector<OxtsRecord> read_oxts_folder(const std::filesystem::path& folder) {
  const std::filesystem::path data =
      std::filesystem::is_directory(folder / "data") ? folder / "data" : folder;
  const auto files = detail::list_scans(data, "", {".txt"}).files;
  if (files.empty()) throw InputError(data.string(), "", "no numbered OXTS files (NNNNNNNNNN.txt)");
  std::vector<OxtsRecord> records;
  for (const auto& f : files) {
    const auto in_file = read_oxts_file(f.path);
    if (in_file.size() != 1) {
      throw InputError(f.path.string(), "",
                       "expected one OXTS record, found " + std::to_string(in_file.size()));
    }
    records.push_back(in_file.front());
  }
  return records;
}

Trajectory oxts_to_poses(const std::vector<OxtsRecord>& records) {
  Trajectory trajectory;
  if (records.empty()) return trajectory;
  const LocalEnu enu(records.front().fix);
  for (const OxtsRecord& r : records) {
    StampedPose p;
    p.stamp = static_cast<double>(trajectory.size());
    p.pose.linear() = (Eigen::AngleAxisd(r.yaw, Eigen::Vector3d::UnitZ()) *
                       Eigen::AngleAxisd(r.pitch, Eigen::Vector3d::UnitY()) *
                       Eigen::AngleAxisd(r.roll, Eigen::Vector3d::UnitX()))
                          .toRotationMatrix();
    p.pose.translation() = enu.to_enu(r.fix);
    trajectory.push_back(p);
  }
  return trajectory;
}

}  // namespace sextant
