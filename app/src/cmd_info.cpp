// `sextant info <path>`: what a point-cloud file, a dataset folder or experiment configs hold.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "experiment_listing.hpp"
#include "sextant/core/dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/pipeline/dataset_argument.hpp"

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

}  // namespace

void add_info_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("info",
                                 "Describe a point-cloud file (points, bounds, frame, dropped points) "
                                 "or a dataset folder (format, scans, odometry, ground truth), or experiment "
                                 "configs (a YAML or the experiments/ folder: kind, layout, methods, runs)");
  auto path = std::make_shared<std::string>();
  auto markdown = std::make_shared<bool>(false);
  cmd->add_option("path", *path,
                  "A cloud file (.3d .bin .xyz32.bin .pcd .ply .csv .xyz .txt), a dataset folder, an "
                  "experiment YAML or a folder of them")
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
                         "no such file or folder (expected a cloud file, a dataset folder, an experiment "
                         "YAML or a folder of them, or 'campus')");
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
