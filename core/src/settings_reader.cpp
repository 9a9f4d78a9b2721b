#include "sextant/core/settings_reader.hpp"

namespace sextant {

long yaml_line(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  const YAML::Mark mark = node.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

YAML::Node load_yaml_file(const std::string& path) {
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw InputError(path, "", "cannot open YAML file");
  } catch (const YAML::ParserException& e) {
    throw InputError(path, at_line(e.mark.line + 1), "YAML syntax error: " + e.msg);
  }
}

SettingsReader::SettingsReader(const YAML::Node& node, std::string file)
    : node_(node), file_(std::move(file)) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
    throw InputError(file_, at_line(yaml_line(node_)), "expected a map of settings");
  }
}

bool SettingsReader::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined();
}

YAML::Node SettingsReader::child(const std::string& key) {
  if (!node_.IsMap()) return YAML::Node();
  const YAML::Node v = node_[key];
  if (v.IsDefined()) read_.insert(key);
  return v;
}

void SettingsReader::finish() const {
  if (!node_.IsMap()) return;
  for (const auto& entry : node_) {
    const std::string key = entry.first.as<std::string>();
    if (!read_.count(key)) {
      throw InputError(file_, at_line(yaml_line(entry.first)), "unknown key '" + key + "'");
    }
  }
}

void SettingsReader::fail(const std::string& key, const std::string& problem) const {
  long line = yaml_line(node_);
  if (!key.empty() && node_.IsMap()) {
    for (const auto& entry : node_) {
      if (entry.first.as<std::string>() == key) line = yaml_line(entry.first);
    }
  }
  const std::string prefix =
      key.empty() || problem.find(key) != std::string::npos ? "" : "key '" + key + "': ";
  throw InputError(file_, line > 0 ? at_line(line) : "", prefix + problem);
}

}  // namespace sextant
