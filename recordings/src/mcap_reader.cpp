// An MCAP file as a Container: through its summary (channels, chunk indexes, the message indexes after
// each chunk) when it has one that indexes every message, else in one pass over the data section,
// decompressing one chunk at a time (a file whose writer stopped early has no summary).
#include <algorithm>
#include <map>
#include <set>

#include "container.hpp"
#include "decompress.hpp"
#include "file_reader.hpp"
#include "mcap_records.hpp"
#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {
namespace {

namespace op = mcap_op;

struct Chunk {
  std::uint64_t offset = 0;          ///< of the chunk record
  std::uint64_t length = 0;          ///< of the whole record
  std::uint64_t records_offset = 0;  ///< of its (compressed) records, in the file
  std::uint64_t records_size = 0, uncompressed_size = 0;
  Compression compression = Compression::none;
};

MessageEncoding encoding_of(const std::string& name) {
  if (name == "ros1" || name == "ros") return MessageEncoding::ros1;
  if (name == "cdr") return MessageEncoding::cdr;
  return MessageEncoding::other;
}

class Mcap : public Container {
 public:
  Mcap(const std::filesystem::path& path, std::uint16_t file_index, KeepMessages keep)
      : Container(file_index, std::move(keep)), reader_(path) {
    file_ = reader_.name();
    format_ = "mcap";
    const Bytes magic = reader_.read(0, kMcapMagicSize, "MCAP magic");
    if (std::string(magic.begin(), magic.end()) != std::string(kMcapMagic, kMcapMagicSize))
      throw InputError(file_, "byte 0", "not an MCAP file (no MCAP magic; MCAP major version 0 is read)");
    Bytes content;
    const std::uint8_t first = record_at(kMcapMagicSize, &content, "header record");
    if (first != op::kHeader)
      throw InputError(file_, at_byte(kMcapMagicSize),
                       "expected the header record (op 1), found op " + std::to_string(first));
    ByteCursor header(content, Place{file_, kMcapMagicSize + kMcapRecordPrefix, "", ""});
    profile_ = header.string32("profile");
    const std::uint64_t data_start = kMcapMagicSize + kMcapRecordPrefix + content.size();
    if (!read_summary()) read_linearly(data_start);
  }

  Bytes read_message(const MessagePosition& p, ChunkCache& cache, std::size_t prefix) const override {
    if (p.chunk == kNoChunk) return message_in_file(p.offset, prefix, describe(p));
    const Chunk& chunk = chunks_.at(p.chunk);
    if (chunk.compression == Compression::none) {
      if (p.offset >= chunk.records_size)
        throw InputError(file_, describe(p), "the message lies past the end of its chunk");
      return message_in_file(chunk.records_offset + p.offset, prefix, describe(p));
    }
    const auto records = cache.get(chunk_key(file_index_, p.chunk), [&] { return decompressed(p.chunk); });
    ByteCursor c(*records, chunk_place(p.chunk));
    c.seek(p.offset, "message");
    const std::uint8_t opcode = c.u8("record opcode");
    const std::uint64_t length = c.u64("record length");
    if (opcode != op::kMessage)
      c.fail_at(p.offset, "expected a message record (op 5), found op " + std::to_string(opcode));
    if (length > c.remaining()) c.fail_at(p.offset, "truncated message record");
    parse_mcap_message_header(c, length);
    const std::size_t n = std::min<std::size_t>(length - kMcapMessageHeader, prefix);
    const std::uint8_t* data = c.take(n, "message data");
    return Bytes(data, data + n);
  }

  std::string describe(const MessagePosition& p) const override {
    if (p.chunk == kNoChunk) return "the message at byte " + std::to_string(p.offset);
    return "the message at " + chunk_place(p.chunk).at(p.offset);
  }

 private:
  Place chunk_place(std::uint32_t chunk) const {
    const Chunk& c = chunks_.at(chunk);
    return Place{file_, 0, "",
                 " of the " + to_string(c.compression) + " chunk at byte " + std::to_string(c.offset)};
  }

  /// The opcode of the record at `offset`; its content into `content` (when given).
  std::uint8_t record_at(std::uint64_t offset, Bytes* content, const std::string& what,
                         std::uint64_t* length = nullptr) const {
    const Bytes prefix = reader_.read(offset, kMcapRecordPrefix, what);
    const std::uint64_t n = load_u64(prefix.data() + 1);
    if (n > reader_.size() - offset - kMcapRecordPrefix)
      throw InputError(file_, at_byte(static_cast<long long>(offset)),
                       "truncated " + what + ": its " + std::to_string(n) +
                           " bytes run past the end of the file (" + std::to_string(reader_.size()) +
                           " bytes)");
    if (content) *content = reader_.read(offset + kMcapRecordPrefix, n, what);
    if (length) *length = n;
    return prefix[0];
  }

  Bytes message_in_file(std::uint64_t offset, std::size_t prefix, const std::string& where) const {
    std::uint64_t length = 0;
    const std::uint8_t opcode = record_at(offset, nullptr, "message record", &length);
    if (opcode != op::kMessage)
      throw InputError(file_, where, "expected a message record (op 5), found op " + std::to_string(opcode));
    if (length < kMcapMessageHeader) throw InputError(file_, where, "message record shorter than its header");
    const std::size_t n = std::min<std::size_t>(length - kMcapMessageHeader, prefix);
    return reader_.read(offset + kMcapRecordPrefix + kMcapMessageHeader, n, "message data");
  }

  std::uint32_t add_chunk(std::uint64_t offset, std::uint64_t length, const McapChunkHeader& h) {
    const auto compression = compression_named(h.compression);
    if (!compression || *compression == Compression::bz2)
      throw InputError(
          file_, at_byte(static_cast<long long>(offset)),
          "unknown chunk compression '" + h.compression + "' (MCAP chunks are uncompressed, zstd or lz4)");
    if (*compression == Compression::none && h.uncompressed_size != h.records_size)
      throw InputError(file_, at_byte(static_cast<long long>(offset)),
                       "uncompressed chunk whose sizes differ");
    compressions_.insert(to_string(*compression));
    chunks_.push_back(
        Chunk{offset, length, offset + h.records_offset, h.records_size, h.uncompressed_size, *compression});
    return static_cast<std::uint32_t>(chunks_.size() - 1);
  }

  Bytes decompressed(std::uint32_t chunk) const {
    const Chunk& c = chunks_.at(chunk);
    const Bytes data = reader_.read(c.records_offset, c.records_size, "chunk records");
    return decompress(c.compression, data.data(), data.size(), c.uncompressed_size, file_,
                      "the " + to_string(c.compression) + " chunk at byte " + std::to_string(c.offset));
  }

  void add_schema(const McapSchema& s) { schemas_[s.id] = s.name; }

  void add_channel(const McapChannel& ch, const std::string& where) {
    if (channels_.count(ch.id)) return;  // repeated in the summary, or in a later chunk
    const auto schema = schemas_.find(ch.schema_id);
    if (ch.schema_id != 0 && schema == schemas_.end())
      throw InputError(file_, where,
                       "channel " + std::to_string(ch.id) + " names schema " + std::to_string(ch.schema_id) +
                           ", which no schema record before it defines");
    channels_[ch.id] = static_cast<std::uint16_t>(connections_.size());
    connections_.push_back(Connection{ch.topic, schema == schemas_.end() ? "" : schema->second,
                                      ch.message_encoding, encoding_of(ch.message_encoding), 0});
  }

  std::uint16_t connection_of(std::uint16_t channel, const std::string& where) const {
    const auto it = channels_.find(channel);
    if (it == channels_.end())
      throw InputError(
          file_, where,
          "a message on channel " + std::to_string(channel) + ", which no channel record before it defines");
    return it->second;
  }

  /// Reads the summary; false when the file has none that indexes every message (then nothing is kept).
  bool read_summary() {
    constexpr std::uint64_t kFooterSize = kMcapRecordPrefix + 20;
    if (reader_.size() < 2 * kMcapMagicSize + kFooterSize) return false;
    const std::uint64_t footer_at = reader_.size() - kMcapMagicSize - kFooterSize;
    const Bytes tail = reader_.read(footer_at, kFooterSize + kMcapMagicSize, "footer");
    if (tail[0] != op::kFooter ||
        std::string(tail.end() - kMcapMagicSize, tail.end()) != std::string(kMcapMagic, 8))
      return false;  // cut short: no footer
    const std::uint64_t summary_start = load_u64(tail.data() + kMcapRecordPrefix);
    const std::uint64_t offsets_start = load_u64(tail.data() + kMcapRecordPrefix + 8);
    if (summary_start == 0) return false;
    const std::uint64_t summary_end = offsets_start != 0 ? offsets_start : footer_at;
    if (summary_start > summary_end)
      throw InputError(file_, at_byte(static_cast<long long>(footer_at)),
                       "the footer's summary offsets are out of order");
    const Bytes summary = reader_.read(summary_start, summary_end - summary_start, "summary section");
    ByteCursor c(summary, Place{file_, summary_start, "", ""});
    std::vector<McapChunkIndex> indexes;
    std::optional<McapStatistics> statistics;
    std::vector<std::pair<McapChannel, std::string>> channels;
    while (!c.at_end()) {
      const std::string where = c.where();
      const std::uint8_t opcode = c.u8("record opcode");
      const std::uint64_t length = c.u64("record length");
      if (length > c.remaining()) c.fail("truncated summary record (op " + std::to_string(opcode) + ")");
      const std::size_t n = static_cast<std::size_t>(length);
      if (opcode == op::kSchema)
        add_schema(parse_mcap_schema(c, n));
      else if (opcode == op::kChannel)
        channels.emplace_back(parse_mcap_channel(c, n), where);
      else if (opcode == op::kChunkIndex)
        indexes.push_back(parse_mcap_chunk_index(c, n));
      else if (opcode == op::kStatistics)
        statistics = parse_mcap_statistics(c, n);
      else
        c.skip(n, "summary record");
    }
    if (indexes.empty()) return false;
    for (const McapChunkIndex& index : indexes)
      if (index.message_index_offsets.empty() && index.uncompressed_size > 0) return false;
    for (const auto& [channel, where] : channels) add_channel(channel, where);
    std::uint64_t indexed = 0;
    for (const McapChunkIndex& index : indexes) indexed += read_chunk_index(index);
    if (statistics && statistics->message_count > indexed) {  // messages outside chunks: not indexed
      forget();
      return false;
    }
    storage_ = storage_text("summary and chunk index");
    return true;
  }

  /// Drops what the summary said, for a pass over the data instead.
  void forget() {
    connections_.clear();
    kept_.clear();
    first_time_.reset();
    last_time_.reset();
    chunks_.clear();
    schemas_.clear();
    channels_.clear();
    compressions_.clear();
  }

  /// The message indexes after one chunk: every channel's count, the point-cloud channels' positions.
  std::uint64_t read_chunk_index(const McapChunkIndex& index) {
    McapChunkHeader header;
    header.compression = index.compression;
    header.uncompressed_size = index.uncompressed_size;
    header.records_size = index.compressed_size;
    header.records_offset = kMcapRecordPrefix + 8 + 8 + 8 + 4 + 4 + index.compression.size() + 8;
    const std::uint32_t chunk = add_chunk(index.chunk_start_offset, index.chunk_length, header);
    saw_time(static_cast<std::int64_t>(index.start_time));
    saw_time(static_cast<std::int64_t>(index.end_time));
    const std::uint64_t at = index.chunk_start_offset + index.chunk_length;
    const Bytes indexes = reader_.read(at, index.message_index_length, "message index records");
    ByteCursor c(indexes, Place{file_, at, "", ""});
    std::uint64_t messages = 0;
    while (!c.at_end()) {
      const std::string where = c.where();
      const std::uint8_t opcode = c.u8("record opcode");
      const std::uint64_t length = c.u64("record length");
      if (opcode != op::kMessageIndex)
        c.fail("expected a message index record (op 7), found op " + std::to_string(opcode));
      const auto [channel, entries] = parse_mcap_message_index(c, static_cast<std::size_t>(length));
      const std::uint16_t connection = connection_of(channel, where);
      connections_[connection].messages += entries.size();
      messages += entries.size();
      for (const auto& entry : entries) saw_time(static_cast<std::int64_t>(entry.first));
      if (!keeps(connection)) continue;
      for (const auto& [time, offset] : entries) {
        if (offset >= index.uncompressed_size)
          throw InputError(file_, where, "a message index entry points past its chunk's records");
        kept_.push_back(
            MessagePosition{static_cast<std::int64_t>(time), offset, chunk, file_index_, connection});
      }
    }
    return messages;
  }

  /// The schemas, channels and messages under `c`: a chunk's records, or one record of the data section
  /// at `file_offset` (chunk kNoChunk).
  void read_records(ByteCursor& c, std::uint32_t chunk, std::uint64_t file_offset) {
    while (!c.at_end()) {
      const std::size_t start = c.position();
      const std::string where = c.where();
      const std::uint8_t opcode = c.u8("record opcode");
      const std::uint64_t length = c.u64("record length");
      if (length > c.remaining())
        c.fail_at(start, "truncated record (op " + std::to_string(opcode) + "): " + std::to_string(length) +
                             " bytes, " + std::to_string(c.remaining()) + " left");
      const std::size_t n = static_cast<std::size_t>(length);
      if (opcode == op::kSchema) {
        add_schema(parse_mcap_schema(c, n));
      } else if (opcode == op::kChannel) {
        add_channel(parse_mcap_channel(c, n), where);
      } else if (opcode == op::kMessage) {
        const McapMessageHeader m = parse_mcap_message_header(c, n);
        c.seek(start + kMcapRecordPrefix + n, "message end");
        add_message(connection_of(m.channel_id, where), static_cast<std::int64_t>(m.log_time), chunk,
                    chunk == kNoChunk ? file_offset + start : start);
      } else {
        c.skip(n, "record");
      }
    }
  }

  void read_linearly(std::uint64_t from) {
    for (std::uint64_t at = from; at < reader_.size();) {
      if (reader_.size() - at == kMcapMagicSize) break;  // the trailing magic
      std::uint64_t length = 0;
      const std::uint8_t opcode = record_at(at, nullptr, "record", &length);
      if (opcode == op::kDataEnd || opcode == op::kFooter) break;
      if (opcode == op::kChunk) {
        const Bytes content = reader_.read(at + kMcapRecordPrefix, length, "chunk record");
        ByteCursor header(content, Place{file_, at + kMcapRecordPrefix, "", ""});
        const std::uint32_t chunk =
            add_chunk(at, kMcapRecordPrefix + length, parse_mcap_chunk_header(header, content.size()));
        const Chunk& c = chunks_[chunk];
        const std::uint64_t begin = c.records_offset - at - kMcapRecordPrefix;
        const Bytes records =
            decompress(c.compression, content.data() + begin, c.records_size, c.uncompressed_size, file_,
                       "the " + to_string(c.compression) + " chunk at byte " + std::to_string(at));
        ByteCursor inner(records, chunk_place(chunk));
        read_records(inner, chunk, 0);
      } else if (opcode == op::kSchema || opcode == op::kChannel || opcode == op::kMessage) {
        const Bytes record = reader_.read(at, kMcapRecordPrefix + length, "record");
        ByteCursor c(record, Place{file_, at, "", ""});
        read_records(c, kNoChunk, at);
      }
      at += kMcapRecordPrefix + length;
    }
    storage_ = storage_text(chunks_.empty() ? "read in one pass" : "no index: read in one pass");
  }

  std::string storage_text(const std::string& how) const {
    std::string kinds;
    for (const std::string& k : compressions_) kinds += (kinds.empty() ? "" : "+") + k;
    const std::string chunks = chunks_.empty() ? "no chunks"
                                               : std::to_string(chunks_.size()) + " " + kinds +
                                                     (chunks_.size() == 1 ? " chunk" : " chunks");
    return "profile " + (profile_.empty() ? std::string("none") : profile_) + ", " + chunks + ", " + how;
  }

  FileReader reader_;
  std::string profile_;
  std::vector<Chunk> chunks_;
  std::map<std::uint16_t, std::string> schemas_;
  std::map<std::uint16_t, std::uint16_t> channels_;  ///< channel id → index in connections_
  std::set<std::string> compressions_;
};

}  // namespace

std::unique_ptr<Container> open_mcap(const std::filesystem::path& file, std::uint16_t file_index,
                                     KeepMessages keep) {
  return std::make_unique<Mcap>(file, file_index, std::move(keep));
}

}  // namespace sextant::recordings_detail
