// PCD and PLY through PCL io. The only core file that includes PCL (linked privately), so PCL
// never leaks into our headers or into the compile time of other files.
#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "formats.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"

namespace sextant::detail {
namespace {

bool has_field(const pcl::PCLPointCloud2& blob, const std::string& name) {
  return std::any_of(blob.fields.begin(), blob.fields.end(),
                     [&](const pcl::PCLPointField& f) { return f.name == name; });
}

PointCloud from_blob(const std::filesystem::path& file, const pcl::PCLPointCloud2& blob,
                     ScanLoadReport* report) {
  for (const char* axis : {"x", "y", "z"}) {
    if (!has_field(blob, axis)) throw InputError(file.string(), "", std::string("no '") + axis + "' field");
  }
  PointCloud cloud;
  if (blob.data.empty() || blob.width * blob.height == 0) {
    // PCL's conversion indexes element 0 of an empty cloud (UB); nothing to convert anyway.
  } else if (has_field(blob, "intensity")) {
    pcl::PointCloud<pcl::PointXYZI> points;
    pcl::fromPCLPointCloud2(blob, points);
    cloud.points().reserve(points.size());
    cloud.intensity().reserve(points.size());
    for (const auto& p : points) cloud.push_back(Eigen::Vector3f(p.x, p.y, p.z), p.intensity);
  } else {
    pcl::PointCloud<pcl::PointXYZ> points;
    pcl::fromPCLPointCloud2(blob, points);
    cloud.reserve(points.size());
    for (const auto& p : points) cloud.push_back(Eigen::Vector3f(p.x, p.y, p.z));
  }
  ScanLoadReport local;
  local.points_read = cloud.size();
  local.non_finite_dropped = remove_non_finite(cloud);
  if (report) *report = local;
  return cloud;
}

template <class PclPoint>
pcl::PointCloud<PclPoint> to_pcl(const PointCloud& cloud) {
  pcl::PointCloud<PclPoint> out;
  out.resize(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    out[i].x = cloud[i].x();
    out[i].y = cloud[i].y();
    out[i].z = cloud[i].z();
    if constexpr (std::is_same_v<PclPoint, pcl::PointXYZI>) out[i].intensity = cloud.intensity()[i];
  }
  out.width = static_cast<std::uint32_t>(cloud.size());
  out.height = 1;
  out.is_dense = true;
  return out;
}

void require_file(const std::filesystem::path& file) {
  std::ifstream probe(file);
  if (!probe) throw InputError(file.string(), "", "cannot open");
}

template <class PclPoint>
void save_pcd(const std::filesystem::path& file, const PointCloud& cloud) {
  const pcl::PointCloud<PclPoint> points = to_pcl<PclPoint>(cloud);
  write_file_atomically_via_path(file, [&](const std::filesystem::path& tmp) {
    if (points.empty()) {
      // PCL refuses to write an empty cloud; its own header with zero points reads back fine.
      std::ofstream out(tmp, std::ios::binary);
      out << pcl::PCDWriter::generateHeader(points) << "DATA binary\n";
      if (!out) throw InputError(file.string(), "", "write failed");
      return;
    }
    if (pcl::PCDWriter().writeBinary(tmp.string(), points) != 0) {
      throw InputError(file.string(), "", "PCL could not write the PCD file");
    }
  });
}

template <class PclPoint>
void save_ply(const std::filesystem::path& file, const PointCloud& cloud) {
  const pcl::PointCloud<PclPoint> points = to_pcl<PclPoint>(cloud);
  write_file_atomically_via_path(file, [&](const std::filesystem::path& tmp) {
    if (pcl::PLYWriter().write(tmp.string(), points, /*binary=*/true, /*use_camera=*/false) != 0) {
      throw InputError(file.string(), "", "PCL could not write the PLY file");
    }
  });
}

}  // namespace

PointCloud read_pcd(const std::filesystem::path& file, ScanLoadReport* report) {
  require_file(file);
  pcl::PCLPointCloud2 blob;
  if (pcl::PCDReader().read(file.string(), blob) < 0) {
    throw InputError(file.string(), "",
                     "PCL could not read the PCD file (malformed header or truncated data)");
  }
  return from_blob(file, blob, report);
}

void write_pcd(const std::filesystem::path& file, const PointCloud& cloud) {
  if (cloud.has_intensity()) {
    save_pcd<pcl::PointXYZI>(file, cloud);
  } else {
    save_pcd<pcl::PointXYZ>(file, cloud);
  }
}

PointCloud read_ply(const std::filesystem::path& file, ScanLoadReport* report) {
  require_file(file);
  pcl::PCLPointCloud2 blob;
  if (pcl::PLYReader().read(file.string(), blob) < 0) {
    throw InputError(file.string(), "",
                     "PCL could not read the PLY file (malformed header or truncated data)");
  }
  return from_blob(file, blob, report);
}

void write_ply(const std::filesystem::path& file, const PointCloud& cloud) {
  if (cloud.has_intensity()) {
    save_ply<pcl::PointXYZI>(file, cloud);
  } else {
    save_ply<pcl::PointXYZ>(file, cloud);
  }
}

}  // namespace sextant::detail
