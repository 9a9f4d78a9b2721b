#include "sextant/experiments/experiment_config.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/pipeline/json.hpp"
#include "sextant/pipeline/yaml_json.hpp"

namespace sextant {
namespace {

// Maps merge key by key (keeping the base's key order), anything else is replaced. The override's
// key and value nodes are inserted themselves, so errors about them point at the override's lines.
YAML::Node merged(const YAML::Node& base, const YAML::Node& overlay) {
  YAML::Node out(YAML::NodeType::Map);
  for (const auto& entry : base) {
    const std::string key = entry.first.as<std::string>();
    const YAML::Node over = overlay[key];
    if (!over.IsDefined()) {
      out.force_insert(entry.first, entry.second);
    } else if (entry.second.IsMap() && over.IsMap()) {
      out.force_insert(entry.first, merged(entry.second, over));
    } else {
      for (const auto& o : overlay) {
        if (o.first.as<std::string>() == key) out.force_insert(o.first, o.second);
      }
    }
  }
  for (const auto& o : overlay) {
    if (!base[o.first.as<std::string>()].IsDefined()) out.force_insert(o.first, o.second);
  }
  return out;
}

bool is_identifier(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
}

/// eNN_<slug>.yaml
bool is_experiment_file_name(const std::string& name) {
  const std::string suffix = ".yaml";
  if (name.size() < 5 + suffix.size() ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  return name[0] == 'e' && digit(name[1]) && digit(name[2]) && name[3] == '_' &&
         is_identifier(name.substr(4, name.size() - 4 - suffix.size()));
}

/// A recording's topic, start, duration and every: only with source: folder; checked as the faces check
/// them (RecordingSelection::problem); whether the path is a recording is checked when it is opened.
void read_recording_selection(SettingsReader& in, DatasetConfig& d) {
  RecordingSelection& s = d.recording;
  double duration = 0.0;
  const bool given[] = {in.read("topic", s.topic), in.read("start", s.start), in.read("duration", duration),
                        in.read("every", s.every)};
  const char* keys[] = {"topic", "start", "duration", "every"};
  if (given[2]) s.duration = duration;
  for (int k = 0; k < 4; ++k)
    if (given[k] && d.source != DatasetSource::kFolder)
      in.fail(keys[k], "key '" + std::string(keys[k]) + "' is only used with source: folder (a recording)");
  const auto [key, problem] = s.problem();
  if (!key.empty()) in.fail(key, "key '" + key + "': " + problem);
}

DatasetConfig read_dataset(const YAML::Node& node, const std::string& file) {
  DatasetConfig d;
  d.node = node;
  if (!node.IsDefined() || node.IsNull()) return d;
  SettingsReader in(node, file);
  std::string source = "none";
  in.read("source", source);
  if (source == "none") {
    d.source = DatasetSource::kNone;
  } else if (source == "synthetic") {
    d.source = DatasetSource::kSynthetic;
  } else if (source == "folder") {
    d.source = DatasetSource::kFolder;
  } else {
    in.fail("source", "key 'source': '" + source + "' is not one of none, synthetic, folder");
  }
  std::string path;
  if (in.read("path", path)) {
    if (d.source != DatasetSource::kFolder) in.fail("path", "key 'path' is only used with source: folder");
    d.path = path;
    if (d.path.is_relative()) d.path = std::filesystem::path(file).parent_path() / d.path;
  } else if (d.source == DatasetSource::kFolder) {
    in.fail("path", "required key 'path' is missing (source: folder)");
  }
  d.campus = in.child("campus");
  if (d.campus.IsDefined() && !d.campus.IsNull() && !d.campus.IsMap())
    in.fail("campus", "key 'campus' must be a map");
  if (d.campus.IsDefined() && d.source != DatasetSource::kSynthetic)
    in.fail("campus", "key 'campus' is only used with source: synthetic");
  d.simulated_odometry = in.child("simulated_odometry");
  if (d.simulated_odometry.IsDefined() && !d.simulated_odometry.IsNull()) {
    if (!d.simulated_odometry.IsMap())
      in.fail("simulated_odometry", "key 'simulated_odometry' must be a map");
    if (d.source != DatasetSource::kFolder)
      in.fail("simulated_odometry", "key 'simulated_odometry' is only used with source: folder");
  }
  read_recording_selection(in, d);
  in.read("seed", d.seed);
  in.finish();
  return d;
}

std::vector<YAML::Node> range_values(const YAML::Node& node, const std::string& file,
                                     const std::string& axis) {
  SettingsReader in(node, file);
  double from = 0, to = 0, step = 1;
  in.require("from", from);
  in.require("to", to);
  in.read("step", step);
  in.finish();
  if (!(step > 0) || !std::isfinite(from) || !std::isfinite(to) || to < from)
    in.fail("step", "axis '" + axis + "': the range needs finite from ≤ to and step > 0");
  const double steps = std::floor((to - from) / step + 1e-9);
  if (!(steps < 1e6)) in.fail("to", "axis '" + axis + "': the range has more than 10^6 values");
  const auto count = static_cast<long>(steps) + 1;
  const bool integral = from == std::floor(from) && step == std::floor(step);
  std::vector<YAML::Node> values;
  for (long i = 0; i < count; ++i) {
    const double v = from + static_cast<double>(i) * step;
    values.push_back(integral ? YAML::Node(static_cast<long long>(v)) : YAML::Node(v));
  }
  return values;
}

/// methods × sweep points × repetitions against kMaxRuns, before anything is allocated (and without
/// overflow): a 10⁴ × 10³ sweep used to take 6 GB before std::bad_alloc.
void check_run_count(const ExperimentConfig& c, SettingsReader& in) {
  std::uint64_t runs = std::max<std::size_t>(c.methods.size(), 1);
  std::string shape = std::to_string(runs) + (runs == 1 ? " method" : " methods");
  bool over = false;
  const auto times = [&](std::uint64_t factor, const std::string& what) {
    shape += " × " + what;
    if (factor != 0 && runs > kMaxRuns / factor) over = true;
    if (!over) runs *= factor;
  };
  for (const SweepAxis& axis : c.sweep)
    times(axis.values.size(), "axis '" + axis.name + "' (" + std::to_string(axis.values.size()) + " values)");
  times(static_cast<std::uint64_t>(c.repetitions), std::to_string(c.repetitions) + " repetitions");
  if (over)
    in.fail(c.sweep.empty() ? "repetitions" : "sweep",
            "the plan has " + shape + ": more than " + std::to_string(kMaxRuns) +
                " runs, the cap of one experiment (split it into several)");
}

std::vector<SweepAxis> read_sweep(const YAML::Node& node, const std::string& file) {
  std::vector<SweepAxis> axes;
  if (!node.IsDefined() || node.IsNull()) return axes;
  if (!node.IsMap())
    throw InputError(file, at_line(yaml_line(node)), "key 'sweep': expected a map axis → values");
  for (const auto& entry : node) {
    SweepAxis axis;
    axis.name = entry.first.as<std::string>();
    const std::string where = at_line(yaml_line(entry.first));
    if (!is_identifier(axis.name))
      throw InputError(file, where, "sweep axis '" + axis.name + "': names use a-z, 0-9 and _");
    if (entry.second.IsSequence()) {
      for (const auto& v : entry.second) axis.values.push_back(v);
    } else if (entry.second.IsMap()) {
      axis.values = range_values(entry.second, file, axis.name);
    } else {
      throw InputError(file, where,
                       "sweep axis '" + axis.name + "': expected a list of values or {from, to, step}");
    }
    if (axis.values.empty()) throw InputError(file, where, "sweep axis '" + axis.name + "' has no values");
    std::map<std::string, long> labels;  // a value twice would run twice under one label
    for (const YAML::Node& v : axis.values) {
      const std::string label = v.IsScalar() ? v.Scalar() : canonical_json(v);
      const auto [first, inserted] = labels.emplace(label, yaml_line(v));
      if (!inserted)
        throw InputError(file, at_line(yaml_line(v) ? yaml_line(v) : yaml_line(entry.second)),
                         "sweep axis '" + axis.name + "': the value '" + label + "' is listed twice" +
                             (first->second ? " (first at line " + std::to_string(first->second) + ")" : ""));
    }
    axes.push_back(std::move(axis));
  }
  return axes;
}

std::vector<MethodConfig> read_methods(const YAML::Node& node, const SettingsReader& top) {
  std::vector<MethodConfig> methods;
  if (!node.IsDefined() || !node.IsSequence() || node.size() == 0)
    top.fail("methods", "key 'methods' must be a non-empty list of {name: ..., ...}");
  std::set<std::string> seen;
  for (const auto& m : node) {
    if (!m.IsMap() || !m["name"].IsDefined() || !m["name"].IsScalar())
      throw InputError(top.file(), at_line(yaml_line(m)), "key 'methods': each method needs a 'name'");
    MethodConfig method{m["name"].as<std::string>(), m};
    if (!seen.insert(method.name).second)
      throw InputError(top.file(), at_line(yaml_line(m["name"])),
                       "key 'name': method '" + method.name + "' appears twice");
    methods.push_back(method);
  }
  return methods;
}

}  // namespace

ExperimentConfig parse_experiment_config(const YAML::Node& document, const std::string& file, bool quick) {
  if (!document.IsMap()) throw InputError(file, "", "an experiment config must be a YAML map");
  const YAML::Node overrides = document["quick"];
  if (overrides.IsDefined() && !overrides.IsNull() && !overrides.IsMap())
    throw InputError(file, at_line(yaml_line(overrides)), "key 'quick' must be a map of overrides");
  if (overrides.IsDefined() && overrides.IsMap() && overrides["quick"].IsDefined())
    throw InputError(file, at_line(yaml_line(overrides)), "key 'quick' cannot be nested");

  ExperimentConfig c;
  c.file = file;
  c.quick = quick;
  const YAML::Node doc =
      quick && overrides.IsDefined() && overrides.IsMap() ? merged(document, overrides) : document;

  SettingsReader in(doc, file);
  in.child("quick");  // consumed above
  in.require("name", c.name);
  if (!is_identifier(c.name)) in.fail("name", "key 'name': '" + c.name + "' must use a-z, 0-9 and _ only");
  in.require("kind", c.kind);
  in.read("title", c.title);
  in.read("thesis", c.thesis);
  in.read("description", c.description);
  in.read("seed", c.seed);
  in.read("repetitions", c.repetitions);
  if (c.repetitions < 1) in.fail("repetitions", "key 'repetitions' must be ≥ 1");
  c.dataset = read_dataset(in.child("dataset"), file);
  c.methods = read_methods(in.child("methods"), in);
  c.sweep = read_sweep(in.child("sweep"), file);
  check_run_count(c, in);
  in.read("metrics", c.metrics);
  c.params = in.child("params");
  if (c.params.IsDefined() && !c.params.IsNull() && !c.params.IsMap())
    in.fail("params", "key 'params' must be a map");
  c.reference = in.child("reference");
  if (c.reference.IsDefined() && !c.reference.IsNull() && !c.reference.IsMap())
    in.fail("reference", "key 'reference' must be a map");
  in.finish();

  // The effective document: everything but the quick block (the runs' identity must not depend on it).
  c.effective = YAML::Node(YAML::NodeType::Map);
  for (const auto& entry : doc) {
    if (entry.first.as<std::string>() != "quick") c.effective[entry.first.as<std::string>()] = entry.second;
  }
  return c;
}

ExperimentConfig read_experiment_config(const std::filesystem::path& file, bool quick) {
  return parse_experiment_config(load_yaml_file(file.string()), file.string(), quick);
}

std::vector<std::filesystem::path> list_experiment_configs(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(folder)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file() && is_experiment_file_name(entry.path().filename().string()))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

const SweepAxis* find_axis(const ExperimentConfig& config, const std::string& name) {
  for (const SweepAxis& axis : config.sweep)
    if (axis.name == name) return &axis;
  return nullptr;
}

}  // namespace sextant
