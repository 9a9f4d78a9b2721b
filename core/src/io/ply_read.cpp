// PLY reader (ascii, binary_little_endian, binary_big_endian), our own rather than PCL's: PCL's
// reader allocates whatever the header's vertex count says. Every element count is checked
// against the bytes actually in the file before anything is allocated. A per-point time property
// under a driver's name (point_time.hpp) is kept.
// Layout: http://paulbourke.net/dataformats/ply/
#include <limits>
#include <string>

#include "binary_fields.hpp"
#include "formats.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/point_time.hpp"
#include "text_parse.hpp"

namespace sextant::detail {
namespace {

struct PlyProperty {
  std::string name;
  ScalarType type;
  bool is_list = false;
  ScalarType count_type;  // for lists
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::uint64_t min_bytes() const {  // a binary row: scalars plus the count of each (possibly empty) list
    std::uint64_t n = 0;
    for (const PlyProperty& p : properties)
      n += static_cast<std::uint64_t>(p.is_list ? p.count_type.size : p.type.size);
    return n;
  }
};

struct PlyHeader {
  std::string format;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;
  long data_line = 0;
};

ScalarType scalar_type(const std::filesystem::path& file, long line, std::string_view name) {
  static const struct {
    const char* name;
    ScalarType type;
  } table[] = {{"char", {'I', 1}},  {"int8", {'I', 1}},    {"uchar", {'U', 1}},  {"uint8", {'U', 1}},
               {"short", {'I', 2}}, {"int16", {'I', 2}},   {"ushort", {'U', 2}}, {"uint16", {'U', 2}},
               {"int", {'I', 4}},   {"int32", {'I', 4}},   {"uint", {'U', 4}},   {"uint32", {'U', 4}},
               {"float", {'F', 4}}, {"float32", {'F', 4}}, {"double", {'F', 8}}, {"float64", {'F', 8}}};
  for (const auto& entry : table) {
    if (name == entry.name) return entry.type;
  }
  fail(file, at_line(line), "unknown PLY property type '" + std::string(name) + "'");
}

PlyHeader parse_ply_header(const std::filesystem::path& file, const std::string& bytes) {
  if (bytes.empty()) fail(file, "", "empty file (0 bytes), not a PLY file");
  PlyHeader h;
  std::size_t start = 0;
  long line = 0;
  bool ended = false;
  while (start < bytes.size() && !ended) {
    std::size_t end = bytes.find('\n', start);
    if (end == std::string::npos) end = bytes.size();
    const std::string_view text(bytes.data() + start, end - start);
    start = end + 1;
    ++line;
    const std::vector<std::string_view> t = split_tokens(text);
    if (line == 1) {
      if (t.size() != 1 || t[0] != "ply")
        fail(file, at_line(1), "not a PLY file (the first line is not 'ply')");
      continue;
    }
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") {
      ended = true;
    } else if (t[0] == "format" && t.size() >= 2) {
      h.format = std::string(t[1]);
      if (h.format != "ascii" && h.format != "binary_little_endian" && h.format != "binary_big_endian") {
        fail(file, at_line(line), "unknown PLY format '" + h.format + "'");
      }
    } else if (t[0] == "element" && t.size() == 3) {
      h.elements.push_back(PlyElement{std::string(t[1]), parse_count(file, line, "element count", t[2]), {}});
    } else if (t[0] == "property" && !h.elements.empty() && t.size() == 3) {
      h.elements.back().properties.push_back(
          PlyProperty{std::string(t[2]), scalar_type(file, line, t[1]), false, {}});
    } else if (t[0] == "property" && !h.elements.empty() && t.size() == 5 && t[1] == "list") {
      const ScalarType count_type = scalar_type(file, line, t[2]);
      if (count_type.kind == 'F') fail(file, at_line(line), "a list count must be an integer type");
      h.elements.back().properties.push_back(
          PlyProperty{std::string(t[4]), scalar_type(file, line, t[3]), true, count_type});
    } else {
      fail(file, at_line(line), "cannot read PLY header line '" + std::string(text.substr(0, 80)) + "'");
    }
  }
  if (!ended) fail(file, "", "no 'end_header' line: not a PLY file, or its header is cut off");
  if (h.format.empty()) fail(file, "", "no 'format' line in the PLY header");
  h.data_offset = std::min(start, bytes.size());
  h.data_line = line;
  // No element may promise more rows than the bytes after the header could hold.
  const std::uint64_t have = bytes.size() - h.data_offset;
  for (const PlyElement& e : h.elements) {
    const std::uint64_t row = h.format == "ascii" ? 2 * std::max<std::size_t>(e.properties.size(), 1)
                                                  : std::max<std::uint64_t>(e.min_bytes(), 1);
    if (e.count > have / row) {
      fail(file, "",
           "the header says " + std::to_string(e.count) + " " + e.name + " rows (at least " +
               std::to_string(row) + " bytes each), but only " + std::to_string(have) +
               " bytes follow the header (truncated or lying header)");
    }
  }
  return h;
}

int property_index(const PlyElement& e, const std::string& name) {
  for (std::size_t i = 0; i < e.properties.size(); ++i) {
    if (e.properties[i].name == name && !e.properties[i].is_list) return static_cast<int>(i);
  }
  return -1;
}

/// The index of the per-point time property under any driver's name (point_time.hpp), or −1; a
/// list of that name is not a time.
int time_property(const PlyElement& e) {
  std::vector<std::string> names;
  for (const PlyProperty& p : e.properties) names.push_back(p.is_list ? std::string() : p.name);
  const auto index = find_point_time_field(names);
  return index ? static_cast<int>(*index) : -1;
}

/// Walks binary rows, bounds-checked; calls f(values) for the vertex rows (scalars only; lists skipped).
class BinaryCursor {
 public:
  BinaryCursor(const std::filesystem::path& file, const std::string& bytes, std::size_t offset, bool swap)
      : file_(file),
        data_(reinterpret_cast<const unsigned char*>(bytes.data())),
        size_(bytes.size()),
        pos_(offset),
        swap_(swap) {}

  double next(ScalarType type) {
    if (static_cast<std::size_t>(type.size) > size_ - pos_) {
      fail(file_, at_byte(static_cast<long long>(pos_)),
           "truncated: the data ends before the header's element counts");
    }
    const double v = read_scalar(data_ + pos_, type, swap_);
    pos_ += static_cast<std::size_t>(type.size);
    return v;
  }

  void row(const PlyElement& e, std::vector<double>& values) {
    values.clear();
    for (const PlyProperty& p : e.properties) {
      if (!p.is_list) {
        values.push_back(next(p.type));
        continue;
      }
      const double n = next(p.count_type);
      if (n < 0 || n > static_cast<double>(size_ - pos_))
        fail(file_, at_byte(static_cast<long long>(pos_)), "bad list length");
      const std::size_t bytes = static_cast<std::size_t>(n) * static_cast<std::size_t>(p.type.size);
      if (bytes > size_ - pos_) fail(file_, at_byte(static_cast<long long>(pos_)), "truncated list");
      pos_ += bytes;
      values.push_back(0.0);
    }
  }

 private:
  const std::filesystem::path& file_;
  const unsigned char* data_;
  std::size_t size_, pos_;
  bool swap_;
};

}  // namespace

PointCloud read_ply(const std::filesystem::path& file, ScanLoadReport* report) {
  const std::string bytes = read_file_bytes(file);
  const PlyHeader h = parse_ply_header(file, bytes);
  std::size_t vertex = h.elements.size();
  for (std::size_t i = 0; i < h.elements.size() && vertex == h.elements.size(); ++i) {
    if (h.elements[i].name == "vertex") vertex = i;
  }
  if (vertex == h.elements.size()) fail(file, "", "no 'vertex' element");
  const PlyElement& v = h.elements[vertex];
  const int axes[3] = {property_index(v, "x"), property_index(v, "y"), property_index(v, "z")};
  for (int k = 0; k < 3; ++k) {
    if (axes[k] < 0) fail(file, "", std::string("no '") + "xyz"[k] + "' vertex property");
  }
  const int intensity = property_index(v, "intensity");
  const int time = time_property(v);
  const ScalarType time_type = time >= 0 ? v.properties[static_cast<std::size_t>(time)].type : ScalarType{};
  PointSink sink(static_cast<std::size_t>(v.count), intensity >= 0, time_kind(time >= 0, time_type));
  std::vector<double> values;
  const auto add = [&] {
    sink.add(values[axes[0]], values[axes[1]], values[axes[2]], intensity >= 0 ? values[intensity] : 0.0,
             time >= 0 ? values[time] : 0.0);
  };
  if (h.format != "ascii") {
    const bool big = h.format == "binary_big_endian";
    const bool host_big = __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__;
    BinaryCursor cursor(file, bytes, h.data_offset, big != host_big);
    for (std::size_t e = 0; e <= vertex; ++e) {
      for (std::uint64_t r = 0; r < h.elements[e].count; ++r) {
        cursor.row(h.elements[e], values);
        if (e == vertex) add();
      }
    }
    return sink.take(report);
  }
  for (const PlyProperty& p : v.properties) {
    if (p.is_list) fail(file, "", "list properties in ascii vertex rows are not supported");
  }
  // ascii: one row per non-blank line, elements in header order; rows of other elements skipped.
  // Values beyond the declared properties and rows beyond the declared counts are counted.
  const std::size_t elements = h.elements.size();
  std::size_t e = 0;
  std::uint64_t r = 0;
  std::uint64_t beyond = 0, wide_rows = 0;
  std::string bad;
  const auto next_element = [&] {
    while (e < elements && r == h.elements[e].count) {
      ++e;
      r = 0;
    }
  };
  for_each_line(std::string_view(bytes).substr(h.data_offset), [&](std::string_view line, long n) {
    next_element();
    if (is_blank(line)) return;
    if (e == elements) {
      ++beyond;
      return;
    }
    ++r;
    if (e != vertex) return;
    const long number = h.data_line + n;
    if (!parse_numbers(line, values, &bad)) fail(file, at_line(number), bad_number_problem(bad));
    if (values.size() < v.properties.size()) {
      fail(file, at_line(number),
           "expected " + std::to_string(v.properties.size()) + " values, found " +
               std::to_string(values.size()));
    }
    if (values.size() > v.properties.size()) ++wide_rows;
    add();
  });
  next_element();
  if (e <= vertex) fail(file, "", "truncated: the data ends before the header's element counts");
  PointCloud cloud = sink.take(report);
  if (report && wide_rows > 0)
    report->warnings.push_back(std::to_string(wide_rows) + " vertex rows have more values than the " +
                               std::to_string(v.properties.size()) +
                               " declared properties (the rest ignored)");
  if (report && beyond > 0)
    report->warnings.push_back(std::to_string(beyond) + " rows after the header's element counts, ignored");
  return cloud;
}

}  // namespace sextant::detail
