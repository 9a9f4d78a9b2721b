#pragma once
// Private helpers of the PCD and PLY readers: scalar types of binary records, header tokens, and
// the checked accumulation of points (NaN, ±Inf and values outside float's range dropped and counted).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "sextant/core/dataset.hpp"
#include "sextant/core/point_cloud.hpp"

namespace sextant::detail {

/// A scalar of a binary record: 'I' signed, 'U' unsigned, 'F' floating point; size in bytes.
struct ScalarType {
  char kind = 'F';
  int size = 4;
};

/// Throws InputError(file, where, what): a malformed header or record.
[[noreturn]] void fail(const std::filesystem::path& file, const std::string& where, const std::string& what);

/// Reads one scalar at `p` (the caller checked that `size` bytes are there); `swap` for big-endian.
double read_scalar(const unsigned char* p, ScalarType type, bool swap);

/// Splits a header line into whitespace-separated tokens.
std::vector<std::string_view> split_tokens(std::string_view line);

/// A non-negative integer header value (e.g. WIDTH, a vertex count), or InputError naming `key`.
std::uint64_t parse_count(const std::filesystem::path& file, long line, std::string_view key,
                          std::string_view token);

/// Collects points into a cloud: counts every point read, drops and counts the ones whose
/// coordinates (or intensity) are NaN, ±Inf or outside float's range.
class PointSink {
 public:
  PointSink(std::size_t expected, bool with_intensity);
  void add(double x, double y, double z, double intensity);
  PointCloud take(ScanLoadReport* report);

 private:
  bool with_intensity_;
  PointCloud cloud_;
  ScanLoadReport report_;
};

}  // namespace sextant::detail
