// sextant.odometry()'s steps table (steps_table.hpp): the library's table (pipeline/steps_table.hpp), one
// NumPy array per column.
#include "steps_table.hpp"

#include <pybind11/numpy.h>

#include "sextant/pipeline/steps_table.hpp"

namespace sextant::python {
namespace py = pybind11;

namespace {

template <class T>
py::array_t<T> numbers(const std::vector<T>& values) {
  return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
}

}  // namespace

py::dict steps_columns(const OdometryResult& result, std::size_t first,
                       const std::optional<std::vector<Eigen::Isometry3d>>& truth) {
  py::dict table;  // keeps the columns' order
  for (const StepsColumn& c : sextant::steps_table(result, first, truth).columns) {
    switch (c.kind) {
      case StepsColumn::Kind::integer: table[c.name.c_str()] = numbers(c.integers); break;
      case StepsColumn::Kind::real: table[c.name.c_str()] = numbers(c.reals); break;
      case StepsColumn::Kind::flag: {
        py::array_t<bool> values(static_cast<py::ssize_t>(c.flags.size()));
        for (std::size_t i = 0; i < c.flags.size(); ++i)
          values.mutable_at(static_cast<py::ssize_t>(i)) = c.flags[i];
        table[c.name.c_str()] = values;
        break;
      }
      case StepsColumn::Kind::text:
        table[c.name.c_str()] =
            py::module_::import("numpy").attr("asarray")(py::cast(c.texts), py::arg("dtype") = "str");
        break;
    }
  }
  return table;
}

}  // namespace sextant::python
