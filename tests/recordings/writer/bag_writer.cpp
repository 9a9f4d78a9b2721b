// Test-only ROS 1 bags (bag_writer.hpp).
#include "bag_writer.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <stdexcept>
#include <utility>

namespace sextant::test {
namespace {

using Fields = std::vector<std::pair<std::string, Bytes>>;

Bytes u32_bytes(std::uint32_t v) {
  ByteWriter w;
  w.u32(v);
  return w.bytes();
}
Bytes u64_bytes(std::uint64_t v) {
  ByteWriter w;
  w.u64(v);
  return w.bytes();
}
Bytes time_bytes(std::int64_t ns) {
  ByteWriter w;
  w.u32(static_cast<std::uint32_t>(ns / 1000000000));
  w.u32(static_cast<std::uint32_t>(ns % 1000000000));
  return w.bytes();
}
Bytes text(const std::string& s) {
  return Bytes(s.begin(), s.end());
}

void fields_into(ByteWriter& w, const Fields& fields) {
  for (const auto& [name, value] : fields) {
    w.u32(static_cast<std::uint32_t>(name.size() + 1 + value.size()));
    w.raw(name.data(), name.size());
    w.u8('=');
    w.raw(value);
  }
}

void record(ByteWriter& w, const Fields& header, const Bytes& data) {
  ByteWriter h;
  fields_into(h, header);
  w.u32(static_cast<std::uint32_t>(h.size()));
  w.raw(h.bytes());
  w.u32(static_cast<std::uint32_t>(data.size()));
  w.raw(data);
}

struct Topic {
  std::uint32_t id;
  std::string name, type;
};

void connection_record(ByteWriter& w, const Topic& t) {
  ByteWriter data;
  fields_into(data, {{"topic", text(t.name)},
                     {"type", text(t.type)},
                     {"md5sum", text("*")},
                     {"message_definition", text("# test\n")}});
  record(w, {{"op", {0x07}}, {"conn", u32_bytes(t.id)}, {"topic", text(t.name)}}, data.bytes());
}

}  // namespace

void write_bag(const std::filesystem::path& file, const std::vector<TestMessage>& messages,
               const BagOptions& o) {
  std::map<std::string, Topic> topics;
  for (const TestMessage& m : messages)
    if (!topics.count(m.topic))
      topics[m.topic] = Topic{static_cast<std::uint32_t>(topics.size()), m.topic, m.type};
  std::vector<std::vector<const TestMessage*>> chunks;
  for (std::size_t k = 0; k < messages.size(); ++k) {
    if (k % o.messages_per_chunk == 0) chunks.emplace_back();
    chunks.back().push_back(&messages[k]);
  }
  if (o.reverse_chunks) std::reverse(chunks.begin(), chunks.end());

  ByteWriter w;
  w.raw("#ROSBAG V2.0\n", 13);
  const std::size_t header_at = w.size();
  const auto bag_header = [&](ByteWriter& into, std::uint64_t index_pos, std::uint32_t conns,
                              std::uint32_t chunks) {
    Fields fields{{"op", {0x03}},
                  {"index_pos", u64_bytes(index_pos)},
                  {"conn_count", u32_bytes(conns)},
                  {"chunk_count", u32_bytes(chunks)}};
    if (!o.encryptor.empty()) fields.emplace_back("encryptor", text(o.encryptor));
    const std::size_t header = 69 + (o.encryptor.empty() ? 0 : 4 + 10 + o.encryptor.size());
    record(into, fields,
           Bytes(o.header_bytes - 8 - header, ' '));  // the record takes 4096 bytes, as rosbag writes it
  };
  bag_header(w, 0, 0, 0);
  struct ChunkInfo {
    std::uint64_t pos;
    std::int64_t start, end;
    std::map<std::uint32_t, std::uint32_t> counts;
  };
  std::vector<ChunkInfo> infos;
  for (const auto& chunk : chunks) {
    ByteWriter records;
    std::map<std::uint32_t, std::vector<std::pair<std::int64_t, std::uint32_t>>> index;
    std::map<std::uint32_t, bool> here;
    ChunkInfo info{w.size(), chunk.front()->log_time, chunk.front()->log_time, {}};
    for (const TestMessage* m : chunk) {
      const Topic& t = topics.at(m->topic);
      if (!here[t.id]) connection_record(records, t);
      here[t.id] = true;
      index[t.id].emplace_back(m->log_time, static_cast<std::uint32_t>(records.size()));
      record(records, {{"op", {0x02}}, {"conn", u32_bytes(t.id)}, {"time", time_bytes(m->log_time)}},
             m->data);
      info.start = std::min(info.start, m->log_time);
      info.end = std::max(info.end, m->log_time);
      ++info.counts[t.id];
    }
    record(w,
           {{"op", {0x05}},
            {"compression", text(o.compression)},
            {"size", u32_bytes(static_cast<std::uint32_t>(records.size()))}},
           compress(o.compression == "none" ? "" : o.compression, records.bytes()));
    if (o.index)
      for (const auto& [id, entries] : index) {
        ByteWriter data;
        for (const auto& [time, offset] : entries) {
          data.raw(time_bytes(time));
          data.u32(offset);
        }
        record(w,
               {{"op", {0x04}},
                {"ver", u32_bytes(1)},
                {"conn", u32_bytes(id)},
                {"count", u32_bytes(static_cast<std::uint32_t>(entries.size()))}},
               data.bytes());
      }
    infos.push_back(info);
  }
  if (o.index) {
    const std::uint64_t index_pos = w.size();
    for (const auto& [name, t] : topics) connection_record(w, t);
    for (const ChunkInfo& info : infos) {
      ByteWriter data;
      for (const auto& [id, count] : info.counts) {
        data.u32(id);
        data.u32(count);
      }
      record(w,
             {{"op", {0x06}},
              {"ver", u32_bytes(1)},
              {"chunk_pos", u64_bytes(info.pos)},
              {"start_time", time_bytes(info.start)},
              {"end_time", time_bytes(info.end)},
              {"count", u32_bytes(static_cast<std::uint32_t>(info.counts.size()))}},
             data.bytes());
    }
    ByteWriter header;  // the bag header again, now with its counts, over the first one
    bag_header(header, index_pos, static_cast<std::uint32_t>(topics.size()),
               static_cast<std::uint32_t>(infos.size()));
    std::copy(header.bytes().begin(), header.bytes().end(),
              w.bytes().begin() + static_cast<std::ptrdiff_t>(header_at));
  }
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(w.bytes().data()), static_cast<std::streamsize>(w.size()));
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace sextant::test
