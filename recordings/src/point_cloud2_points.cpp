// The points of a sensor_msgs/PointCloud2 message (point_cloud2.hpp): every datatype, either byte
// order, organised (height > 1) or not, rows row_step apart and points point_step apart.
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "point_cloud2.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/point_time.hpp"

namespace sextant::recordings_detail {
namespace {

template <class T>
T load(const std::uint8_t* p, bool swap) {
  std::uint8_t bytes[sizeof(T)];
  std::memcpy(bytes, p, sizeof(T));
  if (swap)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

double value_at(const std::uint8_t* p, std::uint8_t datatype, bool swap) {
  switch (datatype) {
    case 1: return static_cast<double>(static_cast<std::int8_t>(*p));
    case 2: return static_cast<double>(*p);
    case 3: return static_cast<double>(load<std::int16_t>(p, swap));
    case 4: return static_cast<double>(load<std::uint16_t>(p, swap));
    case 5: return static_cast<double>(load<std::int32_t>(p, swap));
    case 6: return static_cast<double>(load<std::uint32_t>(p, swap));
    case 7: return static_cast<double>(load<float>(p, swap));
    default: return load<double>(p, swap);
  }
}

/// A field read per point: its offset and datatype.
struct Reader {
  std::uint32_t offset = 0;
  std::uint8_t datatype = 7;
  double at(const std::uint8_t* point, bool swap) const { return value_at(point + offset, datatype, swap); }
};

std::optional<Reader> field(const PointCloud2Message& m, const std::string& name) {
  for (const PointField2& f : m.fields)
    if (f.name == name) return Reader{f.offset, f.datatype};
  return std::nullopt;
}

Reader coordinate(const PointCloud2Message& m, const std::string& name, const Place& place) {
  const auto r = field(m, name);
  std::string names;
  for (const PointField2& f : m.fields) names += (names.empty() ? "" : " ") + f.name;
  if (!r)
    throw InputError(place.file, place.at(0),
                     "a point cloud without the field '" + name + "' (fields: " + names + ")");
  if (r->datatype != 7 && r->datatype != 8)
    throw InputError(place.file, place.at(0),
                     "field '" + name + "' is " + datatype_name(r->datatype) +
                         ": sextant reads float32 or float64 coordinates");
  return *r;
}

bool fits_float(double v) {
  return std::isfinite(v) && std::abs(v) <= static_cast<double>(std::numeric_limits<float>::max());
}

bool is_host_big_endian() {
  const std::uint16_t one = 1;
  std::uint8_t first;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

}  // namespace

PointCloud point_cloud2_points(const PointCloud2Message& m, const Bytes& payload, const Place& place,
                               ScanLoadReport* report) {
  const Reader x = coordinate(m, "x", place), y = coordinate(m, "y", place), z = coordinate(m, "z", place);
  const std::optional<Reader> intensity = field(m, "intensity");
  std::vector<std::string> names;
  for (const PointField2& f : m.fields) names.push_back(f.name);
  const std::optional<std::size_t> time_index = find_point_time_field(names);
  std::optional<Reader> time;
  if (time_index) time = Reader{m.fields[*time_index].offset, m.fields[*time_index].datatype};
  const bool swap = m.is_bigendian != is_host_big_endian();

  ScanLoadReport local;
  const std::size_t points = static_cast<std::size_t>(m.height) * m.width;
  if (points == 0) {  // an empty cloud (a height of 10^9 rows of nothing is not read row by row)
    if (report) *report = local;
    return PointCloud();
  }
  std::vector<Eigen::Vector3f> xyz;
  std::vector<float> intensities;
  std::vector<double> raw_times;
  xyz.reserve(points);
  if (intensity) intensities.reserve(points);
  if (time) raw_times.reserve(points);
  const std::uint8_t* data = payload.data() + m.data_offset;
  for (std::uint32_t row = 0; row < m.height; ++row) {
    const std::uint8_t* p = data + static_cast<std::size_t>(row) * m.row_step;
    for (std::uint32_t col = 0; col < m.width; ++col, p += m.point_step) {
      ++local.points_read;
      const double px = x.at(p, swap), py = y.at(p, swap), pz = z.at(p, swap);
      const double pi = intensity ? intensity->at(p, swap) : 0.0;
      if (!fits_float(px) || !fits_float(py) || !fits_float(pz) || !fits_float(pi)) {
        ++local.non_finite_dropped;
        continue;
      }
      if (px == 0.0 && py == 0.0 && pz == 0.0) {
        ++local.no_return_dropped;
        continue;
      }
      xyz.emplace_back(static_cast<float>(px), static_cast<float>(py), static_cast<float>(pz));
      if (intensity) intensities.push_back(static_cast<float>(pi));
      if (time) raw_times.push_back(time->at(p, swap));
    }
  }
  const std::uint64_t used = std::uint64_t{m.height} * m.row_step;
  if (m.data_size > used && points > 0)
    local.warnings.push_back(std::to_string(m.data_size - used) + " bytes of point data after the " +
                             std::to_string(m.height) + " rows of " + std::to_string(m.row_step) + " bytes");
  PointCloud cloud(std::move(xyz));
  cloud.intensity() = std::move(intensities);
  if (time) {
    const bool integer = m.fields[*time_index].datatype <= 6;
    std::vector<float> seconds = point_times_to_seconds(raw_times, integer, m.stamp);
    cloud.set_time(std::move(seconds));
    local.non_finite_dropped += remove_non_finite(cloud);  // a time that is NaN
  }
  if (report) *report = std::move(local);
  return cloud;
}

}  // namespace sextant::recordings_detail
