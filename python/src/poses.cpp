// sextant.pose_to_matrix / sextant.matrix_to_pose: the library's Pose6 convention (pose.hpp,
// R = Rx(α)·Ry(β)·Rz(γ), eq. 3.8), e.g. to give match() the guess `sextant match --init` takes.
#include "arrays.hpp"
#include "bindings.hpp"
#include "sextant/core/units.hpp"

namespace sextant::python {
namespace {

py::array_t<double> to_matrix(double x, double y, double z, double alpha, double beta, double gamma,
                              bool degrees) {
  // Divided, as `sextant match --init` divides: the same bits as the CLI's guess.
  const double k = degrees ? kDegPerRad : 1.0;
  const Pose6 p{x, y, z, alpha / k, beta / k, gamma / k};
  if (!is_finite(p)) throw py::value_error("pose_to_matrix: every value must be finite");
  return transform_array(to_isometry(p));
}

py::tuple to_pose(const py::object& matrix, bool degrees) {
  const Pose6 p = to_pose6(transform_from_array(matrix, "T"));
  const double k = degrees ? kDegPerRad : 1.0;
  return py::make_tuple(p.x, p.y, p.z, p.alpha * k, p.beta * k, p.gamma * k);
}

}  // namespace

void bind_poses(py::module_& m) {
  m.def("pose_to_matrix", &to_matrix,
        "The 4×4 transform of a pose (x, y, z [m], alpha, beta, gamma): R = Rx(alpha)·Ry(beta)·Rz(gamma) "
        "(the thesis' eq. 3.8). Angles in radians, or degrees with degrees=True (as `sextant match "
        "--init x,y,z,alpha,beta,gamma` takes them).",
        py::arg("x"), py::arg("y"), py::arg("z"), py::arg("alpha"), py::arg("beta"), py::arg("gamma"),
        py::arg("degrees") = false);
  m.def("matrix_to_pose", &to_pose,
        "The pose (x, y, z, alpha, beta, gamma) of a rigid 4×4 transform, the inverse of pose_to_matrix "
        "(beta in [-pi/2, pi/2]); radians, or degrees with degrees=True.",
        py::arg("T"), py::arg("degrees") = false);
}

}  // namespace sextant::python
