// Which files a recording is made of (recording_files.hpp).
#include "recording_files.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <fstream>

#include "container.hpp"
#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {
namespace {

namespace fs = std::filesystem;

std::size_t indent_of(const std::string& line) {
  return line.find_first_not_of(' ') == std::string::npos ? line.size() : line.find_first_not_of(' ');
}

std::string trimmed(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

/// A plain or quoted YAML scalar as rosbag2 writes them ('', "", ~).
std::string scalar(const std::string& raw) {
  const std::string v = trimmed(raw);
  if (v == "~" || v == "null") return "";
  if (v.size() >= 2 && v.front() == '\'' && v.back() == '\'') {
    std::string out;
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
      out += v[i];
      if (v[i] == '\'' && v[i + 1] == '\'') ++i;
    }
    return out;
  }
  if (v.size() >= 2 && v.front() == '"' && v.back() == '"') {
    std::string out;
    for (std::size_t i = 1; i + 1 < v.size(); ++i) {
      if (v[i] == '\\' && i + 2 < v.size()) ++i;
      out += v[i];
    }
    return out;
  }
  return v;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// The number at the end of a file's stem (multiple_files_12.db3 → 12), for the old layout's order.
long trailing_number(const fs::path& file) {
  const std::string stem = file.stem().string();
  std::size_t digits = stem.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(stem[digits - 1]))) --digits;
  if (digits == stem.size() || stem.size() - digits > 9) return -1;
  return std::stol(stem.substr(digits));
}

std::optional<RecordingFiles> folder_files(const fs::path& folder) {
  RecordingFiles r{folder, "rosbag2", {}, false, ""};
  const fs::path metadata = folder / "metadata.yaml";
  std::error_code ec;
  const std::optional<Rosbag2Metadata> read =
      fs::exists(metadata, ec) ? read_rosbag2_metadata(metadata) : std::nullopt;
  if (read) {
    const Rosbag2Metadata& m = *read;
    r.layout = "metadata.yaml";
    const std::string mode = lower(m.compression_mode);
    if (!m.compression_format.empty() && m.compression_format != "zstd")
      throw InputError(metadata.string(), "",
                       "compression_format '" + m.compression_format + "': sextant reads zstd");
    if (mode == "file")
      throw InputError(
          metadata.string(), "",
          "the bag is compressed file by file (compression_mode: file): decompress its files first "
          "(`zstd -d`) and name them in relative_file_paths");
    r.zstd_messages = mode == "message" && m.compression_format == "zstd";
    for (const std::string& name : m.relative_file_paths) {
      const fs::path file = fs::path(name).is_absolute() ? fs::path(name) : folder / name;
      if (!fs::exists(file, ec))
        throw FileError(file.string(),
                        "listed in " + metadata.string() + " (relative_file_paths), but missing", ENOENT);
      r.files.push_back(file);
    }
    if (r.files.empty()) throw InputError(metadata.string(), "", "relative_file_paths lists no file");
    return r;
  }
  for (const auto& entry : fs::directory_iterator(folder, ec))
    if (entry.path().extension() == ".db3") r.files.push_back(entry.path());
  if (r.files.empty()) return std::nullopt;
  std::sort(r.files.begin(), r.files.end(), [](const fs::path& a, const fs::path& b) {
    const long na = trailing_number(a), nb = trailing_number(b);
    return na != nb ? na < nb : a < b;
  });
  r.layout = "old layout without metadata.yaml";
  return r;
}

}  // namespace

std::optional<Rosbag2Metadata> read_rosbag2_metadata(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw FileError::from_errno(file.string(), "cannot open", errno);
  Rosbag2Metadata m;
  std::string line;
  bool inside = false, found = false, in_files = false;
  std::size_t key_indent = std::string::npos;
  while (std::getline(in, line)) {
    if (trimmed(line).empty() || trimmed(line)[0] == '#') continue;
    const std::size_t indent = indent_of(line);
    if (indent == 0) {
      inside = trimmed(line) == "rosbag2_bagfile_information:";
      found = found || inside;
      in_files = false;
      continue;
    }
    if (!inside) continue;
    if (key_indent == std::string::npos) key_indent = indent;
    const std::string text = trimmed(line);
    if (in_files && text.rfind("- ", 0) == 0 && indent >= key_indent) {
      m.relative_file_paths.push_back(scalar(text.substr(2)));
      continue;
    }
    if (indent != key_indent) continue;  // deeper: a value of a key we do not read
    in_files = false;
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos) continue;
    const std::string key = text.substr(0, colon), value = text.substr(colon + 1);
    if (key == "storage_identifier") m.storage_identifier = scalar(value);
    if (key == "compression_format") m.compression_format = scalar(value);
    if (key == "compression_mode") m.compression_mode = scalar(value);
    if (key == "relative_file_paths") {
      in_files = true;
      if (scalar(value) == "[]") in_files = false;
    }
  }
  if (!found) return std::nullopt;
  return m;
}

std::optional<RecordingFiles> find_recording_files(const fs::path& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return folder_files(path);
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  if (path.filename() == "metadata.yaml") {
    auto r = folder_files(path.parent_path().empty() ? fs::path(".") : path.parent_path());
    if (r) r->path = path;
    return r;
  }
  const std::string extension = lower(path.extension().string());
  std::string format = extension == ".bag"    ? "rosbag1"
                       : extension == ".mcap" ? "mcap"
                       : extension == ".db3"  ? "rosbag2"
                                              : "";
  if (format.empty()) {
    const std::string sniffed = sniff_format(path);
    if (sniffed == "rosbag1" || sniffed == "mcap") format = sniffed;
  }
  if (format.empty()) return std::nullopt;
  return RecordingFiles{path, format, {path}, false, ""};
}

}  // namespace sextant::recordings_detail
