#pragma once
// Private: the few decompressed chunks a recording keeps, so that the scans of one chunk decompress it
// once, and memory stays that of `capacity` chunks however long the recording is. Safe from several
// threads: a chunk missing is decompressed outside the lock (two threads may both do it; one copy stays).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <utility>

#include "byte_cursor.hpp"

namespace sextant::recordings_detail {

class ChunkCache {
 public:
  explicit ChunkCache(std::size_t capacity = 4) : capacity_(capacity < 1 ? 1 : capacity) {}

  /// The chunk `key` (file and chunk number), from the cache or from `load`; the least recently used
  /// chunk leaves when the cache holds `capacity` of them.
  std::shared_ptr<const Bytes> get(std::uint64_t key, const std::function<Bytes()>& load);

  std::size_t capacity() const { return capacity_; }
  /// Chunks held now, and the most it ever held.
  std::size_t size() const;
  std::size_t largest_size() const;
  /// How many times a chunk was decompressed.
  std::size_t loads() const;
  /// Bytes the chunks held now take.
  std::size_t bytes() const;

 private:
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::list<std::pair<std::uint64_t, std::shared_ptr<const Bytes>>> chunks_;  ///< most recent first
  std::size_t largest_ = 0, loads_ = 0;
};

/// The key of chunk `chunk` of file `file`.
inline std::uint64_t chunk_key(std::uint32_t file, std::uint32_t chunk) {
  return static_cast<std::uint64_t>(file) << 32 | chunk;
}

}  // namespace sextant::recordings_detail
