// Broken recordings are refused with an InputError that names the file, the byte (or record) and the
// problem: truncated files, unknown compressions, corrupt chunks, wrong magic, broken ROS 2 bag folders.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "bag_writer.hpp"
#include "known_scans.hpp"
#include "mcap_writer.hpp"
#include "rosbag2_writer.hpp"
#include "sextant/core/error.hpp"
#include "sextant/recordings/recording.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

/// The InputError of reading every scan of `path` (opening included), or a failure when there is none.
InputError read_error(const fs::path& path) {
  try {
    const std::unique_ptr<Dataset> d = open_recording(path);
    for (std::size_t i = 0; i < d->size(); ++i) d->scan(i);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << path << " read without an error";
  return InputError("", "", "");
}

void expect_error(const fs::path& path, const std::string& where, const std::string& problem) {
  const InputError e = read_error(path);
  EXPECT_EQ(e.file(), path.string()) << e.what();
  EXPECT_NE(e.where().find(where), std::string::npos) << e.what();
  EXPECT_NE(e.problem().find(problem), std::string::npos) << e.what();
}

std::string bytes_of(const fs::path& file) {
  return test::read_text(file);
}

void write_bytes(const fs::path& file, const std::string& bytes) {
  test::write_text(file, bytes);
}

TEST(BadRecordings, ATruncatedBagNamesTheRecordItBreaksIn) {
  const test::TempDir tmp;
  test::write_bag(tmp / "a.bag", test::known_messages(20, true), test::bag_options("lz4", 10, true, false));
  const std::string whole = bytes_of(tmp / "a.bag");
  write_bytes(tmp / "cut.bag",
              whole.substr(0, whole.size() / 2));  // its index is gone: one pass, cut in a chunk
  expect_error(tmp / "cut.bag", "byte ", "truncated record");
}

TEST(BadRecordings, UnknownCompressionsAreNamed) {
  const test::TempDir tmp;
  test::write_bag(tmp / "a.bag", test::known_messages(3, true), test::bag_options("zlib", 10, false, false));
  expect_error(tmp / "a.bag", "byte 4109",
               "unknown chunk compression 'zlib' (ROS 1 bags use none, bz2 or lz4)");
  test::McapOptions brotli;
  brotli.compression = "brotli";
  test::write_mcap(tmp / "a.mcap", test::known_messages(3, false), brotli);
  expect_error(tmp / "a.mcap", "byte ",
               "unknown chunk compression 'brotli' (MCAP chunks are uncompressed, zstd or lz4)");
}

TEST(BadRecordings, ACorruptChunkIsNamedWhenItsScanIsRead) {
  const test::TempDir tmp;
  test::write_bag(tmp / "a.bag", test::known_messages(4, true), test::bag_options("bz2", 10, true, false));
  std::string bag = bytes_of(tmp / "a.bag");
  const std::size_t chunk = 4109;  // the first record after the 4096-byte bag header
  const std::size_t bz = bag.find("BZh", chunk);
  bag[bz + 40] = static_cast<char>(bag[bz + 40] ^ 0x5A);
  write_bytes(tmp / "a.bag", bag);
  const std::unique_ptr<Dataset> d = open_recording(tmp / "a.bag");  // the index is intact
  try {
    d->scan(0);
    ADD_FAILURE() << "a corrupt chunk read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "the bz2 chunk at byte " + std::to_string(chunk)) << e.what();
    EXPECT_NE(e.problem().find("corrupt bz2 data"), std::string::npos) << e.what();
  }
  test::McapOptions zstd;
  zstd.compression = "zstd";
  test::write_mcap(tmp / "a.mcap", test::known_messages(4, false), zstd);
  std::string mcap = bytes_of(tmp / "a.mcap");
  const std::size_t frame = mcap.find("\x28\xb5\x2f\xfd");  // zstd's magic
  for (std::size_t k = frame + 12; k < frame + 40; ++k) mcap[k] = static_cast<char>(~mcap[k]);
  write_bytes(tmp / "a.mcap", mcap);
  expect_error(tmp / "a.mcap", "zstd chunk at byte ", "corrupt zstd data");
}

TEST(BadRecordings, ABrokenCloudInsideAGoodChunkNamesTheMessageAndTheScan) {
  const test::TempDir tmp;
  std::vector<test::TestMessage> messages = test::known_messages(3, false);
  messages[2].data.resize(messages[2].data.size() - 30);  // scan 1, its point data cut
  test::write_mcap(tmp / "a.mcap", messages, {});
  const InputError e = read_error(tmp / "a.mcap");
  EXPECT_NE(e.where().find("of the message at byte "), std::string::npos) << e.what();
  EXPECT_NE(e.where().find("of the uncompressed chunk at byte "), std::string::npos) << e.what();
  EXPECT_NE(e.where().find("(/points, scan 1)"), std::string::npos) << e.what();
  EXPECT_NE(e.problem().find("the point data claim 100 bytes"), std::string::npos) << e.what();
}

TEST(BadRecordings, WrongMagicEmptyFilesAndOtherVersions) {
  const test::TempDir tmp;
  write_bytes(tmp / "old.bag", "#ROSBAG V1.2\nsomething");
  expect_error(tmp / "old.bag", "byte 0", "ROS 1 bag version '1.2': sextant reads v2.0");
  write_bytes(tmp / "empty.bag", "");
  expect_error(tmp / "empty.bag", "byte 0", "empty file (0 bytes), not a recording");
  write_bytes(tmp / "text.mcap", "hello, not an MCAP file");
  expect_error(tmp / "text.mcap", "byte 0", "not a recording");
  test::write_mcap(tmp / "cut.mcap", test::known_messages(6, false), {});
  const std::string whole = bytes_of(tmp / "cut.mcap");
  write_bytes(tmp / "cut.mcap", whole.substr(0, whole.size() / 2));
  expect_error(tmp / "cut.mcap", "byte ", "truncated");
}

TEST(BadRecordings, BrokenRosbag2Folders) {
  const test::TempDir tmp;
  test::write_rosbag2(tmp / "bag", test::known_messages(4, false), {});
  fs::remove(tmp / "bag" / "bag_0.db3");
  try {
    open_recording(tmp / "bag");
    ADD_FAILURE() << "a bag without its file opened";
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), (tmp / "bag" / "bag_0.db3").string());
    EXPECT_NE(std::string(e.what()).find("listed in"), std::string::npos) << e.what();
  }
  test::Rosbag2Options per_file;
  per_file.zstd_messages = true;
  per_file.compression_mode = "FILE";
  test::write_rosbag2(tmp / "zipped", test::known_messages(4, false), per_file);
  const InputError zipped = read_error(tmp / "zipped");
  EXPECT_EQ(zipped.file(), (tmp / "zipped" / "metadata.yaml").string());
  EXPECT_NE(zipped.problem().find("compressed file by file"), std::string::npos) << zipped.what();
  write_bytes(tmp / "junk" / "junk_0.db3", "SQLite format 3");  // a header and nothing else
  EXPECT_TRUE(is_recording(tmp / "junk"));
  const InputError e = read_error(tmp / "junk");
  EXPECT_EQ(e.file(), (tmp / "junk" / "junk_0.db3").string()) << e.what();
}

}  // namespace
}  // namespace sextant
