// Chunk decompression through libbz2, liblz4 and libzstd (decompress.hpp).
#include "decompress.hpp"

#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <limits>
#include <memory>

#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& where, const std::string& problem) {
  throw InputError(file, where, problem);
}

void check_size(std::uint64_t got, std::uint64_t expected, const char* name, const std::string& file,
                const std::string& where) {
  if (got != expected)
    fail(file, where,
         std::string(name) + " data decompress to " + std::to_string(got) + " bytes, the record says " +
             std::to_string(expected));
}

Bytes bz2(const std::uint8_t* data, std::size_t size, std::uint64_t expected, const std::string& file,
          const std::string& where) {
  Bytes out(expected);
  if (size > std::numeric_limits<unsigned>::max())
    fail(file, where, "bz2 data of " + std::to_string(size) + " bytes: larger than libbz2 reads at once");
  unsigned length = static_cast<unsigned>(expected);
  const int status = BZ2_bzBuffToBuffDecompress(reinterpret_cast<char*>(out.data()), &length,
                                                const_cast<char*>(reinterpret_cast<const char*>(data)),
                                                static_cast<unsigned>(size), 0, 0);
  if (status == BZ_OUTBUFF_FULL)
    fail(file, where,
         "bz2 data decompress to more than the " + std::to_string(expected) + " bytes the record says");
  if (status != BZ_OK) fail(file, where, "corrupt bz2 data (libbz2 status " + std::to_string(status) + ")");
  check_size(length, expected, "bz2", file, where);
  return out;
}

Bytes lz4(const std::uint8_t* data, std::size_t size, std::uint64_t expected, const std::string& file,
          const std::string& where) {
  LZ4F_dctx* raw = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION)))
    fail(file, where, "liblz4 could not make a decompression context");
  const std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> context(
      raw, &LZ4F_freeDecompressionContext);
  Bytes out(expected);
  std::size_t in_done = 0, out_done = 0, hint = 1;
  while (in_done < size) {  // frame after frame (one per chunk, as ROS 1 and MCAP write them)
    std::size_t in_size = size - in_done, out_size = out.size() - out_done;
    hint =
        LZ4F_decompress(context.get(), out.data() + out_done, &out_size, data + in_done, &in_size, nullptr);
    if (LZ4F_isError(hint)) fail(file, where, std::string("corrupt lz4 data: ") + LZ4F_getErrorName(hint));
    in_done += in_size;
    out_done += out_size;
    if (in_size == 0 && out_size == 0)
      fail(file, where,
           "lz4 data decompress to more than the " + std::to_string(expected) + " bytes the record says");
  }
  if (hint != 0) fail(file, where, "truncated lz4 data: the frame does not end");
  check_size(out_done, expected, "lz4", file, where);
  return out;
}

Bytes zstd(const std::uint8_t* data, std::size_t size, std::uint64_t expected, const std::string& file,
           const std::string& where) {
  Bytes out(expected);
  const std::size_t got = ZSTD_decompress(out.data(), out.size(), data, size);
  if (ZSTD_isError(got)) fail(file, where, std::string("corrupt zstd data: ") + ZSTD_getErrorName(got));
  check_size(got, expected, "zstd", file, where);
  return out;
}

}  // namespace

std::optional<Compression> compression_named(const std::string& name) {
  if (name.empty() || name == "none") return Compression::none;
  if (name == "bz2") return Compression::bz2;
  if (name == "lz4") return Compression::lz4;
  if (name == "zstd") return Compression::zstd;
  return std::nullopt;
}

std::string to_string(Compression c) {
  switch (c) {
    case Compression::none: return "uncompressed";
    case Compression::bz2: return "bz2";
    case Compression::lz4: return "lz4";
    case Compression::zstd: return "zstd";
  }
  return "?";
}

Bytes decompress(Compression compression, const std::uint8_t* data, std::size_t size,
                 std::uint64_t uncompressed_size, const std::string& file, const std::string& where) {
  if (uncompressed_size > kLargestUncompressed)
    fail(file, where,
         "claims " + std::to_string(uncompressed_size) +
             " bytes uncompressed, more than the 4 GiB sextant reads");
  switch (compression) {
    case Compression::none:
      check_size(size, uncompressed_size, "uncompressed", file, where);
      return Bytes(data, data + size);
    case Compression::bz2: return bz2(data, size, uncompressed_size, file, where);
    case Compression::lz4: return lz4(data, size, uncompressed_size, file, where);
    case Compression::zstd: return zstd(data, size, uncompressed_size, file, where);
  }
  fail(file, where, "unknown compression");
}

Bytes decompress_zstd_frame(const std::uint8_t* data, std::size_t size, const std::string& file,
                            const std::string& where) {
  const unsigned long long content = ZSTD_getFrameContentSize(data, size);
  if (content == ZSTD_CONTENTSIZE_ERROR) fail(file, where, "not zstd data (rosbag2 message compression)");
  if (content == ZSTD_CONTENTSIZE_UNKNOWN)
    fail(file, where, "a zstd frame that does not record its size: sextant reads rosbag2's, which do");
  return decompress(Compression::zstd, data, size, content, file, where);
}

}  // namespace sextant::recordings_detail
