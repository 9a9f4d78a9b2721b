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
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& writer);

/// Same, for writers that need a file name (e.g. a third-party library's save function): the
/// callback writes the temporary file whose path it is given, which is then renamed into place.
void write_file_atomically_via_path(
    const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path& temporary)>& writer);

/// Appends one line (a trailing '\n' is added) with a single write(2) followed by fsync, so
/// concurrent or killed writers never leave a partial line of less than PIPE_BUF bytes.
void append_line_durably(const std::filesystem::path& path, const std::string& line);

}  // namespace sextant
