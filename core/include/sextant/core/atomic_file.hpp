#pragma once
// Results are written atomically: to a temporary file beside the target, flushed, then renamed,
// so a killed process leaves either the old file or the new one, never half of one.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace sextant {

/// Writes `content` to `path` atomically (creating parent folders).
void write_file_atomically(const std::filesystem::path& path, const std::string& content);
/// Same, with the content produced by a writer callback on a binary ofstream.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& writer);

/// Appends one line (a trailing '\n' is added) with a single write(2) followed by fsync, so
/// concurrent or killed writers never leave a partial line of less than PIPE_BUF bytes.
void append_line_durably(const std::filesystem::path& path, const std::string& line);

}  // namespace sextant
