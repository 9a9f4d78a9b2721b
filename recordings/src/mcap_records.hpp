#pragma once
// Private: the records of an MCAP file (mcap.dev/spec, major version 0): each is <opcode u8><content
// length u64><content>, little-endian; strings and byte arrays carry a u32 length, maps and arrays a
// u32 byte length. Only what reading messages needs is parsed; the rest is skipped.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "byte_cursor.hpp"

namespace sextant::recordings_detail {

namespace mcap_op {
inline constexpr std::uint8_t kHeader = 0x01, kFooter = 0x02, kSchema = 0x03, kChannel = 0x04,
                              kMessage = 0x05, kChunk = 0x06, kMessageIndex = 0x07, kChunkIndex = 0x08,
                              kStatistics = 0x0B, kDataEnd = 0x0F;
}

/// "\x89MCAP0\r\n": the first and the last 8 bytes of a file.
inline constexpr char kMcapMagic[] = "\x89MCAP0\r\n";
inline constexpr std::size_t kMcapMagicSize = 8;
/// Opcode and length before every record's content.
inline constexpr std::size_t kMcapRecordPrefix = 9;
/// channel_id, sequence, log_time, publish_time before a message's data.
inline constexpr std::size_t kMcapMessageHeader = 22;

struct McapSchema {
  std::uint16_t id = 0;
  std::string name, encoding;
};
struct McapChannel {
  std::uint16_t id = 0, schema_id = 0;
  std::string topic, message_encoding;
};
/// A chunk record's fields before its records; `records_offset` from the record's first byte.
struct McapChunkHeader {
  std::uint64_t start_time = 0, end_time = 0, uncompressed_size = 0, records_size = 0;
  std::uint32_t uncompressed_crc = 0;
  std::string compression;
  std::uint64_t records_offset = 0;
};
struct McapChunkIndex {
  std::uint64_t start_time = 0, end_time = 0, chunk_start_offset = 0, chunk_length = 0;
  std::map<std::uint16_t, std::uint64_t> message_index_offsets;
  std::uint64_t message_index_length = 0;
  std::string compression;
  std::uint64_t compressed_size = 0, uncompressed_size = 0;
};
struct McapStatistics {
  std::uint64_t message_count = 0;
  std::uint32_t chunk_count = 0;
  std::uint64_t start_time = 0, end_time = 0;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts;
};
struct McapMessageHeader {
  std::uint16_t channel_id = 0;
  std::uint64_t log_time = 0;
};

/// Each parser reads one record's content from `c` (positioned at it, `size` bytes of it).
McapSchema parse_mcap_schema(ByteCursor& c, std::size_t size);
McapChannel parse_mcap_channel(ByteCursor& c, std::size_t size);
McapChunkHeader parse_mcap_chunk_header(ByteCursor& c, std::size_t size);
McapChunkIndex parse_mcap_chunk_index(ByteCursor& c, std::size_t size);
McapStatistics parse_mcap_statistics(ByteCursor& c, std::size_t size);
McapMessageHeader parse_mcap_message_header(ByteCursor& c, std::size_t size);
/// A message index record: its channel and (log time, offset in the chunk's records) pairs.
std::pair<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> parse_mcap_message_index(
    ByteCursor& c, std::size_t size);

}  // namespace sextant::recordings_detail
