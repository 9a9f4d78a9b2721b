#pragma once
// Private: random access to one file of a recording, safe to use from several threads at once (each
// read is one pread), so that scans of a recording load in parallel without a lock.
#include <cstdint>
#include <filesystem>
#include <string>

#include "byte_cursor.hpp"

namespace sextant::recordings_detail {

class FileReader {
 public:
  /// FileError when the file cannot be opened.
  explicit FileReader(const std::filesystem::path& path);
  ~FileReader();
  FileReader(const FileReader&) = delete;
  FileReader& operator=(const FileReader&) = delete;

  const std::string& name() const { return name_; }
  const std::filesystem::path& path() const { return path_; }
  std::uint64_t size() const { return size_; }

  /// The `n` bytes at `offset`. InputError naming `what` and the offset when they run past the end of the
  /// file (a truncated file, or a length or offset field that is wrong); FileError when reading fails.
  Bytes read(std::uint64_t offset, std::uint64_t n, const std::string& what) const;
  /// As read(), into `out`.
  void read_into(std::uint64_t offset, std::uint64_t n, std::uint8_t* out, const std::string& what) const;
  /// A cursor over read(offset, n), its places named by their byte in the file.
  Bytes read_at(std::uint64_t offset, std::uint64_t n, const std::string& what, Place* place) const;

 private:
  std::filesystem::path path_;
  std::string name_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

}  // namespace sextant::recordings_detail
