#include "results_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "sextant/core/error.hpp"

namespace sextant::detail {

ResultsLock::ResultsLock(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw InputError(folder.string(), "", "cannot create the results folder: " + ec.message());
  const std::filesystem::path file = folder / kLockFile;
  fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw InputError(folder.string(), "",
                     "the results folder is not writable (" + std::string(std::strerror(errno)) +
                         "); choose another with --results");
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK) {
      throw InputError(folder.string(), "",
                       "another sextant process is running this experiment into the same results folder "
                       "(it holds " +
                           file.string() +
                           "); wait for it to finish, or give this one another --results folder");
    }
    throw InputError(file.string(), "", "cannot lock: " + std::string(std::strerror(error)));
  }
}

ResultsLock::~ResultsLock() {
  if (fd_ >= 0) ::close(fd_);  // closing releases the flock
}

}  // namespace sextant::detail
