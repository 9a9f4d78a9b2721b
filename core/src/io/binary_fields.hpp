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
/// coordinates (or intensity) are NaN, ±Inf or outside float's range, or whose time is not finite.
class PointSink {
 public:
  /// `time`: the points have a per-point time field (point_time.hpp), of an integer type or not.
  enum class Time { none, integer, floating };
  PointSink(std::size_t expected, bool with_intensity, Time time = Time::none);
  /// `time` is the field's raw value (ignored without a time field).
  void add(double x, double y, double z, double intensity, double time = 0.0);
  /// The cloud, with its times in seconds (point_times_to_seconds: a file knows no stamp, so times
  /// since the epoch become relative to the earliest point).
  PointCloud take(ScanLoadReport* report);

 private:
  bool with_intensity_;
  Time time_;
  PointCloud cloud_;
  std::vector<double> raw_times_;
  ScanLoadReport report_;
};

/// The time field a reader found: none, or an integer or floating one.
PointSink::Time time_kind(bool found, ScalarType type);

}  // namespace sextant::detail
