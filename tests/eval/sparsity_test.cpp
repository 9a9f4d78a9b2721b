#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "sextant/eval/sparsity.hpp"
#include "xml_check.hpp"

namespace sextant {
namespace {

std::uint32_t be32(const std::string& s, std::size_t at) {
  return (std::uint32_t(static_cast<unsigned char>(s[at])) << 24) |
         (std::uint32_t(static_cast<unsigned char>(s[at + 1])) << 16) |
         (std::uint32_t(static_cast<unsigned char>(s[at + 2])) << 8) |
         std::uint32_t(static_cast<unsigned char>(s[at + 3]));
}

struct DecodedPng {
  std::uint32_t width = 0, height = 0;
  std::string raw;  ///< inflated scanlines
};

/// Walks the chunks, checks every CRC, and inflates the (stored-block) zlib stream.
DecodedPng decode_png(const std::string& png) {
  DecodedPng out;
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  std::string idat;
  std::vector<std::string> types;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t len = be32(png, at);
    const std::string type = png.substr(at + 4, 4);
    const std::string body = png.substr(at + 4, 4 + len);
    EXPECT_EQ(be32(png, at + 8 + len),
              crc32(reinterpret_cast<const unsigned char*>(body.data()), body.size()))
        << type;
    if (type == "IHDR") {
      out.width = be32(png, at + 8);
      out.height = be32(png, at + 12);
      EXPECT_EQ(png[at + 16], 8);  // bit depth
      EXPECT_EQ(png[at + 17], 0);  // grayscale
    }
    if (type == "IDAT") idat += png.substr(at + 8, len);
    types.push_back(type);
    at += 12 + len;
  }
  EXPECT_EQ(types.front(), "IHDR");
  EXPECT_EQ(types.back(), "IEND");
  // zlib: header, stored blocks, Adler-32.
  EXPECT_EQ((static_cast<unsigned char>(idat[0]) * 256 + static_cast<unsigned char>(idat[1])) % 31, 0);
  std::size_t at = 2;
  bool last = false;
  while (!last && at + 5 <= idat.size()) {
    last = idat[at] & 1;
    EXPECT_EQ((idat[at] >> 1) & 3, 0);  // stored
    const std::size_t len =
        static_cast<unsigned char>(idat[at + 1]) | (static_cast<unsigned char>(idat[at + 2]) << 8);
    const std::size_t nlen =
        static_cast<unsigned char>(idat[at + 3]) | (static_cast<unsigned char>(idat[at + 4]) << 8);
    EXPECT_EQ(len ^ 0xFFFF, nlen);
    out.raw += idat.substr(at + 5, len);
    at += 5 + len;
  }
  EXPECT_TRUE(last);
  EXPECT_EQ(be32(idat, at), adler32(reinterpret_cast<const unsigned char*>(out.raw.data()), out.raw.size()));
  EXPECT_EQ(at + 4, idat.size());
  return out;
}

TEST(Checksums, KnownValues) {
  const std::string s = "123456789";
  EXPECT_EQ(crc32(reinterpret_cast<const unsigned char*>(s.data()), s.size()), 0xCBF43926UL);
  const std::string w = "Wikipedia";
  EXPECT_EQ(adler32(reinterpret_cast<const unsigned char*>(w.data()), w.size()), 0x11E60398UL);
}

TEST(Sparsity, DenseGridFractions) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(4, 4);
  m(0, 0) = 1;
  m(1, 1) = 2;
  m(0, 3) = 1e-9;  // below the threshold
  m(3, 2) = -3;
  const SparsityGrid g = sparsity_grid(m, 1e-6, 2);
  ASSERT_EQ(g.grid_rows, 2u);
  ASSERT_EQ(g.grid_cols, 2u);
  EXPECT_EQ(g.nonzeros, 3u);
  EXPECT_DOUBLE_EQ(g.at(0, 0), 0.5);
  EXPECT_DOUBLE_EQ(g.at(0, 1), 0.0);
  EXPECT_DOUBLE_EQ(g.at(1, 0), 0.0);
  EXPECT_DOUBLE_EQ(g.at(1, 1), 0.25);
  const SparsityGrid empty = sparsity_grid(Eigen::MatrixXd(), 0.0, 10);
  EXPECT_EQ(empty.grid_rows, 0u);
  EXPECT_TRUE(sextant::testing::check_xml(render_sparsity_svg(empty, "empty")).ok);
}

TEST(Sparsity, LargeMatrixFromEntriesDownsamples) {
  // A 3000 × 3000 banded information matrix with a dense pose block.
  std::vector<std::pair<std::size_t, std::size_t>> entries;
  for (std::size_t i = 0; i < 3000; ++i)
    for (std::size_t j = (i < 2 ? 0 : i - 2); j < std::min<std::size_t>(3000, i + 3); ++j)
      entries.emplace_back(i, j);
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 3000; j += 7) entries.emplace_back(i, j);
  entries.emplace_back(5000, 1);  // out of range: ignored
  const SparsityGrid g = sparsity_grid(3000, 3000, entries, 300);
  EXPECT_EQ(g.grid_rows, 300u);
  EXPECT_GT(g.at(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(g.at(150, 10), 0.0);
  EXPECT_GT(g.at(150, 150), 0.0);
  const std::string svg = render_sparsity_svg(g, "SEIF information matrix");
  const auto xml = sextant::testing::check_xml(svg);
  ASSERT_TRUE(xml.ok) << xml.error;
  EXPECT_LT(svg.size(), 2'000'000u);

  const GrayImage img = sparsity_image(g, 2);
  EXPECT_EQ(img.width, 600u);
  const DecodedPng png = decode_png(encode_png(img));  // 600·601 bytes: several stored blocks
  EXPECT_EQ(png.width, 600u);
  EXPECT_EQ(png.height, 600u);
  ASSERT_EQ(png.raw.size(), 600u * 601u);
  for (std::size_t y = 0; y < 600; ++y) {
    ASSERT_EQ(png.raw[y * 601], 0);  // filter type none
    for (std::size_t x = 0; x < 600; x += 37)
      ASSERT_EQ(static_cast<unsigned char>(png.raw[y * 601 + 1 + x]), img.pixels[y * 600 + x]);
  }
}

TEST(Png, SmallImageAndEmptyImage) {
  GrayImage img;
  img.width = 3;
  img.height = 2;
  img.pixels = {0, 128, 255, 10, 20, 30};
  const DecodedPng png = decode_png(encode_png(img));
  EXPECT_EQ(png.width, 3u);
  EXPECT_EQ(png.height, 2u);
  EXPECT_EQ(png.raw, std::string("\0\0\x80\xff\0\x0a\x14\x1e", 8));
  const DecodedPng one = decode_png(encode_png(GrayImage{}));
  EXPECT_EQ(one.width, 1u);
}

}  // namespace
}  // namespace sextant
