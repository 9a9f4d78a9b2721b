// NumPy ↔ library conversions (arrays.hpp): clouds in read in place or by one strided copy, clouds out by
// sharing the cloud's memory through a capsule, transforms and pose stacks checked as rigid.
#include "arrays.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#include "sextant/core/io/cloud_io.hpp"

namespace sextant::python {
namespace {

static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "PointCloud stores packed xyz triples");

template <class T>
PointCloud copy_cloud(const py::array& a, const std::string& what) {
  const py::ssize_t n = a.shape(0), columns = a.shape(1);
  const py::ssize_t row_stride = a.strides(0), column_stride = a.strides(1);
  const char* base = static_cast<const char*>(a.data());
  const auto at = [&](py::ssize_t i, py::ssize_t j) {
    T v;
    std::memcpy(&v, base + i * row_stride + j * column_stride, sizeof v);  // any alignment
    return static_cast<float>(v);
  };
  std::vector<Eigen::Vector3f> points(static_cast<std::size_t>(n));
  std::vector<float> intensity(columns == 4 ? static_cast<std::size_t>(n) : 0);
  for (py::ssize_t i = 0; i < n; ++i) {
    Eigen::Vector3f& p = points[static_cast<std::size_t>(i)];
    p = {at(i, 0), at(i, 1), at(i, 2)};
    bool finite = p.allFinite();
    if (columns == 4) {
      const float value = at(i, 3);
      intensity[static_cast<std::size_t>(i)] = value;
      finite = finite && std::isfinite(value);
    }
    if (!finite)
      throw py::value_error(what + ": row " + std::to_string(i) +
                            " is not finite in float32 (NaN, Inf or beyond 3.4e38); drop such rows first");
  }
  PointCloud cloud(std::move(points));
  cloud.intensity() = std::move(intensity);
  return cloud;
}

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) text += (d ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

/// The transform of M after the checks of transform_from_array.
Eigen::Isometry3d checked_transform(const Eigen::Matrix4d& M, const std::string& what) {
  if (const std::string why = rigid_problem(M.topLeftCorner<3, 3>(), M.topRightCorner<3, 1>()); !why.empty())
    throw py::value_error(what + ": not a rigid transform: " + why);
  if (!M.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1), 1e-12))
    throw py::value_error(what + ": the last row of a transform must be 0 0 0 1");
  Eigen::Isometry3d T;
  T.matrix() = M;
  return T;
}

}  // namespace

bool readable_in_place(const py::array& points) {
  return points.ndim() == 2 && points.shape(1) == 3 && py::isinstance<py::array_t<float>>(points) &&
         points.strides(1) == py::ssize_t{sizeof(float)} &&
         points.strides(0) == py::ssize_t{3 * sizeof(float)} &&
         reinterpret_cast<std::uintptr_t>(points.data()) % alignof(Eigen::Vector3f) == 0;
}

PointCloud cloud_from_array(const py::array& points, const std::string& what, Borrowing borrowing) {
  if (points.ndim() != 2 || (points.shape(1) != 3 && points.shape(1) != 4))
    throw py::value_error(what + ": expected an N×3 (x y z) or N×4 (x y z intensity) array, got shape " +
                          shape_text(points));
  if (points.shape(0) == 0) throw py::value_error(what + ": the cloud has no points");
  if (borrowing == Borrowing::kInPlace && readable_in_place(points)) {
    const auto* first = static_cast<const Eigen::Vector3f*>(points.data());
    const auto n = static_cast<std::size_t>(points.shape(0));
    for (std::size_t i = 0; i < n; ++i)
      if (!first[i].allFinite())
        throw py::value_error(what + ": row " + std::to_string(i) +
                              " is not finite (NaN or Inf); drop such rows first");
    return PointCloud::borrow(first, n);
  }
  if (py::isinstance<py::array_t<float>>(points)) return copy_cloud<float>(points, what);
  if (py::isinstance<py::array_t<double>>(points)) return copy_cloud<double>(points, what);
  throw py::value_error(what + ": expected float32 or float64 values, got dtype " +
                        py::str(points.dtype()).cast<std::string>());
}

void warn(const std::string& message) {
  if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 1) != 0) throw py::error_already_set();
}

PointCloud read_cloud_warning_drops(const std::string& path, ScanLoadReport* report) {
  ScanLoadReport local;
  PointCloud cloud;
  {
    const py::gil_scoped_release release;
    cloud = read_cloud(path, &local);
  }
  if (const std::string dropped = dropped_points_note(local); !dropped.empty()) warn(path + ": " + dropped);
  if (report) *report = std::move(local);
  return cloud;
}

PointCloud cloud_from_object(const py::object& source, const std::string& what, Borrowing borrowing,
                             ScanLoadReport* report) {
  if (py::isinstance<py::str>(source) || py::hasattr(source, "__fspath__"))
    return read_cloud_warning_drops(py::module_::import("os").attr("fspath")(source).cast<std::string>(),
                                    report);
  if (py::isinstance<py::array>(source)) return cloud_from_array(source, what, borrowing);
  // A converted list is a temporary array: its memory is gone after this call, so it is copied.
  return cloud_from_array(py::module_::import("numpy").attr("asarray")(source), what, Borrowing::kCopy);
}

CloudArrays cloud_arrays(PointCloud cloud) {
  CloudArrays out;
  const auto n = static_cast<py::ssize_t>(cloud.size());
  const bool has_intensity = cloud.has_intensity();
  if (n == 0) {
    out.points = py::array_t<float>(std::vector<py::ssize_t>{0, 3});
    out.intensity = has_intensity ? py::object(py::array_t<float>(0)) : py::object(py::none());
    return out;
  }
  auto* owned = new PointCloud(std::move(cloud));
  const py::capsule owner(owned, [](void* p) { delete static_cast<PointCloud*>(p); });
  const auto f = static_cast<py::ssize_t>(sizeof(float));
  out.points = py::array_t<float>({n, py::ssize_t{3}}, {3 * f, f}, owned->points().front().data(), owner);
  out.intensity = py::none();
  if (has_intensity) out.intensity = py::array_t<float>({n}, {f}, owned->intensity().data(), owner);
  return out;
}

Eigen::Isometry3d transform_from_array(const py::handle& matrix, const std::string& what) {
  using Dense = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Dense a = Dense::ensure(matrix);
  if (!a) throw py::value_error(what + ": expected a 4×4 array of numbers");
  if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4)
    throw py::value_error(what + ": expected a 4×4 matrix, got shape " + shape_text(a));
  Eigen::Matrix4d M;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) M(i, j) = a.at(i, j);
  return checked_transform(M, what);
}

std::vector<Eigen::Isometry3d> poses_from_array(const py::handle& poses, const std::string& what) {
  using Dense = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Dense a = Dense::ensure(poses);
  if (!a || a.ndim() != 3 || a.shape(1) != 4 || a.shape(2) != 4)
    throw py::value_error(what + ": expected an N×4×4 array of poses" +
                          (a ? ", got shape " + shape_text(a) : ""));
  std::vector<Eigen::Isometry3d> out;
  out.reserve(static_cast<std::size_t>(a.shape(0)));
  for (py::ssize_t k = 0; k < a.shape(0); ++k) {
    Eigen::Matrix4d M;
    for (py::ssize_t i = 0; i < 4; ++i)
      for (py::ssize_t j = 0; j < 4; ++j) M(i, j) = a.at(k, i, j);
    out.push_back(checked_transform(M, what + "[" + std::to_string(k) + "]"));
  }
  return out;
}

py::array_t<double> transform_array(const Eigen::Isometry3d& T) {
  py::array_t<double> out({4, 4});
  auto v = out.mutable_unchecked<2>();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) v(i, j) = T.matrix()(i, j);
  return out;
}

py::array_t<double> poses_array(const std::vector<Eigen::Isometry3d>& poses) {
  py::array_t<double> out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{4}, py::ssize_t{4}});
  auto v = out.mutable_unchecked<3>();
  for (std::size_t k = 0; k < poses.size(); ++k)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) v(static_cast<py::ssize_t>(k), i, j) = poses[k].matrix()(i, j);
  return out;
}

py::array_t<double> matrix6_array(const Matrix6d& M) {
  py::array_t<double> out({6, 6});
  auto v = out.mutable_unchecked<2>();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) v(i, j) = M(i, j);
  return out;
}

py::array_t<double> vector_array(const std::vector<double>& values) {
  py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
  if (!values.empty()) std::memcpy(out.mutable_data(), values.data(), values.size() * sizeof(double));
  return out;
}

}  // namespace sextant::python
