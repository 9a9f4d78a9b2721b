// PCD reader (ascii, binary, binary_compressed), our own rather than PCL's: PCL's reader trusts
// the header (an empty file crashes it, a lying POINTS line allocates whatever it says). Every
// count in the header is checked against the bytes actually in the file before anything is
// allocated. A per-point time field under a driver's name (point_time.hpp) is kept.
// Layout: https://pointclouds.org/documentation/tutorials/pcd_file_format.html
#include <cstring>
#include <limits>
#include <string>

#include "binary_fields.hpp"
#include "formats.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/point_time.hpp"
#include "text_parse.hpp"

namespace sextant::detail {
namespace {

struct PcdField {
  std::string name;
  ScalarType type;
  std::uint64_t count = 1;
  std::uint64_t offset = 0;  // bytes into a binary record
  std::uint64_t column = 0;  // value index in an ascii line
};

struct PcdHeader {
  std::vector<PcdField> fields;
  std::uint64_t points = 0;
  std::uint64_t record = 0;   // bytes per point
  std::uint64_t columns = 0;  // values per ascii line
  std::string encoding;
  std::size_t data_offset = 0;
  long data_line = 0;
};

void fill_types(const std::filesystem::path& file, long line, PcdHeader& h,
                const std::vector<std::string_view>& t, const std::string& key) {
  if (t.size() - 1 != h.fields.size()) {
    fail(file, at_line(line),
         key + " has " + std::to_string(t.size() - 1) + " entries but FIELDS has " +
             std::to_string(h.fields.size()));
  }
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    PcdField& f = h.fields[i];
    const std::string_view v = t[i + 1];
    if (key == "SIZE") {
      const std::uint64_t size = parse_count(file, line, key, v);
      if (size != 1 && size != 2 && size != 4 && size != 8)
        fail(file, at_line(line), "SIZE must be 1, 2, 4 or 8");
      f.type.size = static_cast<int>(size);
    } else if (key == "TYPE") {
      if (v != "F" && v != "I" && v != "U") fail(file, at_line(line), "TYPE must be F, I or U");
      f.type.kind = v[0];
    } else {
      f.count = parse_count(file, line, key, v);
      if (f.count == 0 || f.count > (1u << 16)) fail(file, at_line(line), "COUNT must be 1 … 65536");
    }
  }
}

PcdHeader parse_pcd_header(const std::filesystem::path& file, const std::string& bytes) {
  if (bytes.empty()) fail(file, "", "empty file (0 bytes), not a PCD file");
  PcdHeader h;
  std::uint64_t width = 0, height = 1;
  bool have_width = false, have_points = false, have_size = false, have_type = false;
  std::size_t start = 0;
  long line = 0;
  while (start < bytes.size() && h.encoding.empty()) {
    std::size_t end = bytes.find('\n', start);
    if (end == std::string::npos) end = bytes.size();
    const std::string_view text(bytes.data() + start, end - start);
    start = end + 1;
    ++line;
    const std::vector<std::string_view> t = split_tokens(text);
    if (t.empty() || t[0][0] == '#') continue;
    const std::string key(t[0]);
    if (t.size() < 2) fail(file, at_line(line), "header line '" + key + "' has no value");
    if (key == "VERSION" || key == "VIEWPOINT") {
    } else if (key == "FIELDS" || key == "COLUMNS") {
      h.fields.clear();
      for (std::size_t i = 1; i < t.size(); ++i) h.fields.push_back(PcdField{std::string(t[i]), {}, 1, 0, 0});
    } else if (key == "SIZE" || key == "TYPE" || key == "COUNT") {
      fill_types(file, line, h, t, key);
      have_size = have_size || key == "SIZE";
      have_type = have_type || key == "TYPE";
    } else if (key == "WIDTH") {
      width = parse_count(file, line, key, t[1]);
      have_width = true;
    } else if (key == "HEIGHT") {
      height = parse_count(file, line, key, t[1]);
    } else if (key == "POINTS") {
      h.points = parse_count(file, line, key, t[1]);
      have_points = true;
    } else if (key == "DATA") {
      h.encoding = std::string(t[1]);
      if (h.encoding != "ascii" && h.encoding != "binary" && h.encoding != "binary_compressed") {
        fail(file, at_line(line),
             "DATA must be ascii, binary or binary_compressed, found '" + h.encoding + "'");
      }
      h.data_offset = std::min(start, bytes.size());
      h.data_line = line;
    } else {
      fail(file, at_line(line), "unknown PCD header line '" + key + "' (not a PCD file?)");
    }
  }
  if (h.encoding.empty()) fail(file, "", "no 'DATA' line: not a PCD file, or its header is cut off");
  if (h.fields.empty() || !have_size || !have_type || !have_width) {
    fail(file, "", "the header lacks FIELDS, SIZE, TYPE or WIDTH");
  }
  if (width > std::numeric_limits<std::uint32_t>::max() ||
      height > std::numeric_limits<std::uint32_t>::max()) {
    fail(file, "", "WIDTH or HEIGHT is larger than 2^32 − 1");
  }
  if (have_points && h.points != width * height) {
    fail(file, "",
         "POINTS " + std::to_string(h.points) + " is not WIDTH × HEIGHT = " + std::to_string(width * height));
  }
  h.points = width * height;
  for (PcdField& f : h.fields) {
    if (f.type.kind == 'F' && f.type.size != 4 && f.type.size != 8) {
      fail(file, "", "field '" + f.name + "': a float field must have SIZE 4 or 8");
    }
    f.offset = h.record;
    f.column = h.columns;
    h.record += f.count * static_cast<std::uint64_t>(f.type.size);
    h.columns += f.count;
  }
  return h;
}

const PcdField* find_field(const PcdHeader& h, const std::string& name) {
  for (const PcdField& f : h.fields) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

/// The per-point time field under any driver's name (point_time.hpp), or null.
const PcdField* time_field(const PcdHeader& h) {
  std::vector<std::string> names;
  for (const PcdField& f : h.fields) names.push_back(f.name);
  const auto index = find_point_time_field(names);
  return index ? &h.fields[*index] : nullptr;
}

/// LZF decompression (liblzf's format, as PCL writes it) with every read and write bounds-checked.
bool lzf_decompress(const unsigned char* in, std::size_t in_size, unsigned char* out, std::size_t out_size) {
  std::size_t i = 0, o = 0;
  while (i < in_size) {
    std::size_t ctrl = in[i++];
    if (ctrl < 32) {  // literal run of ctrl + 1 bytes
      const std::size_t n = ctrl + 1;
      if (n > in_size - i || n > out_size - o) return false;
      std::memcpy(out + o, in + i, n);
      i += n;
      o += n;
    } else {  // back reference
      std::size_t len = ctrl >> 5;
      if (len == 7) {
        if (i >= in_size) return false;
        len += in[i++];
      }
      len += 2;
      if (i >= in_size) return false;
      const std::size_t back = ((ctrl & 0x1f) << 8) + in[i++] + 1;
      if (back > o || len > out_size - o) return false;
      for (std::size_t k = 0; k < len; ++k, ++o) out[o] = out[o - back];  // may overlap
    }
  }
  return o == out_size;
}

std::string too_short(const PcdHeader& h, std::uint64_t need, std::size_t have) {
  return "the header promises " + std::to_string(h.points) + " points of " + std::to_string(h.record) +
         " bytes (" + std::to_string(need) + " bytes), but only " + std::to_string(have) +
         " bytes follow the header (truncated or lying header)";
}

}  // namespace

PointCloud read_pcd(const std::filesystem::path& file, ScanLoadReport* report) {
  const std::string bytes = read_file_bytes(file);
  const PcdHeader h = parse_pcd_header(file, bytes);
  const PcdField* axes[3] = {find_field(h, "x"), find_field(h, "y"), find_field(h, "z")};
  for (int k = 0; k < 3; ++k) {
    if (!axes[k]) fail(file, "", std::string("no '") + "xyz"[k] + "' field");
  }
  const PcdField* intensity = find_field(h, "intensity");
  const PcdField* time = time_field(h);
  const PointSink::Time time_type = time_kind(time != nullptr, time ? time->type : ScalarType{});
  const std::size_t have = bytes.size() - h.data_offset;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data()) + h.data_offset;
  const auto value_at = [&](const unsigned char* base, const PcdField& f) {
    return read_scalar(base + f.offset, f.type, false);
  };

  if (h.encoding == "ascii") {
    // Each point is a line of at least one character per value plus separators.
    if (h.points > have / (2 * h.columns) + 1)
      fail(file, at_line(h.data_line), too_short(h, h.points * 2 * h.columns, have));
    PointSink sink(static_cast<std::size_t>(h.points), intensity != nullptr, time_type);
    std::vector<double> v;
    std::string bad;
    std::uint64_t seen = 0;
    std::uint64_t beyond = 0;  // rows after the declared POINTS, counted rather than read
    for_each_line(std::string_view(bytes).substr(h.data_offset), [&](std::string_view line, long n) {
      const long number = h.data_line + n;
      if (is_blank(line)) return;
      if (seen >= h.points) {
        ++beyond;
        return;
      }
      if (!parse_numbers(line, v, &bad)) fail(file, at_line(number), bad_number_problem(bad));
      if (v.size() != h.columns) {
        fail(file, at_line(number),
             "expected " + std::to_string(h.columns) + " values, found " + std::to_string(v.size()));
      }
      sink.add(v[axes[0]->column], v[axes[1]->column], v[axes[2]->column],
               intensity ? v[intensity->column] : 0.0, time ? v[time->column] : 0.0);
      ++seen;
    });
    if (seen != h.points) {
      fail(file, "",
           "truncated: the header promises " + std::to_string(h.points) + " points, the file has " +
               std::to_string(seen));
    }
    PointCloud cloud = sink.take(report);
    if (report && beyond > 0)
      report->warnings.push_back(std::to_string(beyond) + " rows after the header's " +
                                 std::to_string(h.points) + " POINTS, ignored");
    return cloud;
  }
  if (h.record == 0 || h.points > std::numeric_limits<std::uint64_t>::max() / h.record)
    fail(file, "", "point size overflows");
  const std::uint64_t need = h.points * h.record;
  std::string unpacked;
  const unsigned char* records = data;
  if (h.encoding == "binary") {
    if (need > have) fail(file, at_byte(static_cast<long long>(h.data_offset)), too_short(h, need, have));
  } else {  // binary_compressed: u32 compressed size, u32 uncompressed size, LZF data, fields one after
            // another
    if (have < 8)
      fail(file, at_byte(static_cast<long long>(h.data_offset)), "truncated: no compressed-size words");
    std::uint32_t sizes[2];
    std::memcpy(sizes, data, 8);
    if (sizes[1] != need) {
      fail(file, at_byte(static_cast<long long>(h.data_offset)),
           "uncompressed size " + std::to_string(sizes[1]) + " does not match the header (" +
               std::to_string(need) + " bytes)");
    }
    if (sizes[0] > have - 8)
      fail(file, at_byte(static_cast<long long>(h.data_offset)), "truncated: compressed data cut off");
    // LZF turns at most 2 input bytes into 264 output bytes: anything more is a lying header.
    if (need > static_cast<std::uint64_t>(sizes[0]) * 132 + 32)
      fail(file, at_byte(static_cast<long long>(h.data_offset)),
           "uncompressed size impossible for the compressed size");
    unpacked.resize(need);
    auto* out = reinterpret_cast<unsigned char*>(unpacked.data());
    if (!lzf_decompress(data + 8, sizes[0], out, need))
      fail(file, at_byte(static_cast<long long>(h.data_offset) + 8), "corrupt compressed data");
    records = out;
  }
  PointSink sink(static_cast<std::size_t>(h.points), intensity != nullptr, time_type);
  const bool soa = h.encoding == "binary_compressed";  // field-major: all x, then all y, …
  const auto at = [&](const PcdField& f, std::uint64_t i) {
    return soa ? read_scalar(
                     records + f.offset * h.points + i * f.count * static_cast<std::uint64_t>(f.type.size),
                     f.type, false)
               : value_at(records + i * h.record, f);
  };
  for (std::uint64_t i = 0; i < h.points; ++i) {
    sink.add(at(*axes[0], i), at(*axes[1], i), at(*axes[2], i), intensity ? at(*intensity, i) : 0.0,
             time ? at(*time, i) : 0.0);
  }
  PointCloud cloud = sink.take(report);
  if (report && h.encoding == "binary" && have > need)
    report->warnings.push_back(std::to_string(have - need) + " bytes after the header's " +
                               std::to_string(h.points) + " POINTS (" +
                               std::to_string((have - need) / h.record) + " whole points), ignored");
  return cloud;
}

}  // namespace sextant::detail
