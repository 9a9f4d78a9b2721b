// Test-only MCAP files (mcap_writer.hpp).
#include "mcap_writer.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <stdexcept>

namespace sextant::test {
namespace {

constexpr char kMagic[] = "\x89MCAP0\r\n";

/// <opcode><u64 length><content>
void record(ByteWriter& w, std::uint8_t opcode, const Bytes& content) {
  w.u8(opcode);
  w.u64(content.size());
  w.raw(content);
}

struct Channel {
  std::uint16_t id;
  std::string topic, type;
};

Bytes schema_content(const Channel& c, const std::string& profile) {
  ByteWriter w;
  w.u16(c.id);  // one schema per channel, same id
  w.string(c.type);
  w.string(profile == "ros1" ? "ros1msg" : "ros2msg");
  w.string("# test definition");
  return w.bytes();
}

Bytes channel_content(const Channel& c, const std::string& profile) {
  ByteWriter w;
  w.u16(c.id);
  w.u16(c.id);
  w.string(c.topic);
  w.string(profile == "ros1" ? "ros1" : "cdr");
  w.u32(0);  // metadata: an empty map
  return w.bytes();
}

Bytes message_content(const Channel& c, std::uint32_t sequence, const TestMessage& m) {
  ByteWriter w;
  w.u16(c.id);
  w.u32(sequence);
  w.u64(static_cast<std::uint64_t>(m.log_time));
  w.u64(static_cast<std::uint64_t>(m.log_time));
  w.raw(m.data);
  return w.bytes();
}

void id_map(ByteWriter& w, const std::map<std::uint16_t, std::uint64_t>& map) {
  w.u32(static_cast<std::uint32_t>(map.size() * 10));
  for (const auto& [id, value] : map) {
    w.u16(id);
    w.u64(value);
  }
}

}  // namespace

void write_mcap(const std::filesystem::path& file, const std::vector<TestMessage>& messages,
                const McapOptions& o) {
  std::map<std::string, Channel> channels;
  for (const TestMessage& m : messages)
    if (!channels.count(m.topic))
      channels[m.topic] = Channel{static_cast<std::uint16_t>(channels.size() + 1), m.topic, m.type};
  ByteWriter w;
  w.raw(kMagic, 8);
  {
    ByteWriter header;
    header.string(o.profile);
    header.string("sextant test writer");
    record(w, 0x01, header.bytes());
  }
  ByteWriter chunk_indexes;
  std::map<std::uint16_t, std::uint64_t> counts;
  std::uint32_t chunk_count = 0;
  std::map<std::uint16_t, bool> declared;
  const auto declare = [&](ByteWriter& into, const Channel& c) {
    if (declared[c.id]) return;
    declared[c.id] = true;
    record(into, 0x03, schema_content(c, o.profile));
    record(into, 0x04, channel_content(c, o.profile));
  };
  std::uint32_t sequence = 0;
  for (std::size_t begin = 0; begin < messages.size();
       begin += o.chunked ? o.messages_per_chunk : messages.size()) {
    const std::size_t end =
        o.chunked ? std::min(messages.size(), begin + o.messages_per_chunk) : messages.size();
    if (!o.chunked) {
      for (std::size_t k = begin; k < end; ++k) {
        const Channel& c = channels.at(messages[k].topic);
        declare(w, c);
        record(w, 0x05, message_content(c, sequence++, messages[k]));
        ++counts[c.id];
      }
      continue;
    }
    declared.clear();  // every chunk declares its channels again, as writers do
    ByteWriter records;
    std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> index;
    std::uint64_t start = UINT64_MAX, stop = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const Channel& c = channels.at(messages[k].topic);
      declare(records, c);
      const auto t = static_cast<std::uint64_t>(messages[k].log_time);
      index[c.id].emplace_back(t, records.size());
      record(records, 0x05, message_content(c, sequence++, messages[k]));
      ++counts[c.id];
      start = std::min(start, t);
      stop = std::max(stop, t);
    }
    const Bytes packed = compress(o.compression, records.bytes());
    const std::uint64_t chunk_at = w.size();
    ByteWriter chunk;
    chunk.u64(start);
    chunk.u64(stop);
    chunk.u64(records.size());
    chunk.u32(0);  // no CRC
    chunk.string(o.compression);
    chunk.u64(packed.size());
    chunk.raw(packed);
    record(w, 0x06, chunk.bytes());
    const std::uint64_t chunk_length = w.size() - chunk_at;
    std::map<std::uint16_t, std::uint64_t> index_offsets;
    const std::uint64_t indexes_at = w.size();
    for (const auto& [id, entries] : index) {
      index_offsets[id] = w.size();
      ByteWriter mi;
      mi.u16(id);
      mi.u32(static_cast<std::uint32_t>(entries.size() * 16));
      for (const auto& [t, offset] : entries) {
        mi.u64(t);
        mi.u64(offset);
      }
      record(w, 0x07, mi.bytes());
    }
    ByteWriter ci;
    ci.u64(start);
    ci.u64(stop);
    ci.u64(chunk_at);
    ci.u64(chunk_length);
    id_map(ci, index_offsets);
    ci.u64(w.size() - indexes_at);
    ci.string(o.compression);
    ci.u64(packed.size());
    ci.u64(records.size());
    record(chunk_indexes, 0x08, ci.bytes());
    ++chunk_count;
  }
  record(w, 0x0F, Bytes(4, 0));  // data end, no CRC
  if (o.footer) {
    std::uint64_t summary_start = 0;
    if (o.summary) {
      summary_start = w.size();
      for (const auto& [topic, c] : channels) record(w, 0x03, schema_content(c, o.profile));
      for (const auto& [topic, c] : channels) record(w, 0x04, channel_content(c, o.profile));
      w.raw(chunk_indexes.bytes());
      ByteWriter stats;
      stats.u64(messages.size());
      stats.u16(static_cast<std::uint16_t>(channels.size()));
      stats.u32(static_cast<std::uint32_t>(channels.size()));
      stats.u32(0);
      stats.u32(0);
      stats.u32(chunk_count);
      std::uint64_t first = UINT64_MAX, last = 0;
      for (const TestMessage& m : messages) {
        first = std::min(first, static_cast<std::uint64_t>(m.log_time));
        last = std::max(last, static_cast<std::uint64_t>(m.log_time));
      }
      stats.u64(messages.empty() ? 0 : first);
      stats.u64(messages.empty() ? 0 : last);
      id_map(stats, counts);
      record(w, 0x0B, stats.bytes());
    }
    ByteWriter footer;
    footer.u64(summary_start);
    footer.u64(0);
    footer.u32(0);
    record(w, 0x02, footer.bytes());
    w.raw(kMagic, 8);
  }
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(w.bytes().data()), static_cast<std::streamsize>(w.size()));
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace sextant::test
