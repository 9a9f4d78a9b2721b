#include "sextant/core/output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "sextant/core/error.hpp"

namespace fs = std::filesystem;

namespace sextant {
namespace {

/// The absolute target with symbolic links resolved (a link to a folder replaces the folder it
/// points to, not the link) and without a trailing separator.
fs::path resolve(const fs::path& target) {
  std::error_code ec;
  fs::path p = fs::absolute(target, ec).lexically_normal();
  if (!ec && p.filename().empty()) p = p.parent_path();
  if (!ec) p = fs::weakly_canonical(p, ec);
  if (ec) throw InputError(target.string(), "", "cannot resolve the output folder: " + ec.message());
  if (p == p.root_path()) throw InputError(target.string(), "", "cannot replace the root folder");
  return p;
}

/// flock on `file`, re-opened when another process removed or replaced it between our open and
/// our lock (the holder removes it when it is done).
int lock_file(const fs::path& file, const fs::path& target) {
  for (;;) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw FileError::from_errno(target.string(), "cannot create the folder's lock " + file.string(), errno);
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd);
      if (error == EWOULDBLOCK)
        throw InputError(target.string(), "",
                         "another sextant process writes this output folder now (it holds " + file.string() +
                             "); wait for it to finish, or choose another output folder");
      throw InputError(file.string(), "", "cannot lock: " + std::string(std::strerror(error)));
    }
    struct stat locked {
    }, named{};
    if (::fstat(fd, &locked) == 0 && ::stat(file.c_str(), &named) == 0 && locked.st_ino == named.st_ino &&
        locked.st_dev == named.st_dev)
      return fd;
    ::close(fd);
  }
}

/// InputError unless `folder` is absent, empty, or carries sextant's marker.
void check_replaceable(const fs::path& folder, const fs::path& target) {
  std::error_code ec;
  const fs::file_status status = fs::status(folder, ec);
  if (status.type() == fs::file_type::not_found) return;
  if (status.type() != fs::file_type::directory)
    throw InputError(target.string(), "", "is a file, not a folder: choose a folder for the output");
  if (fs::exists(folder / kMarkerFile)) return;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    throw InputError(
        target.string(), "",
        "holds files sextant did not write (e.g. '" + entry.path().filename().string() +
            "'); sextant replaces its output folder as a whole, so choose a new or empty folder");
  }
  if (ec) throw InputError(target.string(), "", "cannot list the folder: " + ec.message());
}

/// Staging and previous folders of killed runs of this target (we hold its lock: none is in use).
void remove_leftovers(const fs::path& parent, const std::string& name) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string file = entry.path().filename().string();
    if (file.rfind("." + name + ".partial-", 0) == 0 || file.rfind("." + name + ".previous-", 0) == 0)
      fs::remove_all(entry.path(), ec);
  }
}

void fsync_folder(const fs::path& folder) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

fs::path lock_path(const fs::path& resolved) {
  return resolved.parent_path() / ("." + resolved.filename().string() + ".lock");
}

}  // namespace

OutputFolder::OutputFolder(const fs::path& target, const std::string& command)
    : target_(target), resolved_(resolve(target)) {
  const fs::path parent = resolved_.parent_path();
  const std::string name = resolved_.filename().string();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec)
    throw FileError(target.string(), "cannot create the folder it goes in: " + ec.message(), ec.value());
  lock_fd_ = lock_file(lock_path(resolved_), target);
  try {
    check_replaceable(resolved_, target);
    remove_leftovers(parent, name);
    staging_ = parent / ("." + name + ".partial-" + std::to_string(::getpid()));
    fs::create_directory(staging_, ec);
    if (ec)
      throw FileError(target.string(), "cannot create " + staging_.string() + ": " + ec.message(),
                      ec.value());
    std::ofstream marker(staging_ / kMarkerFile);
    marker << "written by " << command << "; the folder is replaced as a whole by the next run into it\n";
    if (!marker) throw FileError::from_errno((staging_ / kMarkerFile).string(), "cannot write", errno);
  } catch (...) {
    release();
    throw;
  }
}

OutputFolder::~OutputFolder() {
  release();
}

void OutputFolder::release() {
  std::error_code ec;
  if (!committed_ && !staging_.empty()) fs::remove_all(staging_, ec);
  if (lock_fd_ >= 0) {
    ::unlink(lock_path(resolved_).c_str());  // while holding it: see lock_file
    ::close(lock_fd_);
    lock_fd_ = -1;
  }
}

void OutputFolder::commit() {
  const fs::path parent = resolved_.parent_path();
  std::error_code ec;
  if (!fs::exists(resolved_)) {
    fs::rename(staging_, resolved_, ec);
    if (ec)
      throw FileError(target_.string(), "cannot move the run's files into place: " + ec.message(),
                      ec.value());
  } else if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, resolved_.c_str(), RENAME_EXCHANGE) == 0) {
    fs::remove_all(staging_, ec);  // now the earlier run's files
  } else if (errno == EINVAL || errno == ENOSYS || errno == ENOTSUP) {
    // No atomic exchange here: a kill between the two renames leaves no folder, and the previous
    // one beside it (removed by the next run).
    const fs::path previous =
        parent / ("." + resolved_.filename().string() + ".previous-" + std::to_string(::getpid()));
    fs::rename(resolved_, previous, ec);
    if (!ec) fs::rename(staging_, resolved_, ec);
    if (ec)
      throw FileError(target_.string(), "cannot move the run's files into place: " + ec.message(),
                      ec.value());
    fs::remove_all(previous, ec);
  } else {
    throw FileError::from_errno(target_.string(), "cannot move the run's files into place", errno);
  }
  committed_ = true;
  fsync_folder(parent);
}

}  // namespace sextant
