#pragma once
// Test-only: MCAP files written from the specification (mcap.dev/spec): magic, header, chunks of
// schema, channel and message records (or the records unchunked), message indexes after each chunk,
// Data End, and a summary (schemas, channels, chunk indexes, statistics) with its footer.
#include <filesystem>
#include <string>
#include <vector>

#include "recording_message.hpp"

namespace sextant::test {

struct McapOptions {
  std::string profile = "ros2";  ///< ros2: channels encoded "cdr", schemas "ros2msg"; ros1: "ros1", "ros1msg"
  std::string compression;       ///< "", "zstd", "lz4" (or any name, to test that it is refused)
  std::size_t messages_per_chunk = 10;
  bool chunked = true;
  bool summary = true;  ///< false: no summary, footer summary_start 0 (a reader makes one pass)
  bool footer = true;   ///< false: the file ends after the data section (a writer that stopped)
};

/// Writes `messages` (in their order, one channel per topic) to `file`.
void write_mcap(const std::filesystem::path& file, const std::vector<TestMessage>& messages,
                const McapOptions& options = {});

}  // namespace sextant::test
