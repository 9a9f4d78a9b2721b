#pragma once
// Errors at the boundaries (files, YAML, CLI): one exception type whose message names the
// file, the place in it (line or byte offset) and the problem, so a user can act on it.
#include <stdexcept>
#include <string>

namespace sextant {

class InputError : public std::runtime_error {
 public:
  /// `where` is e.g. "line 12" or "byte 4096"; empty when the problem concerns the whole file.
  InputError(std::string file, std::string where, std::string problem);

  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_, where_, problem_;
};

/// A file or folder the system would not open, create, rename or write: the system's error number
/// beside the message (Python raises the matching OSError: FileNotFoundError, PermissionError, …).
class FileError : public InputError {
 public:
  /// `error_number`: errno (0 when the system gave none); `problem` says what failed and why.
  FileError(std::string file, std::string problem, int error_number);
  /// The problem, " (the system's message)" appended: "cannot open: No such file or directory".
  static FileError from_errno(std::string file, const std::string& what, int error_number);
  int error_number() const { return error_number_; }

 private:
  int error_number_ = 0;
};

/// "line N" helper for messages.
std::string at_line(long line);
/// "byte N" helper for messages.
std::string at_byte(long long offset);

}  // namespace sextant
