#include "sextant/core/settings_reader.hpp"

#include <filesystem>
#include <map>

namespace sextant {

long yaml_line(const YAML::Node& node) {
  if (!node.IsDefined()) return 0;
  const YAML::Mark mark = node.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

namespace {

// Aliases share nodes, so a few lines can stand for an exponentially large tree ("billion
// laughs"); everything that walks the tree later (merging, hashing, writing the effective config)
// would expand it. The walk below stops at the caps, so it costs at most kMaxYamlNodes steps.
constexpr std::size_t kMaxYamlNodes = 1000000;
constexpr int kMaxYamlDepth = 64;

void check_tree(const YAML::Node& node, int depth, std::size_t& count, const std::string& path) {
  if (++count > kMaxYamlNodes) {
    throw InputError(path, at_line(yaml_line(node)),
                     "the YAML expands to more than 10^6 nodes (aliases repeating aliases?)");
  }
  if (depth > kMaxYamlDepth)
    throw InputError(path, at_line(yaml_line(node)), "the YAML nests deeper than 64 levels");
  if (node.IsSequence()) {
    for (const auto& child : node) check_tree(child, depth + 1, count, path);
  } else if (node.IsMap()) {
    std::map<std::string, long> seen;  // key → its line: a repeated key is an error, not "the first wins"
    for (const auto& entry : node) {
      if (!entry.first.IsScalar()) {
        throw InputError(path, at_line(yaml_line(entry.first)),
                         "a map key must be a plain name, not a list or map");
      }
      const auto [first, inserted] = seen.emplace(entry.first.Scalar(), yaml_line(entry.first));
      if (!inserted) {
        throw InputError(path, at_line(yaml_line(entry.first)),
                         "duplicate key '" + entry.first.Scalar() + "' (first at line " +
                             std::to_string(first->second) + ")");
      }
      check_tree(entry.second, depth + 1, count, path);
    }
  }
}

}  // namespace

YAML::Node load_yaml_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, "", "is a folder, expected a YAML file");
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw FileError::from_errno(path, "cannot open YAML file", errno);
  } catch (const YAML::ParserException& e) {
    throw InputError(path, at_line(e.mark.line + 1), "YAML syntax error: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.line >= 0 ? at_line(e.mark.line + 1) : "", "YAML error: " + e.msg);
  }
  std::size_t count = 0;
  check_tree(root, 0, count, path);
  return root;
}

namespace {

thread_local SettingsRecording* t_recording = nullptr;

}  // namespace

SettingsRecording::SettingsRecording() : previous_(t_recording) {
  t_recording = this;
}
SettingsRecording::~SettingsRecording() {
  t_recording = previous_;
}

SettingsReader::SettingsReader(const YAML::Node& node, std::string file)
    : node_(node), file_(std::move(file)) {
  if (node_.IsDefined() && !node_.IsNull() && !node_.IsMap()) {
    throw InputError(file_, at_line(yaml_line(node_)), "expected a map of settings");
  }
  if (SettingsRecording* r = t_recording) {
    // The reader of a child handed out by child() records under its key; any other into the root.
    record_.reset(r->child_pending_ ? r->next_child_ : r->root_);  // reset: bind, never write through
    recording_ = true;
    r->child_pending_ = false;
  }
}

bool SettingsReader::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined();
}

YAML::Node SettingsReader::child(const std::string& key) {
  if (recording_ && t_recording) {
    YAML::Node nested(YAML::NodeType::Map);
    record_[key] = nested;
    t_recording->next_child_.reset(nested);
    t_recording->child_pending_ = true;
  }
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
