#pragma once
// Python values as YAML nodes, so that keyword settings reach the library's SettingsReader the way
// a YAML file's `matcher:` map does: None → null, bool, int, float (inf/nan as .inf/.nan), str,
// dict (string keys) → map, list/tuple → sequence. Anything else is a TypeError naming `what`.
#include <string>

#include <pybind11/pybind11.h>
#include <yaml-cpp/yaml.h>

#include "sextant/pipeline/matcher_request.hpp"

namespace sextant::python {

YAML::Node yaml_from_python(const pybind11::handle& value, const std::string& what);

/// A map node from keyword arguments (empty map for none).
YAML::Node yaml_map_from_kwargs(const pybind11::kwargs& kwargs, const std::string& what);

/// The matcher and sampler `call` ("match()", "odometry()") asks for: its method, preset (None: the
/// default), sampling, settings keywords and sampler_settings (None: the sampler's defaults), with
/// errors named after the call (pipeline/matcher_request.hpp reads it).
MatcherRequest matcher_request(const std::string& call, const std::string& method,
                               const pybind11::object& preset, const std::string& sampling,
                               const pybind11::kwargs& settings, const pybind11::object& sampler_settings);

}  // namespace sextant::python
