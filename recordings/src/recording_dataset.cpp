// The Dataset of one PointCloud2 topic of a recording (recording_dataset.hpp).
#include "recording_dataset.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "point_cloud2.hpp"

namespace sextant::recordings_detail {

std::optional<std::int64_t> OpenedRecording::first_time() const {
  std::optional<std::int64_t> t;
  for (const auto& c : containers)
    if (c->first_time() && (!t || *c->first_time() < *t)) t = c->first_time();
  return t;
}

std::optional<std::int64_t> OpenedRecording::last_time() const {
  std::optional<std::int64_t> t;
  for (const auto& c : containers)
    if (c->last_time() && (!t || *c->last_time() > *t)) t = c->last_time();
  return t;
}

OpenedRecording open_recording_files(RecordingFiles files) {
  OpenedRecording r;
  if (files.files.size() > 0xFFFF) throw std::length_error("a recording of more than 65536 files");
  for (std::size_t k = 0; k < files.files.size(); ++k)
    r.containers.push_back(
        open_container(files.files[k], static_cast<std::uint16_t>(k), files.zstd_messages));
  r.files = std::move(files);
  return r;
}

RecordingDataset::RecordingDataset(OpenedRecording recording, std::string topic,
                                   std::vector<MessagePosition> scans, DatasetMetadata metadata)
    : recording_(std::move(recording)),
      topic_(std::move(topic)),
      scans_(std::move(scans)),
      stamps_(scans_.size(), std::numeric_limits<double>::quiet_NaN()),
      meta_(std::move(metadata)) {
  scans_.shrink_to_fit();
  meta_.scan_count = scans_.size();
}

const MessagePosition& RecordingDataset::position(std::size_t i) const {
  if (i >= scans_.size())
    throw std::out_of_range("scan index " + std::to_string(i) + " out of range (" +
                            std::to_string(scans_.size()) + " scans)");
  return scans_[i];
}

Place RecordingDataset::place(std::size_t i) const {
  const MessagePosition& p = position(i);
  const Container& c = *recording_.containers.at(p.file);
  return Place{c.file(), 0, "", " of " + c.describe(p) + " (" + topic_ + ", scan " + std::to_string(i) + ")"};
}

void RecordingDataset::remember_stamp(std::size_t i, double stamp) const {
  const std::lock_guard<std::mutex> lock(stamps_mutex_);
  stamps_[i] = stamp;
}

PointCloud RecordingDataset::scan(std::size_t i, ScanLoadReport* report) const {
  const MessagePosition& p = position(i);
  const Container& c = *recording_.containers.at(p.file);
  const Bytes payload = c.read_message(p, cache_);
  const Place where = place(i);
  const MessageEncoding encoding = c.connections().at(p.connection).encoding;
  const PointCloud2Message message = parse_point_cloud2(payload, encoding, where);
  remember_stamp(i, message.stamp);
  return point_cloud2_points(message, payload, where, report);
}

std::optional<double> RecordingDataset::stamp(std::size_t i) const {
  const MessagePosition& p = position(i);
  {
    const std::lock_guard<std::mutex> lock(stamps_mutex_);
    if (!std::isnan(stamps_[i])) return stamps_[i];
  }
  const Container& c = *recording_.containers.at(p.file);
  const Bytes prefix = c.read_message(p, cache_, 16);
  const double t = point_cloud2_stamp(prefix, c.connections().at(p.connection).encoding, place(i));
  remember_stamp(i, t);
  return t;
}

std::optional<Eigen::Isometry3d> RecordingDataset::odometry(std::size_t i) const {
  (void)position(i);
  return std::nullopt;
}

std::optional<Eigen::Isometry3d> RecordingDataset::ground_truth(std::size_t i) const {
  (void)position(i);
  return std::nullopt;
}

std::filesystem::path RecordingDataset::scan_file(std::size_t i) const {
  return recording_.containers.at(position(i).file)->file();
}

std::size_t RecordingDataset::index_bytes() const {
  return scans_.capacity() * sizeof(MessagePosition) + stamps_.capacity() * sizeof(double);
}

}  // namespace sextant::recordings_detail
