// Chunk decompression through libbz2, liblz4 and libzstd (decompress.hpp). Each streams into a buffer
// that grows as the data expand, up to the size the record claims: a lying size field cannot make us
// allocate more than twice what the data really hold.
#include "decompress.hpp"

#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <limits>
#include <memory>

#include "sextant/core/error.hpp"

namespace sextant::recordings_detail {
namespace {

[[noreturn]] void fail(const std::string& file, const std::string& where, const std::string& problem) {
  throw InputError(file, where, problem);
}

/// The output buffer: starts at what the input could plausibly expand to, grows (doubling) up to one byte
/// more than the size claimed (room for a decompressor to see that its data end there); `room()` is where
/// the next bytes go.
class Output {
 public:
  Output(std::size_t input_size, std::uint64_t expected) : limit_(expected + 1) {
    bytes_.resize(
        static_cast<std::size_t>(std::min<std::uint64_t>(limit_, 16 * std::uint64_t{input_size} + 4096)));
  }
  std::uint8_t* room() { return bytes_.data() + done_; }
  std::size_t room_size() const { return bytes_.size() - done_; }
  void wrote(std::size_t n) { done_ += n; }
  std::size_t done() const { return done_; }
  /// Makes room when full; false when the limit is reached (the data expand beyond the claim).
  bool grow() {
    if (room_size() > 0) return true;
    if (bytes_.size() >= limit_) return false;
    bytes_.resize(
        static_cast<std::size_t>(std::min<std::uint64_t>(limit_, 2 * std::uint64_t{bytes_.size()} + 1)));
    return true;
  }
  Bytes take() {
    bytes_.resize(done_);
    return std::move(bytes_);
  }

 private:
  std::uint64_t limit_;
  Bytes bytes_;
  std::size_t done_ = 0;
};

void check_size(std::uint64_t got, std::uint64_t expected, const char* name, const std::string& file,
                const std::string& where) {
  if (got != expected)
    fail(file, where,
         std::string(name) + " data decompress to " + std::to_string(got) + " bytes, the record says " +
             std::to_string(expected));
}

[[noreturn]] void too_large(const char* name, std::uint64_t expected, const std::string& file,
                            const std::string& where) {
  fail(file, where,
       std::string(name) + " data decompress to more than the " + std::to_string(expected) +
           " bytes the record says");
}

Bytes bz2(const std::uint8_t* data, std::size_t size, std::uint64_t expected, const std::string& file,
          const std::string& where) {
  bz_stream stream{};
  if (BZ2_bzDecompressInit(&stream, 0, 0) != BZ_OK) fail(file, where, "libbz2 could not start decompressing");
  const std::unique_ptr<bz_stream, int (*)(bz_stream*)> end(&stream, &BZ2_bzDecompressEnd);
  Output out(size, expected);
  std::size_t in_done = 0;
  for (;;) {
    if (!out.grow()) too_large("bz2", expected, file, where);
    const unsigned in_size = static_cast<unsigned>(std::min<std::size_t>(size - in_done, 1u << 30));
    const unsigned out_size = static_cast<unsigned>(std::min<std::size_t>(out.room_size(), 1u << 30));
    stream.next_in = const_cast<char*>(reinterpret_cast<const char*>(data + in_done));
    stream.avail_in = in_size;
    stream.next_out = reinterpret_cast<char*>(out.room());
    stream.avail_out = out_size;
    const int status = BZ2_bzDecompress(&stream);
    in_done += in_size - stream.avail_in;
    out.wrote(out_size - stream.avail_out);
    if (status == BZ_STREAM_END) break;
    if (status != BZ_OK) fail(file, where, "corrupt bz2 data (libbz2 status " + std::to_string(status) + ")");
    if (in_done == size && stream.avail_out > 0)
      fail(file, where, "truncated bz2 data: the stream does not end");
  }
  check_size(out.done(), expected, "bz2", file, where);
  return out.take();
}

Bytes lz4(const std::uint8_t* data, std::size_t size, std::uint64_t expected, const std::string& file,
          const std::string& where) {
  LZ4F_dctx* raw = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION)))
    fail(file, where, "liblz4 could not make a decompression context");
  const std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> context(
      raw, &LZ4F_freeDecompressionContext);
  Output out(size, expected);
  std::size_t in_done = 0;
  for (;;) {  // frame after frame (one per chunk, as ROS 1 and MCAP write them)
    if (!out.grow()) too_large("lz4", expected, file, where);
    std::size_t in_size = size - in_done, out_size = out.room_size();
    const std::size_t room = out_size;
    const std::size_t hint =
        LZ4F_decompress(context.get(), out.room(), &out_size, data + in_done, &in_size, nullptr);
    if (LZ4F_isError(hint)) fail(file, where, std::string("corrupt lz4 data: ") + LZ4F_getErrorName(hint));
    in_done += in_size;
    out.wrote(out_size);
    if (hint == 0 && in_done == size) break;
    if (in_done == size && out_size < room) fail(file, where, "truncated lz4 data: the frame does not end");
  }
  check_size(out.done(), expected, "lz4", file, where);
  return out.take();
}

Bytes zstd(const std::uint8_t* data, std::size_t size, std::uint64_t expected, const std::string& file,
           const std::string& where) {
  const std::unique_ptr<ZSTD_DStream, decltype(&ZSTD_freeDStream)> stream(ZSTD_createDStream(),
                                                                          &ZSTD_freeDStream);
  if (!stream) fail(file, where, "libzstd could not make a decompression stream");
  Output out(size, expected);
  ZSTD_inBuffer in{data, size, 0};
  for (;;) {  // frame after frame
    if (!out.grow()) too_large("zstd", expected, file, where);
    ZSTD_outBuffer o{out.room(), out.room_size(), 0};
    const std::size_t hint = ZSTD_decompressStream(stream.get(), &o, &in);
    if (ZSTD_isError(hint)) fail(file, where, std::string("corrupt zstd data: ") + ZSTD_getErrorName(hint));
    out.wrote(o.pos);
    if (hint == 0 && in.pos == in.size) break;
    if (in.pos == in.size && o.pos < o.size) fail(file, where, "truncated zstd data: the frame does not end");
  }
  check_size(out.done(), expected, "zstd", file, where);
  return out.take();
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
