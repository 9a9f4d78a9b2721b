// Opening one file of a recording by its first bytes (container.hpp).
#include "container.hpp"

#include <cerrno>
#include <fstream>

#include "mcap_records.hpp"
#include "rosbag1_records.hpp"
#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {

bool is_point_cloud2_type(const std::string& type) {
  return type == "sensor_msgs/PointCloud2" || type == "sensor_msgs/msg/PointCloud2";
}

bool keeps_point_clouds(const Connection& c) {
  return is_point_cloud2_type(c.type);
}

std::string sniff_format(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  char bytes[16] = {};
  in.read(bytes, sizeof bytes);
  const std::string first(bytes, static_cast<std::size_t>(in.gcount()));
  if (first.rfind("#ROSBAG V", 0) == 0) return "rosbag1";
  if (first.rfind(std::string(kMcapMagic, kMcapMagicSize), 0) == 0) return "mcap";
  if (first.rfind(std::string("SQLite format 3\0", 16), 0) == 0) return "sqlite3";
  return "";
}

std::unique_ptr<Container> open_container(const std::filesystem::path& file, std::uint16_t file_index,
                                          bool zstd_messages, KeepMessages keep) {
  const std::string format = sniff_format(file);
  if (format == "rosbag1") return open_rosbag1(file, file_index, std::move(keep));
  if (format == "mcap") return open_mcap(file, file_index, std::move(keep));
  if (format == "sqlite3") return open_rosbag2_sqlite(file, file_index, zstd_messages, std::move(keep));
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw FileError(file.string(), "no such recording file", ENOENT);
  throw InputError(
      file.string(), "byte 0",
      std::filesystem::file_size(file, ec) == 0
          ? "empty file (0 bytes), not a recording"
          : "not a recording: neither a ROS 1 bag ('#ROSBAG V2.0'), an MCAP file nor a sqlite3 file");
}

}  // namespace sextant::recordings_detail
