// A long recording streams: opening it keeps 32 bytes per scan (a position and a stamp), and reading every
// scan decompresses each chunk once and never holds more than the cache's few chunks, whatever the length.
#include <gtest/gtest.h>

#include "bag_writer.hpp"
#include "known_scans.hpp"
#include "mcap_writer.hpp"
#include "recording_dataset.hpp"
#include "sextant/recordings/recording.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

using recordings_detail::kCachedChunks;
using recordings_detail::RecordingDataset;

constexpr std::size_t kScans = 18000;  // 30 minutes at 10 Hz
constexpr std::size_t kPerChunk = 100;

std::vector<test::TestMessage> scans_only(bool ros1) {
  std::vector<test::TestMessage> messages;
  messages.reserve(kScans);
  for (std::size_t k = 0; k < kScans; ++k) messages.push_back(test::known_message(k, ros1, "/points", 3));
  return messages;
}

void expect_streams(const std::filesystem::path& path) {
  const std::unique_ptr<Dataset> opened = open_recording(path);
  const auto* d = dynamic_cast<const RecordingDataset*>(opened.get());
  ASSERT_NE(d, nullptr);
  ASSERT_EQ(d->size(), kScans);
  EXPECT_EQ(d->index_bytes(), kScans * (sizeof(recordings_detail::MessagePosition) + sizeof(double)));
  EXPECT_EQ(d->index_bytes(), kScans * 32);
  EXPECT_EQ(d->cache().size(), 0u);  // opening decompressed nothing it kept
  std::size_t points = 0;
  for (std::size_t k = 0; k < kScans; ++k) {
    const PointCloud cloud = d->scan(k);
    points += cloud.size();
    ASSERT_LE(d->cache().size(), kCachedChunks) << k;
    if (k % 997 == 0) test::expect_known_scan(cloud, k, 3);
  }
  EXPECT_EQ(points, 3 * kScans - 1);  // scan 0's first point is (0, 0, 0)
  EXPECT_EQ(d->cache().largest_size(), kCachedChunks);
  EXPECT_EQ(d->cache().loads(), kScans / kPerChunk);  // in order: each chunk decompressed once
  EXPECT_NEAR(*d->stamp(kScans - 1) - *d->stamp(0), 0.1 * (kScans - 1), 1e-3);
}

TEST(Streaming, An18000ScanMcapReadsWithBoundedMemory) {
  const test::TempDir tmp;
  test::McapOptions o;
  o.compression = "zstd";
  o.messages_per_chunk = kPerChunk;
  test::write_mcap(tmp / "long.mcap", scans_only(false), o);
  expect_streams(tmp / "long.mcap");
}

TEST(Streaming, An18000ScanBagReadsWithBoundedMemory) {
  const test::TempDir tmp;
  test::write_bag(tmp / "long.bag", scans_only(true), test::bag_options("lz4", kPerChunk, true, false));
  expect_streams(tmp / "long.bag");
}

}  // namespace
}  // namespace sextant
