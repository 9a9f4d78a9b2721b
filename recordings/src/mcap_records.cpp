// The records of an MCAP file (mcap_records.hpp).
#include "mcap_records.hpp"

namespace sextant::recordings_detail {
namespace {

/// The end of a record's content at `c`'s position; the content must hold `size` bytes.
std::size_t content_end(ByteCursor& c, std::size_t size, const char* what) {
  if (size > c.remaining())
    c.fail("truncated " + std::string(what) + " record: " + std::to_string(size) + " bytes, " +
           std::to_string(c.remaining()) + " left");
  return c.position() + size;
}

/// A field must end inside its record.
void inside(const ByteCursor& c, std::size_t end, const char* what) {
  if (c.position() > end) c.fail(std::string(what) + " runs past the end of its record");
}

/// Map<uint16, uint64>: a u32 byte length, then entries of 10 bytes.
std::map<std::uint16_t, std::uint64_t> id_map(ByteCursor& c, const char* what) {
  const std::size_t start = c.position();
  const std::uint32_t bytes = c.u32(what);
  if (bytes % 10 != 0 || bytes > c.remaining())
    c.fail_at(start,
              std::string(what) + " of " + std::to_string(bytes) + " bytes is not a map of 10-byte entries");
  std::map<std::uint16_t, std::uint64_t> map;
  for (std::uint32_t k = 0; k < bytes / 10; ++k) {
    const std::uint16_t id = c.u16(what);
    map[id] = c.u64(what);
  }
  return map;
}

}  // namespace

McapSchema parse_mcap_schema(ByteCursor& c, std::size_t size) {
  const std::size_t end = content_end(c, size, "schema");
  McapSchema s;
  s.id = c.u16("schema id");
  s.name = c.string32("schema name");
  s.encoding = c.string32("schema encoding");
  inside(c, end, "the schema's name");
  c.seek(end, "schema end");
  return s;
}

McapChannel parse_mcap_channel(ByteCursor& c, std::size_t size) {
  const std::size_t end = content_end(c, size, "channel");
  McapChannel ch;
  ch.id = c.u16("channel id");
  ch.schema_id = c.u16("channel schema id");
  ch.topic = c.string32("channel topic");
  ch.message_encoding = c.string32("channel message encoding");
  inside(c, end, "the channel's topic");
  c.seek(end, "channel end");
  return ch;
}

McapChunkHeader parse_mcap_chunk_header(ByteCursor& c, std::size_t size) {
  const std::size_t start = c.position();
  const std::size_t end = content_end(c, size, "chunk");
  McapChunkHeader h;
  h.start_time = c.u64("chunk start time");
  h.end_time = c.u64("chunk end time");
  h.uncompressed_size = c.u64("chunk uncompressed size");
  h.uncompressed_crc = c.u32("chunk crc");
  h.compression = c.string32("chunk compression");
  h.records_size = c.u64("chunk records length");
  h.records_offset = c.position() - start + kMcapRecordPrefix;
  inside(c, end, "the chunk's header");
  if (h.records_size > end - c.position())
    c.fail("chunk records of " + std::to_string(h.records_size) + " bytes run past the chunk's " +
           std::to_string(size) + "-byte record");
  return h;
}

McapChunkIndex parse_mcap_chunk_index(ByteCursor& c, std::size_t size) {
  const std::size_t end = content_end(c, size, "chunk index");
  McapChunkIndex i;
  i.start_time = c.u64("chunk index start time");
  i.end_time = c.u64("chunk index end time");
  i.chunk_start_offset = c.u64("chunk index chunk offset");
  i.chunk_length = c.u64("chunk index chunk length");
  i.message_index_offsets = id_map(c, "chunk index message index offsets");
  i.message_index_length = c.u64("chunk index message index length");
  i.compression = c.string32("chunk index compression");
  i.compressed_size = c.u64("chunk index compressed size");
  i.uncompressed_size = c.u64("chunk index uncompressed size");
  inside(c, end, "the chunk index");
  c.seek(end, "chunk index end");
  return i;
}

McapStatistics parse_mcap_statistics(ByteCursor& c, std::size_t size) {
  const std::size_t end = content_end(c, size, "statistics");
  McapStatistics s;
  s.message_count = c.u64("statistics message count");
  c.skip(2 + 4 + 4 + 4, "statistics counts");  // schemas, channels, attachments, metadata
  s.chunk_count = c.u32("statistics chunk count");
  s.start_time = c.u64("statistics start time");
  s.end_time = c.u64("statistics end time");
  s.channel_message_counts = id_map(c, "statistics channel message counts");
  inside(c, end, "the statistics");
  c.seek(end, "statistics end");
  return s;
}

McapMessageHeader parse_mcap_message_header(ByteCursor& c, std::size_t size) {
  if (size < kMcapMessageHeader)
    c.fail("message record of " + std::to_string(size) + " bytes, shorter than a message's 22-byte header");
  McapMessageHeader m;
  m.channel_id = c.u16("message channel");
  c.skip(4, "message sequence");
  m.log_time = c.u64("message log time");
  c.skip(8, "message publish time");
  return m;
}

std::pair<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> parse_mcap_message_index(
    ByteCursor& c, std::size_t size) {
  const std::size_t end = content_end(c, size, "message index");
  const std::uint16_t channel = c.u16("message index channel");
  const std::size_t start = c.position();
  const std::uint32_t bytes = c.u32("message index length");
  if (bytes % 16 != 0 || bytes > end - c.position())
    c.fail_at(start,
              "message index of " + std::to_string(bytes) + " bytes is not an array of 16-byte entries");
  std::vector<std::pair<std::uint64_t, std::uint64_t>> entries(bytes / 16);
  for (auto& [time, offset] : entries) {
    time = c.u64("message index time");
    offset = c.u64("message index offset");
  }
  c.seek(end, "message index end");
  return {channel, std::move(entries)};
}

}  // namespace sextant::recordings_detail
