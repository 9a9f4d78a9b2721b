// The records of a ROS 1 bag v2.0 (rosbag1_records.hpp).
#include "rosbag1_records.hpp"

#include <cstring>

#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {
namespace {

/// A header larger than this is a broken length, not a header (message definitions live in the data).
constexpr std::uint32_t kLargestHeader = 1u << 24;

const std::string* find_field(const Rosbag1Record& r, const char* name) {
  for (const auto& [key, value] : r.fields)
    if (key == name) return &value;
  return nullptr;
}

const std::string& field_of_size(const Rosbag1Record& r, const std::string& file, const char* name,
                                 std::size_t size) {
  const std::string* value = find_field(r, name);
  if (!value)
    throw InputError(file, r.where,
                     "the record (op " + std::to_string(r.op) + ") has no '" + name + "' field");
  if (size != 0 && value->size() != size)
    throw InputError(file, r.where,
                     "field '" + std::string(name) + "' has " + std::to_string(value->size()) +
                         " bytes, expected " + std::to_string(size));
  return *value;
}

std::uint8_t op_of(const Rosbag1Record& r, const std::string& file) {
  const std::string& op = field_of_size(r, file, "op", 1);
  return static_cast<std::uint8_t>(op[0]);
}

}  // namespace

std::uint32_t Rosbag1Record::u32(const std::string& file, const char* name) const {
  return load_u32(reinterpret_cast<const std::uint8_t*>(field_of_size(*this, file, name, 4).data()));
}

std::uint64_t Rosbag1Record::u64(const std::string& file, const char* name) const {
  return load_u64(reinterpret_cast<const std::uint8_t*>(field_of_size(*this, file, name, 8).data()));
}

std::int64_t Rosbag1Record::time_ns(const std::string& file, const char* name) const {
  const auto* p = reinterpret_cast<const std::uint8_t*>(field_of_size(*this, file, name, 8).data());
  const std::uint32_t sec = load_u32(p), nsec = load_u32(p + 4);
  return static_cast<std::int64_t>(sec) * 1000000000 + static_cast<std::int64_t>(nsec);
}

const std::string& Rosbag1Record::text(const std::string& file, const char* name) const {
  return field_of_size(*this, file, name, 0);
}

bool Rosbag1Record::has(const char* name) const {
  return find_field(*this, name) != nullptr;
}

std::vector<std::pair<std::string, std::string>> parse_rosbag1_fields(ByteCursor& cursor, std::size_t size) {
  std::vector<std::pair<std::string, std::string>> fields;
  const std::size_t end = cursor.position() + size;
  while (cursor.position() < end) {
    const std::size_t start = cursor.position();
    const std::uint32_t length = cursor.u32("header field length");
    if (length > end - cursor.position())
      cursor.fail_at(start, "header field of " + std::to_string(length) + " bytes runs past its header");
    const char* p = reinterpret_cast<const char*>(cursor.take(length, "header field"));
    const char* equals = static_cast<const char*>(std::memchr(p, '=', length));
    if (!equals) cursor.fail_at(start, "header field without '=' (not a ROS 1 bag record)");
    fields.emplace_back(std::string(p, equals), std::string(equals + 1, p + length));
  }
  return fields;
}

Rosbag1Record read_rosbag1_record(const FileReader& file, std::uint64_t offset) {
  Rosbag1Record r;
  r.offset = offset;
  r.where = at_byte(static_cast<long long>(offset));
  const Bytes length = file.read(offset, 4, "record header length");
  const std::uint32_t header_size = load_u32(length.data());
  if (header_size > kLargestHeader)
    throw InputError(file.name(), r.where,
                     "record header of " + std::to_string(header_size) + " bytes: not a ROS 1 bag record");
  const Bytes header = file.read(offset + 4, std::uint64_t{header_size} + 4, "record header");
  ByteCursor cursor(header, Place{file.name(), offset + 4, "", ""});
  r.fields = parse_rosbag1_fields(cursor, header_size);
  r.data_size = cursor.u32("record data length");
  r.data_offset = offset + 8 + header_size;
  if (r.data_size > file.size() - r.data_offset)
    throw InputError(file.name(), r.where,
                     "truncated record: its data of " + std::to_string(r.data_size) +
                         " bytes runs past the end of the file (" + std::to_string(file.size()) + " bytes)");
  r.op = op_of(r, file.name());
  return r;
}

Rosbag1Record read_rosbag1_record(ByteCursor& cursor) {
  Rosbag1Record r;
  r.offset = cursor.position();
  r.where = cursor.where();
  const std::uint32_t header_size = cursor.u32("record header length");
  if (header_size > cursor.remaining())
    cursor.fail_at(r.offset, "truncated record: a header of " + std::to_string(header_size) + " bytes, " +
                                 std::to_string(cursor.remaining()) + " left");
  r.fields = parse_rosbag1_fields(cursor, header_size);
  r.data_size = cursor.u32("record data length");
  r.data_offset = cursor.position();
  if (r.data_size > cursor.remaining())
    cursor.fail_at(r.offset, "truncated record: data of " + std::to_string(r.data_size) + " bytes, " +
                                 std::to_string(cursor.remaining()) + " left");
  cursor.skip(r.data_size, "record data");
  r.op = op_of(r, cursor.place().file);
  return r;
}

Rosbag1Connection parse_rosbag1_connection(const Rosbag1Record& record, const Bytes& data,
                                           const Place& place) {
  Rosbag1Connection c;
  c.id = record.u32(place.file, "conn");
  c.topic = record.text(place.file, "topic");
  ByteCursor cursor(data, place);
  Rosbag1Record inner;
  inner.where = record.where;
  inner.fields = parse_rosbag1_fields(cursor, data.size());
  c.type = inner.text(place.file, "type");
  return c;
}

}  // namespace sextant::recordings_detail
