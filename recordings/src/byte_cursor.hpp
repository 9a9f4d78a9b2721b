#pragma once
// Private: bounded reading of the binary records of bags and MCAP files (little-endian, or big-endian
// for a CDR message that says so), with errors that name the file and the byte where a record breaks.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sextant::recordings_detail {

using Bytes = std::vector<std::uint8_t>;

/// Where a range of bytes lies, for messages: the file, and how to name the byte at position p of the
/// range: `prefix` + "byte " + (base + p) + `suffix` ("byte 4121", "byte 310 of the zstd chunk at byte 43").
struct Place {
  std::string file;
  std::uint64_t base = 0;
  std::string prefix, suffix;
  std::string at(std::uint64_t position) const;
};

/// Reads fixed-width values, strings and byte runs from a range, never past its end: a read that would
/// go past it throws InputError(file, the byte it starts at, "truncated …: needs N bytes, M left").
class ByteCursor {
 public:
  ByteCursor(const std::uint8_t* data, std::size_t size, Place place, bool big_endian = false);
  ByteCursor(const Bytes& bytes, Place place, bool big_endian = false)
      : ByteCursor(bytes.data(), bytes.size(), std::move(place), big_endian) {}

  std::size_t position() const { return position_; }
  std::size_t size() const { return size_; }
  std::size_t remaining() const { return size_ - position_; }
  bool at_end() const { return position_ == size_; }
  const std::uint8_t* data() const { return data_; }
  const Place& place() const { return place_; }
  /// The place of the byte at `position` (default: the current one), as Place::at names it.
  std::string where() const { return place_.at(position_); }
  std::string where(std::size_t position) const { return place_.at(position); }

  void seek(std::size_t position, const char* what);
  void skip(std::size_t n, const char* what) { (void)take(n, what); }
  /// Advances to the next multiple of `n` from the range's start (CDR aligns from its payload's start).
  void align(std::size_t n, const char* what);

  std::uint8_t u8(const char* what);
  std::uint16_t u16(const char* what);
  std::uint32_t u32(const char* what);
  std::uint64_t u64(const char* what);
  std::int32_t i32(const char* what) { return static_cast<std::int32_t>(u32(what)); }
  /// A uint32 byte length, then that many bytes (MCAP strings, ROS 1 strings).
  std::string string32(const char* what);
  /// `n` bytes: a pointer into the range, valid while it is.
  const std::uint8_t* take(std::size_t n, const char* what);

  /// Throws InputError(file, where(position), problem).
  [[noreturn]] void fail(const std::string& problem) const { fail_at(position_, problem); }
  [[noreturn]] void fail_at(std::size_t position, const std::string& problem) const;

 private:
  std::uint64_t unsigned_value(std::size_t width, const char* what);

  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
  Place place_;
  bool big_endian_;
};

/// Little-endian loads from memory the caller checked.
std::uint32_t load_u32(const std::uint8_t* p);
std::uint64_t load_u64(const std::uint8_t* p);

}  // namespace sextant::recordings_detail
