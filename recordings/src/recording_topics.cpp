// A recording's topics and the choice of the scans' topic (recording_topics.hpp).
#include "recording_topics.hpp"

#include <algorithm>
#include <map>

#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {
namespace {

std::string messages_text(std::uint64_t n) {
  return std::to_string(n) + (n == 1 ? " message" : " messages");
}

}  // namespace

std::vector<TopicSummary> recording_topics(const OpenedRecording& recording) {
  std::map<std::string, TopicSummary> topics;
  for (const auto& container : recording.containers) {
    for (const Connection& c : container->connections()) {
      TopicSummary& t = topics[c.topic];
      if (t.name.empty()) {
        t.name = c.topic;
        t.type = c.type;
        t.encoding = c.encoding_name;
      } else if (t.type != c.type && c.type.size() > 0 && t.type.find(c.type) == std::string::npos) {
        t.type += " | " + c.type;  // two publishers disagree; the topic is not read as scans
      }
      t.messages += c.messages;
    }
  }
  std::vector<TopicSummary> out;
  for (auto& [name, t] : topics) {
    t.point_cloud = is_point_cloud2_type(t.type);
    out.push_back(std::move(t));
  }
  return out;
}

std::string topic_list(const std::vector<TopicSummary>& topics, bool point_clouds_only) {
  std::string list;
  for (const TopicSummary& t : topics) {
    if (point_clouds_only && !t.point_cloud) continue;
    list += (list.empty() ? "" : ", ") + t.name + " (" + (point_clouds_only ? "" : t.type + ", ") +
            messages_text(t.messages) + ")";
  }
  return list.empty() ? "none" : list;
}

const TopicSummary& choose_topic(const std::vector<TopicSummary>& topics, const RecordingSelection& selection,
                                 const std::string& path) {
  const std::size_t clouds = static_cast<std::size_t>(
      std::count_if(topics.begin(), topics.end(), [](const TopicSummary& t) { return t.point_cloud; }));
  const std::string ask = "choose one with " + selection.topic_argument;
  if (!selection.topic.empty()) {
    const auto it = std::find_if(topics.begin(), topics.end(),
                                 [&](const TopicSummary& t) { return t.name == selection.topic; });
    if (it == topics.end())
      throw InputError(path, "",
                       "no topic '" + selection.topic +
                           "' (its sensor_msgs/PointCloud2 topics: " + topic_list(topics, true) + ")");
    if (!it->point_cloud)
      throw InputError(
          path, "",
          "topic '" + it->name + "' holds " + it->type +
              ", not sensor_msgs/PointCloud2 (its point-cloud topics: " + topic_list(topics, true) + ")");
    return *it;
  }
  if (clouds == 0)
    throw InputError(
        path, "",
        "no sensor_msgs/PointCloud2 topic to read scans from; its topics: " + topic_list(topics, false));
  if (clouds > 1)
    throw InputError(
        path, "",
        std::to_string(clouds) + " sensor_msgs/PointCloud2 topics: " + topic_list(topics, true) + "; " + ask);
  return *std::find_if(topics.begin(), topics.end(), [](const TopicSummary& t) { return t.point_cloud; });
}

}  // namespace sextant::recordings_detail
