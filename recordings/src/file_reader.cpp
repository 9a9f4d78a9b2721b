// Random access to one file of a recording (file_reader.hpp).
#include "file_reader.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {

FileReader::FileReader(const std::filesystem::path& path) : path_(path), name_(path.string()) {
  fd_ = ::open(name_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) throw FileError::from_errno(name_, "cannot open", errno);
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    const int error = errno;
    ::close(fd_);
    throw FileError::from_errno(name_, "cannot read its size", error);
  }
  if (S_ISDIR(info.st_mode)) {
    ::close(fd_);
    throw FileError(name_, "is a folder, expected a recording file", EISDIR);
  }
  size_ = static_cast<std::uint64_t>(info.st_size);
}

FileReader::~FileReader() {
  if (fd_ >= 0) ::close(fd_);
}

void FileReader::read_into(std::uint64_t offset, std::uint64_t n, std::uint8_t* out,
                           const std::string& what) const {
  if (offset > size_ || n > size_ - offset)
    throw InputError(name_, at_byte(static_cast<long long>(offset)),
                     "truncated " + what + ": needs " + std::to_string(n) + " bytes, the file ends at byte " +
                         std::to_string(size_));
  std::uint64_t done = 0;
  while (done < n) {
    const ssize_t got = ::pread(fd_, out + done, n - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw FileError::from_errno(name_, "cannot read " + what, errno);
    if (got == 0)
      throw InputError(name_, at_byte(static_cast<long long>(offset + done)),
                       "truncated " + what + ": the file ended while reading it");
    done += static_cast<std::uint64_t>(got);
  }
}

Bytes FileReader::read(std::uint64_t offset, std::uint64_t n, const std::string& what) const {
  if (offset > size_ || n > size_ - offset) read_into(offset, n, nullptr, what);  // throws
  Bytes bytes(n);
  read_into(offset, n, bytes.data(), what);
  return bytes;
}

Bytes FileReader::read_at(std::uint64_t offset, std::uint64_t n, const std::string& what,
                          Place* place) const {
  if (place) *place = Place{name_, offset, "", ""};
  return read(offset, n, what);
}

}  // namespace sextant::recordings_detail
