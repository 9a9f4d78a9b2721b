// Test-only ROS 2 bag folders (rosbag2_writer.hpp).
#include "rosbag2_writer.hpp"

#include <sqlite3.h>

#include <fstream>
#include <map>
#include <stdexcept>

#include "mcap_writer.hpp"

namespace sextant::test {
namespace {

void exec(sqlite3* db, const std::string& sql) {
  char* error = nullptr;
  if (sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string why = error ? error : "?";
    sqlite3_free(error);
    throw std::runtime_error("sqlite3: " + why);
  }
}

void write_db3(const std::filesystem::path& file, const std::vector<TestMessage>& messages, bool zstd) {
  std::filesystem::remove(file);
  sqlite3* db = nullptr;
  if (sqlite3_open(file.string().c_str(), &db) != SQLITE_OK) throw std::runtime_error("sqlite3 open");
  exec(db,
       "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
       "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);"
       "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, "
       "data BLOB NOT NULL);"
       "BEGIN;");
  std::map<std::string, int> topics;
  sqlite3_stmt* topic = nullptr;
  sqlite3_stmt* message = nullptr;
  sqlite3_prepare_v2(db, "INSERT INTO topics VALUES(?1, ?2, ?3, 'cdr', '')", -1, &topic, nullptr);
  sqlite3_prepare_v2(db, "INSERT INTO messages(topic_id, timestamp, data) VALUES(?1, ?2, ?3)", -1, &message,
                     nullptr);
  for (const TestMessage& m : messages) {
    if (!topics.count(m.topic)) {
      const int id = static_cast<int>(topics.size()) + 1;
      topics[m.topic] = id;
      sqlite3_bind_int(topic, 1, id);
      sqlite3_bind_text(topic, 2, m.topic.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(topic, 3, m.type.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_step(topic);
      sqlite3_reset(topic);
    }
    const Bytes data = zstd ? compress("zstd", m.data) : m.data;
    sqlite3_bind_int(message, 1, topics[m.topic]);
    sqlite3_bind_int64(message, 2, m.log_time);
    sqlite3_bind_blob(message, 3, data.data(), static_cast<int>(data.size()), SQLITE_TRANSIENT);
    if (sqlite3_step(message) != SQLITE_DONE) throw std::runtime_error("sqlite3 insert");
    sqlite3_reset(message);
  }
  sqlite3_finalize(topic);
  sqlite3_finalize(message);
  exec(db, "COMMIT;");
  sqlite3_close(db);
}

}  // namespace

void write_rosbag2(const std::filesystem::path& folder, const std::vector<TestMessage>& messages,
                   const Rosbag2Options& o) {
  std::filesystem::create_directories(folder);
  const std::string name = folder.filename().string();
  const std::string extension = o.storage == "mcap" ? ".mcap" : ".db3";
  std::vector<std::string> files;
  const std::size_t per_file = (messages.size() + o.files - 1) / o.files;
  for (std::size_t f = 0; f < o.files; ++f) {
    const std::size_t begin = std::min(messages.size(), f * per_file);
    const std::vector<TestMessage> part(
        messages.begin() + static_cast<std::ptrdiff_t>(begin),
        messages.begin() + static_cast<std::ptrdiff_t>(std::min(messages.size(), begin + per_file)));
    files.push_back(name + "_" + std::to_string(f) + extension);
    if (o.storage == "mcap") {
      McapOptions m;
      m.compression = "zstd";
      write_mcap(folder / files.back(), part, m);
    } else {
      write_db3(folder / files.back(), part, o.zstd_messages);
    }
  }
  if (!o.metadata) return;
  std::map<std::string, std::pair<std::string, std::size_t>> topics;
  for (const TestMessage& m : messages) {
    topics[m.topic].first = m.type;
    ++topics[m.topic].second;
  }
  std::ofstream yaml(folder / "metadata.yaml");
  yaml << "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: " << o.storage
       << "\n  duration:\n    nanoseconds: 0\n  starting_time:\n    nanoseconds_since_epoch: 0\n  "
          "message_count: "
       << messages.size() << "\n  topics_with_message_count:\n";
  for (const auto& [topic, info] : topics)
    yaml << "    - topic_metadata:\n        name: " << topic << "\n        type: " << info.first
         << "\n        serialization_format: cdr\n        offered_qos_profiles: \"- history: 3\\n  depth: "
            "0\"\n"
         << "      message_count: " << info.second << "\n";
  yaml << "  compression_format: " << (o.zstd_messages ? "zstd" : "\"\"") << "\n  compression_mode: "
       << (!o.compression_mode.empty() ? o.compression_mode
           : o.zstd_messages           ? "MESSAGE"
                                       : "\"\"")
       << "\n  relative_file_paths:\n";
  for (const std::string& f : files) yaml << "    - " << f << "\n";
}

}  // namespace sextant::test
