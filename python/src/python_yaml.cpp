// Python values → YAML nodes (python_yaml.hpp). Scalars become the text a YAML file would hold, so
// the library parses them exactly as it parses a settings file.
#include "python_yaml.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace sextant::python {
namespace py = pybind11;

namespace {

std::string number_text(double v) {
  if (std::isnan(v)) return ".nan";
  if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
  std::ostringstream out;
  out.precision(std::numeric_limits<double>::max_digits10);
  out << v;
  return out.str();
}

}  // namespace

YAML::Node yaml_from_python(const py::handle& value, const std::string& what) {
  if (value.is_none()) return YAML::Node(YAML::NodeType::Null);
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::int_>(value)) return YAML::Node(py::str(value).cast<std::string>());
  if (py::isinstance<py::float_>(value)) return YAML::Node(number_text(value.cast<double>()));
  if (py::isinstance<py::str>(value)) return YAML::Node(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) {
    YAML::Node map(YAML::NodeType::Map);
    for (const auto& item : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(item.first))
        throw py::type_error(what + ": setting names must be strings, got " +
                             py::repr(item.first).cast<std::string>());
      const std::string key = item.first.cast<std::string>();
      map[key] = yaml_from_python(item.second, what + "." + key);
    }
    return map;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node sequence(YAML::NodeType::Sequence);
    std::size_t i = 0;
    for (const auto& item : value)
      sequence.push_back(yaml_from_python(item, what + "[" + std::to_string(i++) + "]"));
    return sequence;
  }
  // NumPy scalars (numpy.float64 is a float already; numpy.int64 and numpy.bool_ are not).
  if (py::hasattr(value, "item") && py::hasattr(value, "dtype"))
    return yaml_from_python(value.attr("item")(), what);
  throw py::type_error(what + ": cannot pass a " +
                       py::str(value.get_type().attr("__name__")).cast<std::string>() +
                       " as a setting (use None, bool, int, float, str, dict or list)");
}

YAML::Node yaml_map_from_kwargs(const py::kwargs& kwargs, const std::string& what) {
  YAML::Node map(YAML::NodeType::Map);
  for (const auto& item : kwargs) {
    const std::string key = item.first.cast<std::string>();
    map[key] = yaml_from_python(item.second, what + " '" + key + "'");
  }
  return map;
}

MatcherRequest matcher_request(const std::string& call, const std::string& method,
                               const pybind11::object& preset, const std::string& sampling,
                               const pybind11::kwargs& settings, const pybind11::object& sampler_settings) {
  MatcherRequest r;
  r.method = method;
  if (!preset.is_none()) r.preset = preset.cast<std::string>();
  r.sampling = sampling;
  r.matcher = yaml_map_from_kwargs(settings, call + " setting");
  if (!sampler_settings.is_none()) r.sampler = yaml_from_python(sampler_settings, "sampler_settings");
  r.matcher_where = call + " settings";
  r.sampler_where = call + " sampler settings";
  return r;
}

}  // namespace sextant::python
