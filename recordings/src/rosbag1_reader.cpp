// A ROS 1 bag v2.0 as a Container: through its index (the connection and chunk-info records at the
// bag header's index_pos, the index records after each chunk) when it has one, else in one pass over
// its chunks, decompressing one at a time (a bag whose recording was cut short has no index).
#include <map>
#include <set>

#include "container.hpp"
#include "decompress.hpp"
#include "file_reader.hpp"
#include "rosbag1_records.hpp"
#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {
namespace {

namespace op = rosbag1_op;

struct Chunk {
  std::uint64_t offset = 0;       ///< of the chunk record
  std::uint64_t data_offset = 0;  ///< of its (compressed) records
  std::uint32_t data_size = 0;
  std::uint32_t uncompressed_size = 0;
  Compression compression = Compression::none;
};

class Rosbag1 : public Container {
 public:
  Rosbag1(const std::filesystem::path& path, std::uint16_t file_index, KeepMessages keep)
      : Container(file_index, std::move(keep)), reader_(path) {
    file_ = reader_.name();
    format_ = "rosbag1";
    const Bytes magic = reader_.read(0, kRosbag1MagicSize, "bag version line");
    if (std::string(magic.begin(), magic.end()) != kRosbag1Magic) {
      const std::string line(magic.begin(), magic.end());
      throw InputError(file_, "byte 0",
                       line.rfind("#ROSBAG V", 0) == 0 ? "ROS 1 bag version '" + line.substr(9, 3) +
                                                             "': sextant reads v2.0 (`rosbag fix` converts)"
                                                       : "not a ROS 1 bag (no '#ROSBAG V2.0' line)");
    }
    const Rosbag1Record header = read_rosbag1_record(reader_, kRosbag1MagicSize);
    if (header.op != op::kBagHeader)
      throw InputError(file_, header.where,
                       "expected the bag header record (op 3), found op " + std::to_string(header.op));
    if (header.has("encryptor") && header.text(file_, "encryptor") != "rosbag/NoEncryptor")
      throw InputError(file_, header.where,
                       "an encrypted bag (encryptor " + header.text(file_, "encryptor") +
                           "): sextant reads unencrypted bags (`rosbag decrypt` writes one)");
    const std::uint64_t index_pos = header.u64(file_, "index_pos");
    const std::uint32_t chunk_count = header.u32(file_, "chunk_count");
    if (index_pos != 0 && index_pos < reader_.size()) {
      read_index(index_pos, chunk_count);
    } else if (index_pos == 0 || index_pos > reader_.size()) {
      read_linearly(header.end());
    } else {  // index_pos == size: an indexed bag with nothing in it (no connections, no chunks)
      storage_ = "empty";
    }
  }

  Bytes read_message(const MessagePosition& p, ChunkCache& cache, std::size_t prefix) const override {
    if (p.chunk == kNoChunk) return message_data(read_rosbag1_record(reader_, p.offset), nullptr, prefix);
    const Chunk& chunk = chunks_.at(p.chunk);
    if (chunk.compression == Compression::none) {  // straight from the file
      Rosbag1Record r = read_rosbag1_record(reader_, chunk.data_offset + p.offset);
      r.where = describe(p);
      return message_data(r, nullptr, prefix);
    }
    const auto records = cache.get(chunk_key(file_index_, p.chunk), [&] { return decompressed(p.chunk); });
    ByteCursor cursor(*records, chunk_place(p.chunk));
    cursor.seek(p.offset, "message");
    const Rosbag1Record r = read_rosbag1_record(cursor);
    return message_data(r, records->data(), prefix);
  }

  std::string describe(const MessagePosition& p) const override {
    if (p.chunk == kNoChunk) return "the message at byte " + std::to_string(p.offset);
    return "the message at " + chunk_place(p.chunk).at(p.offset);
  }

 private:
  Place chunk_place(std::uint32_t chunk, std::uint64_t base = 0) const {
    const Chunk& c = chunks_.at(chunk);
    return Place{file_, base, "",
                 " of the " + to_string(c.compression) + " chunk at byte " + std::to_string(c.offset)};
  }

  Bytes message_data(const Rosbag1Record& r, const std::uint8_t* memory, std::size_t prefix) const {
    if (r.op != op::kMessage)
      throw InputError(file_, r.where, "expected a message record (op 2), found op " + std::to_string(r.op));
    const std::size_t n = std::min<std::size_t>(r.data_size, prefix);
    if (memory) return Bytes(memory + r.data_offset, memory + r.data_offset + n);
    return reader_.read(r.data_offset, n, "message data");
  }

  /// The chunk record at `offset`: registered, its number returned.
  std::uint32_t add_chunk(const Rosbag1Record& r) {
    if (r.op != op::kChunk)
      throw InputError(file_, r.where, "expected a chunk record (op 5), found op " + std::to_string(r.op));
    const std::string& name = r.text(file_, "compression");
    const auto compression = compression_named(name);
    if (!compression)
      throw InputError(file_, r.where,
                       "unknown chunk compression '" + name + "' (ROS 1 bags use none, bz2 or lz4)");
    Chunk c{r.offset, r.data_offset, r.data_size, r.u32(file_, "size"), *compression};
    if (c.compression == Compression::none && c.uncompressed_size != c.data_size)
      throw InputError(file_, r.where,
                       "uncompressed chunk of " + std::to_string(c.data_size) + " bytes says it holds " +
                           std::to_string(c.uncompressed_size));
    compressions_.insert(to_string(c.compression));
    chunks_.push_back(c);
    return static_cast<std::uint32_t>(chunks_.size() - 1);
  }

  Bytes decompressed(std::uint32_t chunk) const {
    const Chunk& c = chunks_.at(chunk);
    const Bytes data = reader_.read(c.data_offset, c.data_size, "chunk data");
    return decompress(c.compression, data.data(), data.size(), c.uncompressed_size, file_,
                      "the " + to_string(c.compression) + " chunk at byte " + std::to_string(c.offset));
  }

  void add_connection(const Rosbag1Record& r, const Bytes& data, const Place& place) {
    const Rosbag1Connection c = parse_rosbag1_connection(r, data, place);
    if (ids_.count(c.id)) return;  // a connection record repeats in every chunk that uses it
    if (connections_.size() > 0xFFFF) throw InputError(file_, r.where, "more than 65536 connections");
    ids_[c.id] = static_cast<std::uint16_t>(connections_.size());
    connections_.push_back(Connection{c.topic, c.type, "ros1", MessageEncoding::ros1, 0});
  }

  std::uint16_t connection_of(std::uint32_t id, const std::string& where) const {
    const auto it = ids_.find(id);
    if (it == ids_.end())
      throw InputError(
          file_, where,
          "a message of connection " + std::to_string(id) + ", which no connection record defines");
    return it->second;
  }

  void read_index(std::uint64_t index_pos, std::uint32_t chunk_count) {
    struct ChunkInfo {
      std::uint64_t chunk_pos;
      std::string where;
      std::vector<std::pair<std::uint32_t, std::uint32_t>> counts;  ///< connection id, messages
    };
    std::vector<ChunkInfo> infos;
    for (std::uint64_t at = index_pos; at < reader_.size();) {
      const Rosbag1Record r = read_rosbag1_record(reader_, at);
      const Bytes data = reader_.read(r.data_offset, r.data_size, "record data");
      const Place place{file_, r.data_offset, "", ""};
      if (r.op == op::kConnection) {
        add_connection(r, data, place);
      } else if (r.op == op::kChunkInfo) {
        ChunkInfo info{r.u64(file_, "chunk_pos"), r.where, {}};
        const std::uint32_t n = r.u32(file_, "count");
        ByteCursor cursor(data, place);
        for (std::uint32_t k = 0; k < n; ++k) {
          const std::uint32_t id = cursor.u32("chunk info connection");
          info.counts.emplace_back(id, cursor.u32("chunk info count"));
        }
        saw_time(r.time_ns(file_, "start_time"));
        saw_time(r.time_ns(file_, "end_time"));
        infos.push_back(std::move(info));
      }
      at = r.end();
    }
    if (infos.size() != chunk_count)
      throw InputError(file_, at_byte(static_cast<long long>(index_pos)),
                       "the bag header counts " + std::to_string(chunk_count) + " chunks, its index lists " +
                           std::to_string(infos.size()));
    for (const ChunkInfo& info : infos) {
      const std::uint32_t chunk = add_chunk(read_rosbag1_record(reader_, info.chunk_pos));
      std::set<std::uint16_t> wanted;
      for (const auto& [id, count] : info.counts) {
        const std::uint16_t c = connection_of(id, info.where);
        connections_[c].messages += count;
        if (keeps(c)) wanted.insert(c);
      }
      if (!wanted.empty()) read_chunk_index(chunk, info.counts.size(), wanted);
    }
    storage_ = storage_text("indexed");
  }

  /// The index records after chunk `chunk`: one per connection in it; the wanted ones' positions kept.
  void read_chunk_index(std::uint32_t chunk, std::size_t records, const std::set<std::uint16_t>& wanted) {
    std::uint64_t at = chunks_[chunk].data_offset + chunks_[chunk].data_size;
    for (std::size_t k = 0; k < records; ++k) {
      const Rosbag1Record r = read_rosbag1_record(reader_, at);
      if (r.op != op::kIndex)
        throw InputError(file_, r.where,
                         "expected the index record of the chunk at byte " +
                             std::to_string(chunks_[chunk].offset) + " (op 4), found op " +
                             std::to_string(r.op));
      const std::uint16_t c = connection_of(r.u32(file_, "conn"), r.where);
      if (wanted.count(c)) {
        const std::uint32_t n = r.u32(file_, "count");
        const Bytes data = reader_.read(r.data_offset, r.data_size, "index data");
        ByteCursor cursor(data, Place{file_, r.data_offset, "", ""});
        for (std::uint32_t m = 0; m < n; ++m) {
          const std::int64_t sec = cursor.u32("index time"), nsec = cursor.u32("index time");
          const std::uint32_t offset = cursor.u32("index offset");
          if (offset >= chunks_[chunk].uncompressed_size)
            cursor.fail("index entry points at byte " + std::to_string(offset) + " of a chunk of " +
                        std::to_string(chunks_[chunk].uncompressed_size) + " bytes");
          kept_.push_back(MessagePosition{sec * 1000000000 + nsec, offset, chunk, file_index_, c});
          saw_time(kept_.back().log_time);
        }
      }
      at = r.end();
    }
  }

  void read_linearly(std::uint64_t from) {
    for (std::uint64_t at = from; at < reader_.size();) {
      const Rosbag1Record r = read_rosbag1_record(reader_, at);
      if (r.op == op::kChunk) {
        const std::uint32_t chunk = add_chunk(r);
        const Bytes records = decompressed(chunk);
        ByteCursor cursor(records, chunk_place(chunk));
        while (!cursor.at_end()) {
          const Rosbag1Record inner = read_rosbag1_record(cursor);
          if (inner.op == op::kConnection)
            add_connection(inner,
                           Bytes(records.begin() + static_cast<std::ptrdiff_t>(inner.data_offset),
                                 records.begin() + static_cast<std::ptrdiff_t>(inner.end())),
                           chunk_place(chunk, inner.data_offset));
          if (inner.op == op::kMessage)
            add_message(connection_of(inner.u32(file_, "conn"), inner.where), inner.time_ns(file_, "time"),
                        chunk, inner.offset);
        }
      } else if (r.op == op::kConnection) {
        add_connection(r, reader_.read(r.data_offset, r.data_size, "connection data"),
                       Place{file_, r.data_offset, "", ""});
      } else if (r.op == op::kMessage) {
        add_message(connection_of(r.u32(file_, "conn"), r.where), r.time_ns(file_, "time"), kNoChunk,
                    r.offset);
      }
      at = r.end();
    }
    storage_ = storage_text("no index: read in one pass");
  }

  std::string storage_text(const std::string& how) const {
    std::string kinds;
    for (const std::string& k : compressions_) kinds += (kinds.empty() ? "" : "+") + k;
    return std::to_string(chunks_.size()) + (kinds.empty() ? "" : " " + kinds) +
           (chunks_.size() == 1 ? " chunk, " : " chunks, ") + how;
  }

  FileReader reader_;
  std::vector<Chunk> chunks_;
  std::map<std::uint32_t, std::uint16_t> ids_;  ///< the bag's connection id → index in connections_
  std::set<std::string> compressions_;
};

}  // namespace

std::unique_ptr<Container> open_rosbag1(const std::filesystem::path& file, std::uint16_t file_index,
                                        KeepMessages keep) {
  return std::make_unique<Rosbag1>(file, file_index, std::move(keep));
}

}  // namespace sextant::recordings_detail
