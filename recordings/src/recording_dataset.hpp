#pragma once
// Private: the Dataset of one PointCloud2 topic of a recording. It holds the recording's files open,
// one 24-byte position per scan and its stamp once read (8 bytes), and a cache of at most a few
// decompressed chunks: memory does not grow with the recording beyond the positions.
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "chunk_cache.hpp"
#include "container.hpp"
#include "recording_files.hpp"
#include "sextant/core/dataset.hpp"

namespace sextant::recordings_detail {

/// A recording's files, opened.
struct OpenedRecording {
  RecordingFiles files;
  std::vector<std::unique_ptr<Container>> containers;
  /// The log time of its first message, any topic [ns].
  std::optional<std::int64_t> first_time() const;
  std::optional<std::int64_t> last_time() const;
};
OpenedRecording open_recording_files(RecordingFiles files);

/// The chunks a recording's dataset keeps decompressed at most.
inline constexpr std::size_t kCachedChunks = 4;

class RecordingDataset : public Dataset {
 public:
  /// `scans`: the positions of the topic's messages chosen, in log-time order.
  RecordingDataset(OpenedRecording recording, std::string topic, std::vector<MessagePosition> scans,
                   DatasetMetadata metadata);

  const DatasetMetadata& metadata() const override { return meta_; }
  PointCloud scan(std::size_t i, ScanLoadReport* report = nullptr) const override;
  std::optional<Eigen::Isometry3d> odometry(std::size_t i) const override;
  std::optional<Eigen::Isometry3d> ground_truth(std::size_t i) const override;
  /// The message's header stamp [s since the epoch], read from its first bytes when first asked.
  std::optional<double> stamp(std::size_t i) const override;
  std::filesystem::path scan_file(std::size_t i) const override;

  /// Bytes held per scan (its position and stamp), times the scans: what grows with the recording.
  std::size_t index_bytes() const;
  const ChunkCache& cache() const { return cache_; }
  /// The log time of scan i [ns].
  std::int64_t log_time(std::size_t i) const { return scans_.at(i).log_time; }

 private:
  const MessagePosition& position(std::size_t i) const;
  Place place(std::size_t i) const;
  void remember_stamp(std::size_t i, double stamp) const;

  OpenedRecording recording_;
  std::string topic_;
  std::vector<MessagePosition> scans_;
  mutable std::mutex stamps_mutex_;
  mutable std::vector<double> stamps_;  ///< NaN until read
  mutable ChunkCache cache_{kCachedChunks};
  DatasetMetadata meta_;
};

}  // namespace sextant::recordings_detail
