#pragma once
// Test-only: appending fixed-width values, strings and byte runs to a buffer, little- or big-endian,
// with CDR's alignment (from the first byte after the encapsulation header) when asked.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace sextant::test {

using Bytes = std::vector<std::uint8_t>;

class ByteWriter {
 public:
  explicit ByteWriter(bool big_endian = false, bool cdr = false, std::size_t origin = 0)
      : big_endian_(big_endian), cdr_(cdr), origin_(origin) {}

  Bytes& bytes() { return bytes_; }
  const Bytes& bytes() const { return bytes_; }
  std::size_t size() const { return bytes_.size(); }

  void align(std::size_t n) {
    if (!cdr_) return;
    while ((bytes_.size() - origin_) % n != 0) bytes_.push_back(0);
  }
  void u8(std::uint8_t v) { bytes_.push_back(v); }
  void u16(std::uint16_t v) { put(v, 2); }
  void u32(std::uint32_t v) { put(v, 4); }
  void u64(std::uint64_t v) { put(v, 8); }
  /// A u32 length and the bytes; with CDR the length counts a closing NUL, which follows.
  void string(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size() + (cdr_ ? 1 : 0)));
    raw(s.data(), s.size());
    if (cdr_) u8(0);
  }
  void raw(const void* p, std::size_t n) {
    const auto* b = static_cast<const std::uint8_t*>(p);
    bytes_.insert(bytes_.end(), b, b + n);
  }
  void raw(const Bytes& b) { bytes_.insert(bytes_.end(), b.begin(), b.end()); }
  /// Overwrites 4 or 8 bytes at `at` (little-endian): a length known only later.
  void patch_u32(std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes_[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
  }
  void patch_u64(std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) bytes_[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
  }

 private:
  void put(std::uint64_t v, int width) {
    align(static_cast<std::size_t>(width));
    for (int i = 0; i < width; ++i) {
      const int shift = 8 * (big_endian_ ? width - 1 - i : i);
      bytes_.push_back(static_cast<std::uint8_t>(v >> shift));
    }
  }

  Bytes bytes_;
  bool big_endian_, cdr_;
  std::size_t origin_;
};

}  // namespace sextant::test
