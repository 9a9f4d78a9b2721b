// `sextant info <path>`: what a point-cloud file or a dataset folder holds.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/io/cloud_io.hpp"

namespace sextant::cli {
namespace {

std::string vector_text(const Eigen::Vector3f& v) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(3) << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
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
            << "read:        " << report.points_read << " point records\n"
            << "dropped:     " << report.non_finite_dropped << " non-finite, " << report.no_return_dropped
            << " no-return\n"
            << "header:      " << report.header_lines_skipped << " line(s) skipped\n"
            << "bounds min:  " << vector_text(b.min) << " m\n"
            << "bounds max:  " << vector_text(b.max) << " m\n"
            << "extent:      " << vector_text(b.extent()) << " m\n";
  for (const std::string& warning : report.warnings) std::cout << "warning:     " << warning << "\n";
}

void describe_dataset(const std::filesystem::path& folder) {
  const auto dataset = open_dataset(folder);
  const DatasetMetadata& m = dataset->metadata();
  std::cout << "folder:       " << folder.string() << "\n"
            << "name:         " << m.name << "\n"
            << "format:       " << m.format << "\n"
            << "scans:        " << m.scan_count << "\n"
            << "odometry:     " << (m.has_odometry ? "yes" : "no") << "\n"
            << "ground truth: " << (m.has_ground_truth ? "yes" : "no") << "\n"
            << "timestamps:   " << (m.scan_count > 0 && dataset->stamp(0) ? "yes" : "no") << "\n";
  if (m.scan_count > 0) std::cout << "first scan:   " << dataset->scan_file(0).string() << "\n";
  for (const std::string& note : m.notes) std::cout << "note:         " << note << "\n";
  if (m.has_ground_truth && m.scan_count > 1) {
    double length = 0.0;
    for (std::size_t i = 1; i < m.scan_count; ++i) {
      length +=
          (dataset->ground_truth(i)->translation() - dataset->ground_truth(i - 1)->translation()).norm();
    }
    std::cout << "path length:  " << std::fixed << std::setprecision(3) << length << " m (ground truth)\n";
  }
}

}  // namespace

void add_info_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("info",
                                 "Describe a point-cloud file (points, bounds, frame, dropped points) "
                                 "or a dataset folder (format, scans, odometry, ground truth)");
  auto path = std::make_shared<std::string>();
  cmd->add_option("path", *path,
                  "A cloud file (.3d .bin .xyz32.bin .pcd .ply .csv .xyz .txt) or a dataset folder")
      ->required();
  cmd->callback([&exit_code, path] {
    exit_code = guarded([path] {
      std::error_code ec;  // a symlink loop: the reader names it
      if (std::filesystem::is_directory(*path, ec)) {
        describe_dataset(*path);
      } else {
        describe_cloud(*path);
      }
      return 0;
    });
  });
}

}  // namespace sextant::cli
