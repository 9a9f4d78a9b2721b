#include "sextant/core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "sextant/core/error.hpp"

namespace sextant {
namespace {

std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  return path.parent_path() / ("." + path.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                               std::to_string(counter++));
}

void create_parent_folder(const std::filesystem::path& path) {
  if (!path.has_parent_path()) return;
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) throw FileError(path.string(), "cannot create its folder: " + ec.message(), ec.value());
}

void fsync_path(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

void write_file_atomically_via_path(
    const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path& temporary)>& writer) {
  create_parent_folder(path);
  const auto tmp = temporary_beside(path);
  // The temporary file is created here, so that a folder we may not write is the system's error
  // naming the file, whatever the writer (PCL's says "Error during open!").
  const int fd =
      ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);  // as ofstream: the umask decides
  if (fd < 0) throw FileError::from_errno(path.string(), "cannot open for writing", errno);
  ::close(fd);
  try {
    writer(tmp);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw;
  }
  fsync_path(tmp);
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw FileError(path.string(), "cannot rename temporary file into place: " + ec.message(), ec.value());
  }
  if (path.has_parent_path()) fsync_path(path.parent_path());
}

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& writer) {
  write_file_atomically_via_path(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw FileError::from_errno(path.string(), "cannot open for writing", errno);
    writer(out);
    out.flush();
    if (!out) throw FileError::from_errno(path.string(), "write failed (the previous file is kept)", errno);
  });
}

void write_file_atomically(const std::filesystem::path& path, const std::string& content) {
  write_file_atomically(path, [&content](std::ostream& out) { out << content; });
}

void append_line_durably(const std::filesystem::path& path, const std::string& line) {
  create_parent_folder(path);
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd < 0) throw FileError::from_errno(path.string(), "cannot open for appending", errno);
  const std::string text = line + "\n";
  const off_t before = ::lseek(fd, 0, SEEK_END);
  const ssize_t written = ::write(fd, text.data(), text.size());
  const int write_errno = errno;
  if (written != static_cast<ssize_t>(text.size())) {
    // Disk full (ENOSPC), file-size limit (EFBIG), I/O error: take back a partial line, so the
    // file holds only whole lines and everything written before stays readable.
    if (before >= 0 && ::ftruncate(fd, before) == 0) ::fsync(fd);
    ::close(fd);
    throw InputError(path.string(), "",
                     "cannot append a line: " +
                         std::string(written < 0 ? std::strerror(write_errno) : "short write (disk full?)") +
                         "; the lines already in the file are kept");
  }
  ::fsync(fd);
  ::close(fd);
}

}  // namespace sextant
