#pragma once
// Maps a YAML map onto a settings struct. Every problem — an unknown key, a wrong type, a value
// out of range — is an InputError naming the file, the line and the key:
//
//   SettingsReader in(node, file);
//   in.read("cell_size", s.cell_size);        // optional key, keeps the default when absent
//   in.read("layers", s.layers);
//   in.finish();                              // throws on keys nobody read (typos)
//   std::string why; if (!s.valid(&why)) in.fail("", why);
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "sextant/core/error.hpp"

namespace sextant {

/// While one is alive on this thread, every SettingsReader records each key it reads with the
/// value the setting ends with (the file's, or the default it kept): the fully resolved settings,
/// for provenance.json and --print-config. A child read through child() nests under its key; a
/// second top-level reader (FbML-NDT's ML-NDT keys) adds its keys to the same map.
///
///   SettingsRecording recording;
///   auto matcher = make_matcher("mlndt", node, file);
///   YAML::Node resolved = recording.resolved();
class SettingsRecording {
 public:
  SettingsRecording();
  ~SettingsRecording();
  SettingsRecording(const SettingsRecording&) = delete;
  SettingsRecording& operator=(const SettingsRecording&) = delete;
  const YAML::Node& resolved() const { return root_; }

 private:
  friend class SettingsReader;
  YAML::Node root_{YAML::NodeType::Map};
  YAML::Node next_child_;  ///< where the reader of the child just handed out records (a map)
  bool child_pending_ = false;
  SettingsRecording* previous_ = nullptr;
};

class SettingsReader {
 public:
  /// `node` may be null/undefined (all defaults); otherwise it must be a map.
  SettingsReader(const YAML::Node& node, std::string file);

  /// Reads `key` into `value` if present (scalar types, std::string, std::vector of scalars). A
  /// SettingsRecording records `value` as it ends: initialise it with the default.
  template <class T>
  bool read(const std::string& key, T& value);

  /// Reads a deprecated spelling of another key: as read(), but not recorded (the other key is).
  template <class T>
  bool read_alias(const std::string& key, T& value) {
    return read_value(key, value);
  }
  /// Reads a required key.
  template <class T>
  void require(const std::string& key, T& value);

  bool has(const std::string& key) const;
  /// A child node (marked as read) for nested settings; null when absent.
  YAML::Node child(const std::string& key);
  /// Throws InputError for the first key that was not read.
  void finish() const;
  /// Throws InputError at `key`'s line (or the map's line when key is empty or absent).
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

  const std::string& file() const { return file_; }
  const YAML::Node& node() const { return node_; }

 private:
  template <class T>
  bool read_value(const std::string& key, T& value);

  YAML::Node node_;
  std::string file_;
  std::set<std::string> read_;
  bool recording_ = false;
  YAML::Node record_;  ///< the resolved map this reader writes to, when recording_
};

/// 1-based line of a node (0 when unknown).
long yaml_line(const YAML::Node& node);
/// Loads a YAML file; a syntax error becomes an InputError with the line.
YAML::Node load_yaml_file(const std::string& path);

template <class T>
bool SettingsReader::read(const std::string& key, T& value) {
  const bool found = read_value(key, value);
  if (recording_) record_[key] = value;
  return found;
}

template <class T>
bool SettingsReader::read_value(const std::string& key, T& value) {
  if (!node_.IsMap()) return false;
  const YAML::Node v = node_[key];
  if (!v.IsDefined() || v.IsNull()) {
    if (v.IsDefined()) read_.insert(key);
    return false;
  }
  read_.insert(key);
  try {
    value = v.as<T>();
  } catch (const YAML::Exception&) {
    throw InputError(file_, at_line(yaml_line(v)),
                     "key '" + key + "': cannot read '" + YAML::Dump(v) + "' as the expected type");
  }
  return true;
}

template <class T>
void SettingsReader::require(const std::string& key, T& value) {
  if (!read(key, value)) fail(key, "required key '" + key + "' is missing");
}

}  // namespace sextant
