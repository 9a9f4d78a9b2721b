#include "binary_fields.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <utility>

#include "sextant/core/error.hpp"
#include "sextant/core/io/point_time.hpp"
#include "text_parse.hpp"

namespace sextant::detail {
namespace {

template <class T>
T load(const unsigned char* p, bool swap) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, p, sizeof(T));
  if (swap) {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
  }
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

}  // namespace

void fail(const std::filesystem::path& file, const std::string& where, const std::string& what) {
  throw InputError(file.string(), where, what);
}

double read_scalar(const unsigned char* p, ScalarType type, bool swap) {
  switch (type.kind) {
    case 'F': return type.size == 8 ? load<double>(p, swap) : static_cast<double>(load<float>(p, swap));
    case 'I':
      switch (type.size) {
        case 1: return static_cast<double>(static_cast<std::int8_t>(p[0]));
        case 2: return static_cast<double>(load<std::int16_t>(p, swap));
        case 4: return static_cast<double>(load<std::int32_t>(p, swap));
        default: return static_cast<double>(load<std::int64_t>(p, swap));
      }
    default:
      switch (type.size) {
        case 1: return static_cast<double>(p[0]);
        case 2: return static_cast<double>(load<std::uint16_t>(p, swap));
        case 4: return static_cast<double>(load<std::uint32_t>(p, swap));
        default: return static_cast<double>(load<std::uint64_t>(p, swap));
      }
  }
}

std::vector<std::string_view> split_tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t end = i;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r') ++end;
    if (end > i) out.push_back(line.substr(i, end - i));
    i = end;
  }
  return out;
}

std::uint64_t parse_count(const std::filesystem::path& file, long line, std::string_view key,
                          std::string_view token) {
  std::uint64_t value = 0;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (ec != std::errc() || ptr != token.data() + token.size()) {
    throw InputError(
        file.string(), at_line(line),
        std::string(key) + ": expected a non-negative integer, found '" + std::string(token) + "'");
  }
  return value;
}

PointSink::Time time_kind(bool found, ScalarType type) {
  if (!found) return PointSink::Time::none;
  return type.kind == 'F' ? PointSink::Time::floating : PointSink::Time::integer;
}

PointSink::PointSink(std::size_t expected, bool with_intensity, Time time)
    : with_intensity_(with_intensity), time_(time) {
  cloud_.mutable_points().reserve(expected);
  if (with_intensity_) cloud_.intensity().reserve(expected);
  if (time_ != Time::none) raw_times_.reserve(expected);
}

void PointSink::add(double x, double y, double z, double intensity, double time) {
  ++report_.points_read;
  if (!fits_float(x) || !fits_float(y) || !fits_float(z) || (with_intensity_ && !fits_float(intensity)) ||
      (time_ != Time::none && !std::isfinite(time))) {
    ++report_.non_finite_dropped;
    return;
  }
  if (time_ != Time::none) raw_times_.push_back(time);
  const Eigen::Vector3f p(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
  if (with_intensity_) {
    cloud_.push_back(p, static_cast<float>(intensity));
  } else {
    cloud_.push_back(p);
  }
}

PointCloud PointSink::take(ScanLoadReport* report) {
  if (time_ != Time::none) {
    cloud_.set_time(point_times_to_seconds(raw_times_, time_ == Time::integer, std::nullopt));
    // A finite raw value whose seconds overflow float (1e300 s) is dropped as non-finite too.
    report_.non_finite_dropped += remove_non_finite(cloud_);
  }
  if (report) *report = report_;
  return std::move(cloud_);
}

}  // namespace sextant::detail
