#pragma once
// Test-only: ROS 1 bags v2.0 written from the format's description (wiki.ros.org/Bags/Format/2.0):
// the bag header record padded to 4096 bytes, chunks of connection and message records, index records
// after each chunk, and at index_pos the connection and chunk-info records.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "recording_message.hpp"

namespace sextant::test {

struct BagOptions {
  std::string compression = "none";  ///< none, bz2, lz4 (or any name, to test that it is refused)
  std::size_t messages_per_chunk = 10;
  bool index = true;            ///< false: index_pos 0, no index records (a recording cut short)
  bool reverse_chunks = false;  ///< chunks written last-first (their times out of order)
  std::string encryptor;        ///< the bag header's `encryptor` field, when not empty (the data stay plain)
  std::size_t header_bytes = 4096;  ///< the bag header record's size, padding included (rosbag: 4096)
};

inline BagOptions bag_options(std::string compression, std::size_t messages_per_chunk = 10, bool index = true,
                              bool reverse_chunks = false) {
  BagOptions o;
  o.compression = std::move(compression);
  o.messages_per_chunk = messages_per_chunk;
  o.index = index;
  o.reverse_chunks = reverse_chunks;
  return o;
}

/// Writes `messages` (in their order, one connection per topic) to `file`.
void write_bag(const std::filesystem::path& file, const std::vector<TestMessage>& messages,
               const BagOptions& options = {});

}  // namespace sextant::test
