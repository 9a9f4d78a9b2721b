#pragma once
// Private: a recording's topics over all its files and connections, and the choice of the scans' topic.
#include <string>
#include <vector>

#include "recording_dataset.hpp"
#include "sextant/recordings/recording.hpp"

namespace sextant::recordings_detail {

/// Every topic of the recording, by name (counts summed over files and connections; no point fields).
std::vector<TopicSummary> recording_topics(const OpenedRecording& recording);

/// The topic the scans come from: `selection.topic`, or the only PointCloud2 topic. InputError naming
/// `path` and listing the topics (with their counts) when there is none, several, or the named one is
/// missing or not a point cloud.
const TopicSummary& choose_topic(const std::vector<TopicSummary>& topics, const RecordingSelection& selection,
                                 const std::string& path);

/// "/a (120 messages), /b (60 messages)".
std::string topic_list(const std::vector<TopicSummary>& topics, bool point_clouds_only);

}  // namespace sextant::recordings_detail
