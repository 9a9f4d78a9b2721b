// The few decompressed chunks a recording keeps (chunk_cache.hpp).
#include "chunk_cache.hpp"

#include <algorithm>

namespace sextant::recordings_detail {

std::shared_ptr<const Bytes> ChunkCache::get(std::uint64_t key, const std::function<Bytes()>& load) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto it =
        std::find_if(chunks_.begin(), chunks_.end(), [&](const auto& c) { return c.first == key; });
    if (it != chunks_.end()) {
      chunks_.splice(chunks_.begin(), chunks_, it);
      return chunks_.front().second;
    }
  }
  auto chunk = std::make_shared<const Bytes>(load());
  const std::lock_guard<std::mutex> lock(mutex_);
  ++loads_;
  const auto it = std::find_if(chunks_.begin(), chunks_.end(), [&](const auto& c) { return c.first == key; });
  if (it != chunks_.end()) return it->second;  // another thread loaded it meanwhile
  chunks_.emplace_front(key, chunk);
  while (chunks_.size() > capacity_) chunks_.pop_back();
  largest_ = std::max(largest_, chunks_.size());
  return chunk;
}

std::size_t ChunkCache::size() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return chunks_.size();
}

std::size_t ChunkCache::largest_size() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return largest_;
}

std::size_t ChunkCache::loads() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return loads_;
}

std::size_t ChunkCache::bytes() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::size_t total = 0;
  for (const auto& c : chunks_) total += c.second->size();
  return total;
}

}  // namespace sextant::recordings_detail
