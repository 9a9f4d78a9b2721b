// PCD and PLY writers through PCL io (the readers are pcd_read.cpp and ply_read.cpp); a cloud with
// per-point time gets a float field `time`. The only core file that includes PCL (linked privately), so
// PCL never leaks into our headers or into the compile time of other files.
#include <pcl/PCLPointCloud2.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>

#include "formats.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"

namespace sextant::detail {
namespace {

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

template <class PclPoint>
void save_pcd(const std::filesystem::path& file, const PointCloud& cloud) {
  const pcl::PointCloud<PclPoint> points = to_pcl<PclPoint>(cloud);
  write_file_atomically_via_path(file, [&](const std::filesystem::path& tmp) {
    if (points.empty()) {
      // PCL refuses to write an empty cloud; its own header with zero points reads back fine.
      std::ofstream out(tmp, std::ios::binary);
      out << pcl::PCDWriter::generateHeader(points) << "DATA binary\n";
      if (!out) throw FileError::from_errno(file.string(), "write failed", errno);
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

/// A cloud with per-point time as PCL's generic record: float32 x y z [intensity] time, the time in
/// seconds from the scan's stamp under the name `time` (Velodyne's, which every reader of ours finds).
pcl::PCLPointCloud2 timed_record(const PointCloud& cloud) {
  std::vector<std::string> names{"x", "y", "z"};
  if (cloud.has_intensity()) names.emplace_back("intensity");
  names.emplace_back("time");
  pcl::PCLPointCloud2 out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    pcl::PCLPointField field;
    field.name = names[k];
    field.offset = static_cast<std::uint32_t>(4 * k);
    field.datatype = pcl::PCLPointField::FLOAT32;
    field.count = 1;
    out.fields.push_back(field);
  }
  out.height = 1;
  out.width = static_cast<std::uint32_t>(cloud.size());
  out.point_step = static_cast<std::uint32_t>(4 * names.size());
  out.row_step = out.point_step * out.width;
  out.is_dense = true;
  out.data.resize(static_cast<std::size_t>(out.row_step));
  std::vector<float> record(names.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    std::size_t k = 0;
    for (; k < 3; ++k) record[k] = cloud[i][static_cast<Eigen::Index>(k)];
    if (cloud.has_intensity()) record[k++] = cloud.intensity()[i];
    record[k] = cloud.time()[i];
    std::memcpy(out.data.data() + i * out.point_step, record.data(), out.point_step);
  }
  return out;
}

void save_timed(const std::filesystem::path& file, const PointCloud& cloud, bool pcd) {
  const pcl::PCLPointCloud2 record = timed_record(cloud);
  write_file_atomically_via_path(file, [&](const std::filesystem::path& tmp) {
    const int status =
        pcd ? pcl::PCDWriter().writeBinary(tmp.string(), record)
            : pcl::PLYWriter().writeBinary(tmp.string(), record, Eigen::Vector4f::Zero(),
                                           Eigen::Quaternionf::Identity(), /*use_camera=*/false);
    if (status != 0)
      throw InputError(file.string(), "",
                       std::string("PCL could not write the ") + (pcd ? "PCD" : "PLY") + " file");
  });
}

}  // namespace

void write_pcd(const std::filesystem::path& file, const PointCloud& cloud) {
  if (cloud.has_time()) {
    save_timed(file, cloud, true);
  } else if (cloud.has_intensity()) {
    save_pcd<pcl::PointXYZI>(file, cloud);
  } else {
    save_pcd<pcl::PointXYZ>(file, cloud);
  }
}

void write_ply(const std::filesystem::path& file, const PointCloud& cloud) {
  if (cloud.has_time()) {
    save_timed(file, cloud, false);
  } else if (cloud.has_intensity()) {
    save_ply<pcl::PointXYZI>(file, cloud);
  } else {
    save_ply<pcl::PointXYZ>(file, cloud);
  }
}

}  // namespace sextant::detail
