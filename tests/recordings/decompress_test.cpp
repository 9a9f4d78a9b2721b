// The chunk decompressions (libbz2, liblz4 frames, libzstd): data that expand a thousandfold come back
// whole, and a record whose size lies (too small, too large: a broken field must not make us allocate
// gigabytes) or whose data are cut is an InputError naming the chunk.
#include <gtest/gtest.h>

#include <string>

#include "decompress.hpp"
#include "recording_message.hpp"
#include "sextant/core/error.hpp"

namespace sextant {
namespace {

using namespace recordings_detail;

test::Bytes compressible(std::size_t n) {
  test::Bytes data(n, 0);
  for (std::size_t i = 0; i < n; i += 4096) data[i] = static_cast<std::uint8_t>(i / 4096);  // mostly zeros
  return data;
}

std::string problem(Compression c, const test::Bytes& packed, std::uint64_t claimed) {
  try {
    decompress(c, packed.data(), packed.size(), claimed, "a.bag", "the chunk at byte 9");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "a.bag");
    EXPECT_EQ(e.where(), "the chunk at byte 9");
    return e.problem();
  }
  ADD_FAILURE() << "decompressed";
  return "";
}

TEST(Decompress, EveryCodecRoundTripsAndRefusesLyingSizes) {
  const test::Bytes data = compressible(8 << 20);  // 8 MiB, as an Ouster chunk
  for (const auto& [name, codec] : {std::pair{"bz2", Compression::bz2}, std::pair{"lz4", Compression::lz4},
                                    std::pair{"zstd", Compression::zstd}}) {
    const test::Bytes packed = test::compress(name, data);
    ASSERT_LT(packed.size() * 100, data.size()) << name;  // the buffer must grow many times
    EXPECT_EQ(decompress(codec, packed.data(), packed.size(), data.size(), "a.bag", "x"), data) << name;
    EXPECT_NE(
        problem(codec, packed, data.size() - 1).find("decompress to 8388608 bytes, the record says 8388607"),
        std::string::npos)
        << name;
    EXPECT_NE(problem(codec, packed, data.size() - 2).find("decompress to more than the 8388606 bytes"),
              std::string::npos)
        << name;
    // A size field of 3 GiB over 8 MiB of data: refused after decompressing what is there, not allocated.
    EXPECT_NE(problem(codec, packed, std::uint64_t{3} << 30)
                  .find("decompress to 8388608 bytes, the record says 3221225472"),
              std::string::npos)
        << name;
    const test::Bytes cut(packed.begin(), packed.begin() + static_cast<std::ptrdiff_t>(packed.size() / 2));
    EXPECT_FALSE(problem(codec, cut, data.size()).empty()) << name;
  }
  EXPECT_NE(problem(Compression::zstd, compressible(10), std::uint64_t{5} << 32).find("more than the 4 GiB"),
            std::string::npos);
}

}  // namespace
}  // namespace sextant
