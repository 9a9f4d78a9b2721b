// sextant.odometry()'s dataset argument (odometry_dataset.hpp): a folder, the campus or a list.
#include "odometry_dataset.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "arrays.hpp"
#include "memory_dataset.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/kitti.hpp"
#include "sextant/pipeline/dataset_argument.hpp"

namespace sextant::python {
namespace {

/// A folder, a recording or the campus (dataset_argument.hpp), with a poses file for a folder of scans.
std::unique_ptr<Dataset> open_folder(const std::string& name, const py::object& poses,
                                     std::uint64_t campus_seed, const RecordingSelection& selection) {
  std::optional<std::string> poses_file;
  if (!poses.is_none()) poses_file = py::module_::import("os").attr("fspath")(poses).cast<std::string>();
  const py::gil_scoped_release release;
  return open_dataset_argument(name, poses_file, campus_seed, Face::python, selection);
}

/// A list of clouds (arrays or paths) with optional ground truth, odometry and times.
std::unique_ptr<Dataset> open_list(const py::sequence& clouds, const py::object& poses,
                                   const py::object& odometry, const py::object& times) {
  std::vector<PointCloud> scans;
  std::vector<ScanLoadReport> loads(clouds.size());  // of the scans given as paths
  for (std::size_t i = 0; i < clouds.size(); ++i)
    scans.push_back(
        cloud_from_object(clouds[i], "scans[" + std::to_string(i) + "]", Borrowing::kCopy, &loads[i]));
  if (scans.empty()) throw py::value_error("odometry: the list of scans is empty");
  std::vector<Eigen::Isometry3d> truth, odometry_poses;
  if (!poses.is_none()) truth = poses_from_array(poses, "poses");
  if (!odometry.is_none()) odometry_poses = poses_from_array(odometry, "odometry_poses");
  std::vector<double> stamps;
  if (!times.is_none()) {
    const auto t = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(times);
    if (!t || t.ndim() != 1) throw py::value_error("times: expected a 1-D array of seconds");
    stamps.assign(t.data(), t.data() + t.shape(0));
    for (std::size_t k = 0; k < stamps.size(); ++k) {  // as times.txt: finite, each after the one before
      const std::string problem =
          scan_time_problem(k == 0 ? std::nullopt : std::optional<double>(stamps[k - 1]), stamps[k]);
      if (!problem.empty()) throw py::value_error("times[" + std::to_string(k) + "]: " + problem);
    }
  }
  return std::make_unique<MemoryDataset>(std::move(scans), std::move(loads), std::move(truth),
                                         std::move(odometry_poses), std::move(stamps));
}

}  // namespace

std::unique_ptr<Dataset> open_odometry_dataset(const py::object& source, const py::object& poses,
                                               const py::object& odometry_poses, const py::object& times,
                                               std::uint64_t campus_seed,
                                               const RecordingSelection& selection) {
  if (py::isinstance<py::str>(source) || py::hasattr(source, "__fspath__")) {
    if (!odometry_poses.is_none() || !times.is_none())
      throw py::value_error("odometry_poses and times are for a list of arrays; a folder brings its own");
    return open_folder(py::module_::import("os").attr("fspath")(source).cast<std::string>(), poses,
                       campus_seed, selection);
  }
  if (!selection.is_default())
    throw py::value_error("topic, start, duration and every choose the scans of a recording, not of a list");
  if (py::isinstance<py::array>(source))
    throw py::type_error("odometry: got one array; expected a list of scans (N×3/N×4 arrays)");
  if (!py::isinstance<py::sequence>(source))
    throw py::type_error("odometry: expected a dataset folder, 'campus', or a list of N×3/N×4 arrays");
  return open_list(source.cast<py::sequence>(), poses, odometry_poses, times);
}

}  // namespace sextant::python
