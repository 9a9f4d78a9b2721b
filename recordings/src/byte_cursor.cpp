// Bounded reading of binary records (byte_cursor.hpp).
#include "byte_cursor.hpp"

#include <cstring>

#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {

std::string Place::at(std::uint64_t position) const {
  return prefix + "byte " + std::to_string(base + position) + suffix;
}

ByteCursor::ByteCursor(const std::uint8_t* data, std::size_t size, Place place, bool big_endian)
    : data_(data), size_(size), place_(std::move(place)), big_endian_(big_endian) {}

void ByteCursor::fail_at(std::size_t position, const std::string& problem) const {
  throw InputError(place_.file, place_.at(position), problem);
}

const std::uint8_t* ByteCursor::take(std::size_t n, const char* what) {
  if (n > remaining())
    fail("truncated " + std::string(what) + ": needs " + std::to_string(n) + " bytes, " +
         std::to_string(remaining()) + " left");
  const std::uint8_t* p = data_ + position_;
  position_ += n;
  return p;
}

void ByteCursor::seek(std::size_t position, const char* what) {
  if (position > size_)
    fail(std::string(what) + " at " + std::to_string(position) + " lies past the end (" +
         std::to_string(size_) + " bytes)");
  position_ = position;
}

void ByteCursor::align(std::size_t n, const char* what) {
  const std::size_t padding = (n - position_ % n) % n;
  if (padding > remaining()) fail("truncated " + std::string(what) + ": the padding before it is cut off");
  position_ += padding;
}

std::uint64_t ByteCursor::unsigned_value(std::size_t width, const char* what) {
  const std::uint8_t* p = take(width, what);
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < width; ++i) {
    const std::uint64_t byte = p[big_endian_ ? i : width - 1 - i];
    value = (value << 8) | byte;
  }
  return value;
}

std::uint8_t ByteCursor::u8(const char* what) {
  return *take(1, what);
}
std::uint16_t ByteCursor::u16(const char* what) {
  return static_cast<std::uint16_t>(unsigned_value(2, what));
}
std::uint32_t ByteCursor::u32(const char* what) {
  return static_cast<std::uint32_t>(unsigned_value(4, what));
}
std::uint64_t ByteCursor::u64(const char* what) {
  return unsigned_value(8, what);
}

std::string ByteCursor::string32(const char* what) {
  const std::size_t start = position_;
  const std::uint32_t length = u32(what);
  if (length > remaining())
    fail_at(start, std::string(what) + " claims " + std::to_string(length) + " bytes, only " +
                       std::to_string(remaining()) + " follow");
  const std::uint8_t* p = take(length, what);
  return std::string(reinterpret_cast<const char*>(p), length);
}

std::uint32_t load_u32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

std::uint64_t load_u64(const std::uint8_t* p) {
  return static_cast<std::uint64_t>(load_u32(p)) | static_cast<std::uint64_t>(load_u32(p + 4)) << 32;
}

}  // namespace sextant::recordings_detail
