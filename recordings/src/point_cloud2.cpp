// sensor_msgs/PointCloud2 from its ROS 1 or CDR serialization (point_cloud2.hpp).
#include "point_cloud2.hpp"

#include <algorithm>
#include <cstdio>

#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {
namespace {

/// How the message's own fields are laid out.
struct Layout {
  bool cdr = false;         ///< align values, strings end with NUL
  bool big_endian = false;  ///< of the message's fields (not of the point data: is_bigendian)
};

/// The encapsulation header of a CDR payload: the layout, and the cursor past the header.
Layout cdr_header(const Bytes& payload, const Place& place) {
  if (payload.size() < 4)
    throw InputError(
        place.file, place.at(0),
        "a CDR message of " + std::to_string(payload.size()) + " bytes, shorter than its 4-byte header");
  const unsigned id = static_cast<unsigned>(payload[0]) << 8 | payload[1];
  switch (id) {
    case 0x0000:
    case 0x0006:
    case 0x0010: return {true, true};
    case 0x0001:
    case 0x0007:
    case 0x0011: return {true, false};
    default: {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%04x", id);
      throw InputError(
          place.file, place.at(0),
          std::string("CDR representation ") + hex +
              " is not read: sextant reads plain CDR (0x0000, 0x0001) and plain XCDR2 (0x0006, 0x0007)");
    }
  }
}

ByteCursor message_cursor(const Bytes& payload, MessageEncoding encoding, const Place& place,
                          Layout* layout) {
  if (encoding == MessageEncoding::cdr) {
    *layout = cdr_header(payload, place);
    Place after = place;
    after.base += 4;
    return ByteCursor(payload.data() + 4, payload.size() - 4, after, layout->big_endian);
  }
  if (encoding != MessageEncoding::ros1)
    throw InputError(place.file, place.at(0), "a message encoding other than ROS 1 or CDR is not read");
  *layout = Layout{};
  return ByteCursor(payload, place);
}

std::uint32_t u32(ByteCursor& c, const Layout& l, const char* what) {
  if (l.cdr) c.align(4, what);
  return c.u32(what);
}

std::string string_of(ByteCursor& c, const Layout& l, const char* what) {
  if (!l.cdr) return c.string32(what);
  c.align(4, what);
  std::string s = c.string32(what);
  if (!s.empty() && s.back() == '\0') s.pop_back();  // CDR counts the NUL
  return s;
}

double stamp_of(ByteCursor& c, const Layout& l) {
  if (!l.cdr) c.skip(4, "header seq");
  const std::uint32_t sec = u32(c, l, "header stamp");
  const std::uint32_t nsec = u32(c, l, "header stamp");
  const double seconds =
      l.cdr ? static_cast<double>(static_cast<std::int32_t>(sec)) : static_cast<double>(sec);
  return seconds + 1e-9 * nsec;
}

void check_fields(const PointCloud2Message& m, ByteCursor& c, std::size_t at) {
  for (const PointField2& f : m.fields) {
    const std::size_t size = datatype_size(f.datatype);
    if (size == 0)
      c.fail_at(at, "field '" + f.name + "' has unknown " + datatype_name(f.datatype) + " (1–8 are known)");
    if (std::uint64_t{f.offset} + size * std::max<std::uint32_t>(f.count, 1) > m.point_step)
      c.fail_at(at, "field '" + f.name + "' (" + datatype_name(f.datatype) + " at " +
                        std::to_string(f.offset) + ") lies outside point_step " +
                        std::to_string(m.point_step));
  }
  const std::uint64_t points = std::uint64_t{m.height} * m.width;
  if (points > 0 && std::uint64_t{m.width} * m.point_step > m.row_step)
    c.fail_at(at, "row_step " + std::to_string(m.row_step) + " is shorter than width × point_step (" +
                      std::to_string(m.width) + " × " + std::to_string(m.point_step) + ")");
  if (std::uint64_t{m.height} * m.row_step > m.data_size && points > 0)
    c.fail_at(at, "the point data hold " + std::to_string(m.data_size) + " bytes, height × row_step is " +
                      std::to_string(std::uint64_t{m.height} * m.row_step));
}

}  // namespace

std::string datatype_name(std::uint8_t datatype) {
  static const char* const names[] = {"",      "int8",   "uint8",   "int16",  "uint16",
                                      "int32", "uint32", "float32", "float64"};
  if (datatype >= 1 && datatype <= 8) return names[datatype];
  return "datatype " + std::to_string(datatype);
}

std::size_t datatype_size(std::uint8_t datatype) {
  static const std::size_t sizes[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
  return datatype <= 8 ? sizes[datatype] : 0;
}

PointCloud2Message parse_point_cloud2(const Bytes& payload, MessageEncoding encoding, const Place& place) {
  Layout l;
  ByteCursor c = message_cursor(payload, encoding, place, &l);
  PointCloud2Message m;
  m.stamp = stamp_of(c, l);
  m.frame_id = string_of(c, l, "header frame_id");
  m.height = u32(c, l, "height");
  m.width = u32(c, l, "width");
  const std::size_t fields_at = c.position();
  const std::uint32_t fields = u32(c, l, "fields length");
  if (fields > c.remaining() / 9)  // a field takes 9 bytes or more
    c.fail_at(fields_at, std::to_string(fields) + " point fields cannot fit in the " +
                             std::to_string(c.remaining()) + " bytes left");
  for (std::uint32_t k = 0; k < fields; ++k) {
    PointField2 f;
    f.name = string_of(c, l, "field name");
    f.offset = u32(c, l, "field offset");
    f.datatype = c.u8("field datatype");
    f.count = u32(c, l, "field count");
    m.fields.push_back(std::move(f));
  }
  m.is_bigendian = c.u8("is_bigendian") != 0;
  m.point_step = u32(c, l, "point_step");
  m.row_step = u32(c, l, "row_step");
  const std::size_t data_at = c.position();
  m.data_size = u32(c, l, "data length");
  if (m.data_size > c.remaining())
    c.fail_at(data_at, "the point data claim " + std::to_string(m.data_size) + " bytes, " +
                           std::to_string(c.remaining()) + " follow");
  m.data_offset = (l.cdr ? 4 : 0) + c.position();
  c.skip(m.data_size, "point data");
  if (!c.at_end()) m.is_dense = c.u8("is_dense") != 0;
  check_fields(m, c, fields_at);
  return m;
}

double point_cloud2_stamp(const Bytes& payload_prefix, MessageEncoding encoding, const Place& place) {
  Layout l;
  ByteCursor c = message_cursor(payload_prefix, encoding, place, &l);
  return stamp_of(c, l);
}

}  // namespace sextant::recordings_detail
