// `sextant info <path>`: what a point-cloud file, a dataset folder, a recording or experiment configs hold.
#include <algorithm>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "experiment_listing.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/io/point_time.hpp"
#include "sextant/matchers/point_spacing.hpp"
#include "sextant/matchers/sensor_kind.hpp"
#include "sextant/pipeline/dataset_argument.hpp"
#include "sextant/recordings/recording.hpp"

namespace sextant::cli {
namespace {

std::string vector_text(const Eigen::Vector3f& v) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return out.str();
}

/// Whether the points carry their own time, and over how long (the sweep the odometry deskews).
std::string time_text(const PointCloud& cloud) {
  if (!cloud.has_time()) return "none (no per-point time field)";
  const auto [earliest, latest] = std::minmax_element(cloud.time().begin(), cloud.time().end());
  std::ostringstream out;
  out << std::fixed << std::setprecision(6) << "per point, " << *earliest << " to " << *latest << " s (span "
      << static_cast<double>(*latest) - static_cast<double>(*earliest) << " s)";
  return out.str();
}

void describe_cloud(const std::filesystem::path& file) {
  const CloudFormat format = cloud_format(file);
  ScanLoadReport report;
  const PointCloud cloud = read_cloud(file, &report);
  const Bounds b = cloud.bounds();
  std::cout << "file:        " << file.string() << "\n"
            << "format:      " << format.name << "\n"
            << "frame:       " << format.frame << "\n"
            << "points:      " << cloud.size() << (cloud.has_intensity() ? " (with intensity)" : "") << "\n"
            << "time:        " << time_text(cloud) << "\n"
            << "read:        " << report.points_read << " point records\n"
            << "dropped:     " << report.non_finite_dropped << " non-finite, " << report.no_return_dropped
            << " no-return\n"
            << "header:      " << report.header_lines_skipped << " line(s) skipped\n"
            << "bounds min:  " << vector_text(b.min) << " m\n"
            << "bounds max:  " << vector_text(b.max) << " m\n"
            << "extent:      " << vector_text(b.extent()) << " m\n";
  // The scan's measured density and view (issue 62): what sizes and checks that follow the sensor read.
  const PointSpacing spacing = measure_point_spacing(cloud);
  const SensorDetection sensor = detect_sensor(cloud);
  std::cout << std::fixed << std::setprecision(3) << "spacing:     " << spacing.median
            << " m (median distance to the nearest other point, " << spacing.queried << " points measured)\n"
            << std::setprecision(2) << "azimuth:     " << sensor.azimuth_coverage
            << " of the circle about the frame's z axis (" << to_string(sensor.kind)
            << " if this is the sensor's frame)\n";
  std::cout.unsetf(std::ios::floatfield);
  for (const std::string& warning : report.warnings) std::cout << "warning:     " << warning << "\n";
}

void describe_dataset(const Dataset& dataset, const std::string& where) {
  const DatasetMetadata& m = dataset.metadata();
  std::cout << "dataset:      " << where << "\n"
            << "name:         " << m.name << "\n"
            << "format:       " << m.format << "\n"
            << "scans:        " << m.scan_count << "\n"
            << "odometry:     " << (m.has_odometry ? "yes" : "no") << "\n"
            << "ground truth: " << (m.has_ground_truth ? "yes" : "no") << "\n"
            << "timestamps:   " << (m.scan_count > 0 && dataset.stamp(0) ? "yes" : "no") << "\n";
  if (m.scan_count > 0 && !dataset.scan_file(0).empty())
    std::cout << "first scan:   " << dataset.scan_file(0).string() << "\n";
  for (const std::string& note : m.notes) std::cout << "note:         " << note << "\n";
  if (m.has_ground_truth && m.scan_count > 1) {
    double length = 0.0;
    for (std::size_t i = 1; i < m.scan_count; ++i) {
      length += (dataset.ground_truth(i)->translation() - dataset.ground_truth(i - 1)->translation()).norm();
    }
    std::cout << "path length:  " << std::fixed << std::setprecision(3) << length << " m (ground truth)\n";
  }
}

/// "1592833242.605 s (2020-06-22 13:40:42 UTC)"; the date only for a clock since the epoch (1990–2100).
std::string time_text(double seconds) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(6) << seconds << " s";
  if (seconds > 631152000.0 && seconds < 4102444800.0) {
    const std::time_t t = static_cast<std::time_t>(seconds);
    std::tm utc{};
    gmtime_r(&t, &utc);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S UTC", &utc);
    out << " (" << date << ")";
  }
  return out.str();
}

/// One point-cloud topic's first message: its size and fields, the per-point time field named.
void print_point_fields(const TopicSummary& t) {
  std::cout << "      points: " << t.height << " × " << t.width << (t.height > 1 ? " (organised)" : "")
            << ", point_step " << t.point_step << ", frame '" << t.frame_id << "'\n      fields:";
  std::vector<std::string> names;
  for (const PointFieldSummary& f : t.fields) names.push_back(f.name);
  const auto time_field = find_point_time_field(names);
  for (std::size_t k = 0; k < t.fields.size(); ++k) {
    const PointFieldSummary& f = t.fields[k];
    std::cout << (k ? ", " : " ") << f.name << " " << f.datatype
              << (f.count > 1 ? "×" + std::to_string(f.count) : "") << " @" << f.offset
              << (time_field && *time_field == k ? " (per-point time)" : "");
  }
  std::cout << "\n";
}

void describe_recording_text(const std::filesystem::path& path) {
  const RecordingSummary s = describe_recording(path);
  std::cout << "recording:    " << path.string() << "\n"
            << "format:       " << s.format << " (" << s.storage << ")\n";
  if (s.files.size() > 1)
    for (const auto& file : s.files) std::cout << "file:         " << file.string() << "\n";
  std::cout << "messages:     " << s.messages << "\n";
  if (s.start && s.end)
    std::cout << "start:        " << time_text(*s.start) << "\n"
              << "end:          " << time_text(*s.end) << "\n"
              << "duration:     " << std::fixed << std::setprecision(6) << *s.end - *s.start << " s\n";
  std::size_t name_width = 5, type_width = 4;
  for (const TopicSummary& t : s.topics) {
    name_width = std::max(name_width, t.name.size());
    type_width = std::max(type_width, t.type.size());
  }
  std::cout << "topics:       " << s.topics.size() << "\n";
  std::vector<std::string> clouds;
  for (const TopicSummary& t : s.topics) {
    std::cout << "  " << std::left << std::setw(static_cast<int>(name_width)) << t.name << "  "
              << std::setw(static_cast<int>(type_width)) << t.type << "  " << std::setw(5) << t.encoding
              << std::right << std::setw(8) << t.messages << (t.messages == 1 ? " message" : " messages")
              << "\n";
    if (!t.point_cloud) continue;
    clouds.push_back(t.name);
    if (!t.fields.empty()) print_point_fields(t);
  }
  if (clouds.size() == 1)
    std::cout << "scans:        " << clouds.front() << " (its only sensor_msgs/PointCloud2 topic)\n";
  else if (clouds.empty())
    std::cout << "scans:        none (no sensor_msgs/PointCloud2 topic)\n";
  else
    std::cout << "scans:        " << clouds.size()
              << " sensor_msgs/PointCloud2 topics: choose one with --topic\n";
}

}  // namespace

void add_info_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "info",
      "Describe a point-cloud file (points, bounds, frame, dropped points, point spacing, azimuth coverage), "
      "a dataset folder (format, scans, odometry, ground truth), a recording (a ROS 1 "
      ".bag, an .mcap file, a ROS 2 bag folder: topics, types, message counts, point "
      "fields), or experiment configs (a YAML or the experiments/ folder: kind, layout, "
      "methods, runs)");
  auto path = std::make_shared<std::string>();
  auto markdown = std::make_shared<bool>(false);
  cmd->add_option("path", *path,
                  "A cloud file (.3d .bin .xyz32.bin .pcd .ply .csv .xyz .txt), a dataset folder, a "
                  "recording (.bag, .mcap, a ROS 2 bag folder), an experiment YAML or a folder of them")
      ->required();
  cmd->add_flag("--markdown", *markdown, "Experiments: print a Markdown table");
  cmd->callback([&exit_code, path, markdown] {
    exit_code = guarded([path, markdown] {
      std::error_code ec;  // a symlink loop or no permission: the reader names it
      const bool missing = !std::filesystem::exists(*path, ec) && !ec;
      if (missing && names_builtin_campus(*path)) {
        describe_dataset(*open_builtin_campus(1), "(built in: the synthetic campus, seed 1, cast when read)");
      } else if (missing) {
        throw InputError(*path, "",
                         "no such file or folder (expected a cloud file, a dataset folder, a recording, an "
                         "experiment YAML or a folder of them, or 'campus')");
      } else if (is_recording(*path)) {
        describe_recording_text(*path);
      } else if (holds_experiments(*path)) {
        describe_experiments(*path, *markdown);
      } else if (std::filesystem::is_directory(*path, ec)) {
        describe_dataset(*open_dataset(*path), *path);
      } else {
        describe_cloud(*path);
      }
      return 0;
    });
  });
}

}  // namespace sextant::cli
