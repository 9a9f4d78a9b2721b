// The extension module sextant._sextant: the library's errors as Python exceptions, then each
// topic's bindings (bindings.hpp). The package sextant (python/sextant/__init__.py) re-exports it.
#include <filesystem>

#include "bindings.hpp"
#include "sextant/core/error.hpp"

namespace sextant::python {
namespace py = pybind11;

void bind_errors(py::module_& m) {
  // Created once and never freed: a static py::object would be released after the interpreter.
  static PyObject* input_error = PyErr_NewExceptionWithDoc(
      "sextant.InputError",
      "Bad input (a file, a setting, a name): the library's InputError. str() is '<file>:<where>: "
      "<problem>'; the attributes file, where and problem hold the parts. A subclass of ValueError. "
      "A file the system would not open, create or write raises the matching OSError instead "
      "(FileNotFoundError, PermissionError, …), its filename the file's.",
      PyExc_ValueError, nullptr);
  m.add_object("InputError", py::handle(input_error).inc_ref());
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const FileError& e) {
      // OSError(errno, strerror, filename) is the subclass the number names: FileNotFoundError,
      // PermissionError, IsADirectoryError, …; str() is "[Errno 13] <the CLI's problem>: '<file>'".
      const py::object os_error = py::module_::import("builtins").attr("OSError");
      const py::object error =
          e.error_number() != 0 ? os_error(e.error_number(), e.problem(), e.file()) : os_error(e.what());
      PyErr_SetObject(error.get_type().ptr(), error.ptr());
    } catch (const std::filesystem::filesystem_error& e) {
      const py::object error = py::module_::import("builtins")
                                   .attr("OSError")(e.code().value(), e.code().message(), e.path1().string());
      PyErr_SetObject(error.get_type().ptr(), error.ptr());
    } catch (const InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(input_error)(e.what());
      error.attr("file") = e.file();
      error.attr("where") = e.where();
      error.attr("problem") = e.problem();
      PyErr_SetObject(input_error, error.ptr());
    }
  });
}

}  // namespace sextant::python

PYBIND11_MODULE(_sextant, m) {
  namespace sp = sextant::python;
  m.doc() = "Sextant's registration (NDT, ML-NDT, ICP), odometry and trajectory metrics on NumPy arrays.";
  m.attr("__version__") = SEXTANT_VERSION;
  sp::bind_errors(m);
  sp::bind_clouds(m);
  sp::bind_poses(m);
  sp::bind_match(m);
  sp::bind_odometry(m);
  sp::bind_metrics(m);
}
