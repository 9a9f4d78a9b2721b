// Test-only PointCloud2 messages (cloud_writer.hpp).
#include "cloud_writer.hpp"

#include <cstring>
#include <stdexcept>

namespace sextant::test {
namespace {

std::size_t size_of(std::uint8_t datatype) {
  static const std::size_t sizes[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
  if (datatype < 1 || datatype > 8) throw std::invalid_argument("datatype");
  return sizes[datatype];
}

void put_value(ByteWriter& w, std::uint8_t datatype, double v) {
  switch (datatype) {
    case 1: w.u8(static_cast<std::uint8_t>(static_cast<std::int8_t>(v))); break;
    case 2: w.u8(static_cast<std::uint8_t>(v)); break;
    case 3: w.u16(static_cast<std::uint16_t>(static_cast<std::int16_t>(v))); break;
    case 4: w.u16(static_cast<std::uint16_t>(v)); break;
    case 5: w.u32(static_cast<std::uint32_t>(static_cast<std::int32_t>(v))); break;
    case 6: w.u32(static_cast<std::uint32_t>(v)); break;
    case 7: {
      const float f = static_cast<float>(v);
      std::uint32_t bits;
      std::memcpy(&bits, &f, 4);
      w.u32(bits);
      break;
    }
    default: {
      std::uint64_t bits;
      std::memcpy(&bits, &v, 8);
      w.u64(bits);
    }
  }
}

void serialize(ByteWriter& w, const TestCloud& c, bool ros1) {
  if (ros1) w.u32(0);  // seq
  w.u32(static_cast<std::uint32_t>(c.sec));
  w.u32(c.nsec);
  w.string(c.frame_id);
  w.u32(c.height);
  w.u32(c.width);
  w.u32(static_cast<std::uint32_t>(c.fields.size()));
  for (std::size_t k = 0; k < c.fields.size(); ++k) {
    w.string(c.fields[k].name);
    w.u32(c.offsets[k]);
    w.u8(c.fields[k].datatype);
    w.u32(1);
  }
  w.u8(c.is_bigendian ? 1 : 0);
  w.u32(c.point_step);
  w.u32(c.row_step);
  w.u32(static_cast<std::uint32_t>(c.data.size()));
  w.raw(c.data);
  w.u8(c.is_dense ? 1 : 0);
}

}  // namespace

TestCloud make_test_cloud(const std::vector<TestField>& fields,
                          const std::vector<std::vector<double>>& values, std::uint32_t height,
                          bool big_endian, std::uint32_t point_padding, std::uint32_t row_padding) {
  TestCloud c;
  c.fields = fields;
  c.is_bigendian = big_endian;
  c.height = height;
  c.width = height == 0 ? 0 : static_cast<std::uint32_t>(values.size() / height);
  if (static_cast<std::size_t>(c.width) * height != values.size()) throw std::invalid_argument("rows");
  std::uint32_t offset = 0;
  for (const TestField& f : fields) {
    c.offsets.push_back(offset);
    offset += static_cast<std::uint32_t>(size_of(f.datatype));
  }
  c.point_step = offset + point_padding;
  c.row_step = c.point_step * c.width + row_padding;
  ByteWriter w(big_endian);
  for (std::uint32_t row = 0; row < height; ++row) {
    for (std::uint32_t col = 0; col < c.width; ++col) {
      const std::vector<double>& point = values[static_cast<std::size_t>(row) * c.width + col];
      for (std::size_t k = 0; k < fields.size(); ++k) put_value(w, fields[k].datatype, point.at(k));
      for (std::uint32_t p = 0; p < point_padding; ++p) w.u8(0xAB);
    }
    for (std::uint32_t p = 0; p < row_padding; ++p) w.u8(0xCD);
  }
  c.data = std::move(w.bytes());
  return c;
}

Bytes serialize_ros1(const TestCloud& cloud) {
  ByteWriter w;
  serialize(w, cloud, true);
  return std::move(w.bytes());
}

Bytes serialize_cdr(const TestCloud& cloud, bool big_endian) {
  ByteWriter w(big_endian, true, 4);
  w.u8(0);
  w.u8(big_endian ? 0 : 1);
  w.u8(0);
  w.u8(0);
  serialize(w, cloud, false);
  return std::move(w.bytes());
}

std::vector<TestField> xyz_intensity_t_fields() {
  return {{"x", 7}, {"y", 7}, {"z", 7}, {"intensity", 7}, {"t", 6}};
}

}  // namespace sextant::test
