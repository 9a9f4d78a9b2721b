#pragma once
// Conversions between NumPy arrays and the library's types, for every binding: point clouds
// (N×3 or N×4 float32/float64 in, read in place or copied once; float32 out without a copy), 4×4 transforms,
// stacks of N 4×4 poses and 6×6 matrices. Every shape or value problem is a ValueError naming the argument.
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <Eigen/Geometry>

#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"
#include "sextant/core/pose.hpp"

namespace sextant::python {

namespace py = pybind11;

/// kInPlace: an array whose layout is the library's (readable_in_place) is read where it is, without
/// a copy; the caller keeps the array alive and unchanged while the cloud is used. kCopy: always copied.
enum class Borrowing { kCopy, kInPlace };

/// True for the library's own layout: float32, N×3, rows of 12 bytes packed, float-aligned data.
bool readable_in_place(const py::array& points);

/// A cloud from an N×3 (x y z) or N×4 (x y z intensity) array of float32 or float64, any strides:
/// read in place (see Borrowing) or copied once into a PointCloud that owns its points. ValueError
/// naming `what` for another shape or dtype, no points, or a NaN/Inf value (the row is named).
/// Needs the GIL.
PointCloud cloud_from_array(const py::array& points, const std::string& what, Borrowing borrowing);

/// A cloud from an array (as cloud_from_array; anything else array-like is converted and copied)
/// or a path (str or os.PathLike, read by the library's read_cloud with the GIL released).
/// InputError for a bad file. `report`, for a path, gets what reading it dropped.
PointCloud cloud_from_object(const py::object& source, const std::string& what, Borrowing borrowing,
                             ScanLoadReport* report = nullptr);

/// read_cloud with the GIL released; a UserWarning naming the file says what reading it dropped.
PointCloud read_cloud_warning_drops(const std::string& path, ScanLoadReport* report = nullptr);
/// A UserWarning (an exception when the warnings filter makes it one).
void warn(const std::string& message);

/// Arrays that share the memory of a cloud moved into them (the arrays keep it alive): points N×3
/// float32 and, when the cloud has intensity, intensity N float32 (else None). No copy.
struct CloudArrays {
  py::array points;
  py::object intensity;
};
CloudArrays cloud_arrays(PointCloud cloud);

/// A rigid transform from a 4×4 array (any float dtype). ValueError naming `what` when the shape is
/// not 4×4, the last row is not 0 0 0 1 or the rotation is not one (rigid_problem, pose.hpp).
Eigen::Isometry3d transform_from_array(const py::handle& matrix, const std::string& what);

/// Poses from an N×4×4 array (or a sequence of 4×4 arrays), each checked as transform_from_array.
std::vector<Eigen::Isometry3d> poses_from_array(const py::handle& poses, const std::string& what);

/// A 4×4 float64 array of T.
py::array_t<double> transform_array(const Eigen::Isometry3d& T);
/// An N×4×4 float64 array of the poses.
py::array_t<double> poses_array(const std::vector<Eigen::Isometry3d>& poses);
/// A 6×6 float64 array.
py::array_t<double> matrix6_array(const Matrix6d& M);
/// A 1-D float64 array of the values.
py::array_t<double> vector_array(const std::vector<double>& values);

}  // namespace sextant::python
