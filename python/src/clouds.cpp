// sextant.read_cloud / sextant.write_cloud: the library's readers and writers (cloud_io.hpp) on
// NumPy arrays. A read cloud is handed to NumPy without a copy.
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "sextant/core/io/cloud_io.hpp"

namespace sextant::python {
namespace {

std::string path_of(const py::object& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

py::object read(const py::object& path, bool intensity) {
  CloudArrays arrays = cloud_arrays(read_cloud_warning_drops(path_of(path)));
  if (!intensity) return std::move(arrays.points);
  return py::make_tuple(arrays.points, arrays.intensity);
}

void write(const py::object& path, const py::array& points, const py::object& intensity) {
  const std::string file = path_of(path);
  PointCloud cloud = cloud_from_array(points, "points", Borrowing::kInPlace);
  if (!intensity.is_none()) {
    if (cloud.has_intensity())
      throw py::value_error("intensity is given twice (an N×4 array and intensity=)");
    const auto values = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(intensity);
    if (!values || values.ndim() != 1 || static_cast<std::size_t>(values.shape(0)) != cloud.size())
      throw py::value_error("intensity: expected one value per point (a 1-D array of " +
                            std::to_string(cloud.size()) + ")");
    cloud.intensity().assign(values.data(), values.data() + values.shape(0));
  }
  CloudWriteReport written;
  {
    const py::gil_scoped_release release;
    written = write_cloud(file, cloud);
  }
  if (const std::string note = dropped_on_reading_note(file, written); !note.empty()) warn(note);
}

constexpr char kReadDoc[] = R"doc(Read a point-cloud file with the library's readers.

Formats by extension: .3d (uos), .bin (KITTI velodyne, x y z intensity), .xyz32.bin, .pcd, .ply,
.csv/.xyz/.txt (x,y,z[,i]). Every reader converts to the internal frame (metres, x forward, y left,
z up) and drops non-finite points (and a .3d file's "no return" points): a UserWarning names the file
and counts them.

Returns:
  intensity=False (default): the points, an N×3 float32 array.
  intensity=True: a tuple (points, intensity): intensity is an N float32 array, or None when the file
  has no intensity. The return type depends only on this argument, never on the file.
The arrays share the library's memory (no copy).

Raises InputError (a ValueError) naming the file, the line or byte, and the problem, for a missing,
unknown or malformed file, or one without a usable point.)doc";

constexpr char kWriteDoc[] =
    R"doc(Write a point cloud with the library's writers (format by extension, atomically).

points: N×3 or N×4 (x y z intensity) float32/float64 array in metres, internal frame (a .3d file is
written in the uos frame and centimetres). intensity: optional N values (not with an N×4 array).
A UserWarning counts the points that reading the file back drops: non-finite ones, and in a .3d file
those at or beyond 32.75 m (the SICK's "no return").)doc";

}  // namespace

void bind_clouds(py::module_& m) {
  m.def("read_cloud", &read, kReadDoc, py::arg("path"), py::arg("intensity") = false);
  m.def("write_cloud", &write, kWriteDoc, py::arg("path"), py::arg("points"),
        py::arg("intensity") = py::none());
  m.def(
      "reads_in_place", [](const py::array& points) { return readable_in_place(points); },
      "True when match() and write_cloud() read this array where it is, without a copy: a C-contiguous\n"
      "N×3 float32 array, as read_cloud() returns. Other arrays are copied once.",
      py::arg("points"));
}

}  // namespace sextant::python
