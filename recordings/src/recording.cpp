// Robot recordings as datasets (recording.hpp): finding a recording's files, describing them, and the
// scans of one topic in log-time order.
#include "sextant/recordings/recording.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "point_cloud2.hpp"
#include "recording_dataset.hpp"
#include "recording_files.hpp"
#include "recording_topics.hpp"
#include "sextant/core/error.hpp"

namespace sextant {
namespace {

using namespace recordings_detail;

RecordingFiles files_of(const std::filesystem::path& path) {
  std::optional<RecordingFiles> files = find_recording_files(path);
  if (!files)
    throw InputError(path.string(), "",
                     "not a recording (a ROS 1 .bag, an .mcap file, or a ROS 2 bag folder with metadata.yaml "
                     "or .db3 files)");
  return std::move(*files);
}

std::string storage_of(const OpenedRecording& r) {
  std::string storage = r.containers.empty() ? "" : r.containers.front()->storage();
  if (r.containers.size() > 1)
    storage = std::to_string(r.containers.size()) + " files, the first: " + storage;
  if (!r.files.layout.empty()) storage += " (" + r.files.layout + ")";
  return storage;
}

/// The positions of every point-cloud topic's messages in all files, by topic, each in log-time order
/// (ties: file, then place in it).
std::map<std::string, std::vector<MessagePosition>> point_cloud_messages(OpenedRecording& r) {
  std::map<std::string, std::vector<MessagePosition>> topics;
  for (auto& container : r.containers)
    for (const MessagePosition& p : container->take_kept_messages())
      topics[container->connections()[p.connection].topic].push_back(p);
  for (auto& [topic, all] : topics)
    std::stable_sort(all.begin(), all.end(), [](const MessagePosition& a, const MessagePosition& b) {
      if (a.log_time != b.log_time) return a.log_time < b.log_time;
      if (a.file != b.file) return a.file < b.file;
      if (a.chunk != b.chunk) return a.chunk < b.chunk;
      return a.offset < b.offset;
    });
  return topics;
}

bool chooses_a_part(const RecordingSelection& s) {
  return s.start != 0.0 || s.duration || s.every != 1;
}

std::string seconds_text(double s) {
  std::ostringstream out;
  out << s;
  return out.str() + " s";
}

std::string ordinal(std::size_t n) {
  const std::size_t tens = n % 100, ones = n % 10;
  const char* suffix = tens >= 11 && tens <= 13 ? "th"
                       : ones == 1              ? "st"
                       : ones == 2              ? "nd"
                       : ones == 3              ? "rd"
                                                : "th";
  return std::to_string(n) + suffix;
}

std::string selection_text(const RecordingSelection& s) {
  std::string text = "from " + seconds_text(s.start);
  text += s.duration ? " for " + seconds_text(*s.duration) : " to the end";
  if (s.every > 1) text += ", every " + ordinal(s.every) + " message";
  return text;
}

/// [ns] of `seconds` (≥ 0), saturated at 4·10^9 s: beyond any recording, and added to a log time (ns since
/// 1970) it does not overflow.
std::int64_t nanoseconds(double seconds) {
  return seconds >= 4e9 ? std::int64_t{4000000000000000000} : std::llround(seconds * 1e9);
}

/// The chosen part of `all` (log-time order): from first + start for duration, every N-th.
std::vector<MessagePosition> select(const std::vector<MessagePosition>& all, const RecordingSelection& s,
                                    std::int64_t first) {
  // Log times are whatever the file says (an MCAP time beyond 2^63 ns reads as negative): the sums and
  // differences are taken so that none overflows.
  const std::int64_t start = nanoseconds(s.start);
  const std::int64_t from = first > std::numeric_limits<std::int64_t>::max() - start
                                ? std::numeric_limits<std::int64_t>::max()
                                : first + start;
  const std::uint64_t length = s.duration ? static_cast<std::uint64_t>(nanoseconds(*s.duration))
                                          : std::numeric_limits<std::uint64_t>::max();
  std::vector<MessagePosition> chosen;
  std::size_t k = 0;
  for (const MessagePosition& p : all) {
    if (p.log_time < from) continue;
    if (static_cast<std::uint64_t>(p.log_time) - static_cast<std::uint64_t>(from) >= length) continue;
    if (k++ % s.every == 0) chosen.push_back(p);
  }
  return chosen;
}

}  // namespace

bool RecordingSelection::is_default() const {
  return topic.empty() && start == 0.0 && !duration && every == 1;
}

std::pair<std::string, std::string> RecordingSelection::problem() const {
  if (!std::isfinite(start) || start < 0.0)
    return {"start", "expected a finite number of seconds ≥ 0 from the recording's start"};
  if (duration && !(std::isfinite(*duration) && *duration > 0.0))
    return {"duration", "expected a finite number of seconds > 0"};
  if (every < 1) return {"every", "expected a whole number ≥ 1"};
  return {};
}

bool RecordingSelection::valid(std::string* why) const {
  const auto [field, problem_text] = problem();
  if (why) *why = field.empty() ? "" : field + ": " + problem_text;
  return field.empty();
}

bool is_recording(const std::filesystem::path& path) {
  try {
    return find_recording_files(path).has_value();
  } catch (const InputError&) {
    return true;  // a recording whose metadata is broken: opening it says how
  }
}

RecordingSummary describe_recording(const std::filesystem::path& path) {
  OpenedRecording r = open_recording_files(files_of(path));
  RecordingSummary s;
  s.path = path;
  s.format = r.files.format;
  s.files = r.files.files;
  s.storage = storage_of(r);
  if (const auto t = r.first_time()) s.start = 1e-9 * static_cast<double>(*t);
  if (const auto t = r.last_time()) s.end = 1e-9 * static_cast<double>(*t);
  s.topics = recording_topics(r);
  std::map<std::string, std::vector<MessagePosition>> clouds = point_cloud_messages(r);
  for (TopicSummary& t : s.topics) {
    s.messages += t.messages;
    const std::vector<MessagePosition>& messages = clouds[t.name];
    if (!t.point_cloud || messages.empty()) continue;
    const MessagePosition& first = messages.front();
    const Container& c = *r.containers[first.file];
    ChunkCache cache(1);
    const Bytes payload = c.read_message(first, cache);
    const PointCloud2Message m = parse_point_cloud2(
        payload, c.connections()[first.connection].encoding,
        Place{c.file(), 0, "", " of " + c.describe(first) + " (the first message of " + t.name + ")"});
    for (const PointField2& f : m.fields)
      t.fields.push_back({f.name, datatype_name(f.datatype), f.offset, f.count});
    t.height = m.height;
    t.width = m.width;
    t.point_step = m.point_step;
    t.frame_id = m.frame_id;
  }
  return s;
}

std::unique_ptr<Dataset> open_recording(const std::filesystem::path& path,
                                        const RecordingSelection& selection) {
  std::string why;
  if (!selection.valid(&why)) throw InputError(path.string(), "", "recording selection: " + why);
  OpenedRecording r = open_recording_files(files_of(path));
  const std::vector<TopicSummary> topics = recording_topics(r);
  const TopicSummary& topic = choose_topic(topics, selection, path.string());
  if (topic.encoding != "ros1" && topic.encoding != "ros" && topic.encoding != "cdr")
    throw InputError(path.string(), "",
                     "topic '" + topic.name + "' is encoded '" + topic.encoding +
                         "': sextant reads ROS 1 and CDR messages");
  const std::vector<MessagePosition> all = std::move(point_cloud_messages(r)[topic.name]);
  if (all.empty()) throw InputError(path.string(), "", "topic '" + topic.name + "' has no messages");
  // The recording starts at its first message, which an index that lies about its chunks' times must
  // not put after the topic's own first message.
  const std::int64_t first = std::min(*r.first_time(), all.front().log_time);
  std::vector<MessagePosition> chosen = select(all, selection, first);
  const double span = 1e-9 * (static_cast<double>(std::max(*r.last_time(), all.back().log_time)) -
                              static_cast<double>(first));
  if (chosen.empty())
    throw InputError(path.string(), "",
                     "the selection (" + selection_text(selection) + ") holds none of the " +
                         std::to_string(all.size()) + " messages of " + topic.name +
                         " (the recording spans " + seconds_text(span) + ")");
  DatasetMetadata meta;
  meta.name = path.filename().empty() ? path.parent_path().filename().string() : path.filename().string();
  meta.format = r.files.format;
  meta.path = path;
  meta.notes.push_back("topic " + topic.name + " (" + topic.type + ", " + topic.encoding +
                       "): " + std::to_string(chosen.size()) + " of its " + std::to_string(all.size()) +
                       " messages" + (chooses_a_part(selection) ? ", " + selection_text(selection) : ""));
  meta.notes.push_back("recording: " + storage_of(r) + ", " + seconds_text(span));
  return std::make_unique<RecordingDataset>(std::move(r), topic.name, std::move(chosen), std::move(meta));
}

std::unique_ptr<Dataset> open_dataset_or_recording(const std::filesystem::path& path,
                                                   const RecordingSelection& selection) {
  if (is_recording(path)) return open_recording(path, selection);
  if (!selection.is_default())
    throw InputError(
        path.string(), "",
        "is not a recording: a topic, start, duration or every chooses the scans of a recording (a ROS 1 "
        ".bag, an .mcap file, a ROS 2 bag folder), not of a folder of scans");
  return open_dataset(path);
}

}  // namespace sextant
