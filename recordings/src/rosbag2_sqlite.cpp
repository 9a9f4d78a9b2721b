// One sqlite3 file of a ROS 2 bag as a Container, through Debian's libsqlite3: the `topics` table
// (id, name, type, serialization_format) and the `messages` table (id, topic_id, timestamp [ns], data),
// in both the current layout and the old two-table one. A message's position is its row id; its data
// are read through an incremental blob handle, so reading a stamp reads a few bytes.
#include <sqlite3.h>

#include <map>
#include <mutex>

#include "container.hpp"
#include "decompress.hpp"
#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {
namespace {

class Statement {
 public:
  Statement(sqlite3* db, const char* sql, const std::string& file) : db_(db), file_(file) {
    if (sqlite3_prepare_v2(db, sql, -1, &statement_, nullptr) != SQLITE_OK)
      throw InputError(file, "", std::string("not a rosbag2 sqlite3 bag: ") + sqlite3_errmsg(db));
  }
  ~Statement() { sqlite3_finalize(statement_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  void bind(int index, std::int64_t value) { sqlite3_bind_int64(statement_, index, value); }
  void reset() { sqlite3_reset(statement_); }
  /// True while a row is there.
  bool step() {
    const int status = sqlite3_step(statement_);
    if (status == SQLITE_ROW) return true;
    if (status == SQLITE_DONE) return false;
    throw InputError(file_, "", std::string("sqlite3 cannot read the bag: ") + sqlite3_errmsg(db_));
  }
  std::int64_t integer(int column) const { return sqlite3_column_int64(statement_, column); }
  std::string text(int column) const {
    const unsigned char* t = sqlite3_column_text(statement_, column);
    return t ? std::string(reinterpret_cast<const char*>(t)) : std::string();
  }

 private:
  sqlite3* db_;
  sqlite3_stmt* statement_ = nullptr;
  std::string file_;
};

MessageEncoding encoding_of(const std::string& name) {
  return name == "cdr" ? MessageEncoding::cdr : MessageEncoding::other;
}

class Rosbag2Sqlite : public Container {
 public:
  Rosbag2Sqlite(const std::filesystem::path& path, std::uint16_t file_index, bool zstd_messages,
                KeepMessages keep)
      : Container(file_index, std::move(keep)), zstd_messages_(zstd_messages) {
    file_ = path.string();
    format_ = "rosbag2";
    storage_ = zstd_messages ? "sqlite3, zstd per message" : "sqlite3";
    if (sqlite3_open_v2(file_.c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
      const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      throw InputError(file_, "", "sqlite3 cannot open it: " + why);
    }
    try {
      read_tables();
    } catch (...) {
      sqlite3_close(db_);
      throw;
    }
  }
  ~Rosbag2Sqlite() override { sqlite3_close(db_); }

  Bytes read_message(const MessagePosition& p, ChunkCache& /*cache*/, std::size_t prefix) const override {
    const std::lock_guard<std::mutex> lock(mutex_);
    sqlite3_blob* blob = nullptr;
    if (sqlite3_blob_open(db_, "main", "messages", "data", static_cast<sqlite3_int64>(p.offset), 0, &blob) !=
        SQLITE_OK) {
      const std::string why = sqlite3_errmsg(db_);
      sqlite3_blob_close(blob);
      throw InputError(file_, describe(p), "sqlite3 cannot read the message: " + why);
    }
    const std::size_t size = static_cast<std::size_t>(sqlite3_blob_bytes(blob));
    const std::size_t n = zstd_messages_ ? size : std::min(size, prefix);
    Bytes data(n);
    const int status = n == 0 ? SQLITE_OK : sqlite3_blob_read(blob, data.data(), static_cast<int>(n), 0);
    sqlite3_blob_close(blob);
    if (status != SQLITE_OK) throw InputError(file_, describe(p), "sqlite3 cannot read the message's data");
    if (!zstd_messages_) return data;
    Bytes plain = decompress_zstd_frame(data.data(), data.size(), file_, describe(p));
    if (plain.size() > prefix) plain.resize(prefix);
    return plain;
  }

  std::string describe(const MessagePosition& p) const override {
    return "message row " + std::to_string(p.offset);
  }

 private:
  void read_tables() {
    std::map<std::int64_t, std::uint16_t> topics;  // topic id → index in connections_
    {
      Statement s(db_, "SELECT id, name, type, serialization_format FROM topics ORDER BY id", file_);
      while (s.step()) {
        if (connections_.size() > 0xFFFF) throw InputError(file_, "", "more than 65536 topics");
        topics[s.integer(0)] = static_cast<std::uint16_t>(connections_.size());
        const std::string format = s.text(3);
        connections_.push_back(Connection{s.text(1), s.text(2), format, encoding_of(format), 0});
      }
    }
    {
      Statement s(db_,
                  "SELECT topic_id, COUNT(*), MIN(timestamp), MAX(timestamp) FROM messages GROUP BY topic_id",
                  file_);
      while (s.step()) {
        const auto topic = topics.find(s.integer(0));
        if (topic == topics.end())
          throw InputError(file_, "table messages",
                           std::to_string(s.integer(1)) + " messages of topic id " +
                               std::to_string(s.integer(0)) + ", which the topics table does not list");
        connections_[topic->second].messages = static_cast<std::uint64_t>(s.integer(1));
        saw_time(s.integer(2));
        saw_time(s.integer(3));
      }
    }
    Statement s(db_, "SELECT id, timestamp FROM messages WHERE topic_id = ?1", file_);
    for (const auto& [id, index] : topics) {
      if (!keeps(index)) continue;
      s.bind(1, id);
      while (s.step())
        kept_.push_back(MessagePosition{s.integer(1), static_cast<std::uint64_t>(s.integer(0)), kNoChunk,
                                        file_index_, index});
      s.reset();
    }
  }

  sqlite3* db_ = nullptr;
  bool zstd_messages_;
  mutable std::mutex mutex_;  ///< one connection, used by one thread at a time
};

}  // namespace

std::unique_ptr<Container> open_rosbag2_sqlite(const std::filesystem::path& file, std::uint16_t file_index,
                                               bool zstd_messages, KeepMessages keep) {
  return std::make_unique<Rosbag2Sqlite>(file, file_index, zstd_messages, std::move(keep));
}

}  // namespace sextant::recordings_detail
