// Test-only compression (recording_message.hpp).
#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <stdexcept>

#include "recording_message.hpp"

namespace sextant::test {

Bytes compress(const std::string& compression, const Bytes& data) {
  if (compression.empty() || compression == "none") return data;
  if (compression == "bz2") {
    Bytes out(data.size() + data.size() / 100 + 600);
    unsigned length = static_cast<unsigned>(out.size());
    if (BZ2_bzBuffToBuffCompress(reinterpret_cast<char*>(out.data()), &length,
                                 const_cast<char*>(reinterpret_cast<const char*>(data.data())),
                                 static_cast<unsigned>(data.size()), 9, 0, 0) != BZ_OK)
      throw std::runtime_error("bz2");
    out.resize(length);
    return out;
  }
  if (compression == "lz4") {
    Bytes out(LZ4F_compressFrameBound(data.size(), nullptr));
    const std::size_t n = LZ4F_compressFrame(out.data(), out.size(), data.data(), data.size(), nullptr);
    if (LZ4F_isError(n)) throw std::runtime_error("lz4");
    out.resize(n);
    return out;
  }
  if (compression == "zstd") {
    Bytes out(ZSTD_compressBound(data.size()));
    const std::size_t n = ZSTD_compress(out.data(), out.size(), data.data(), data.size(), 3);
    if (ZSTD_isError(n)) throw std::runtime_error("zstd");
    out.resize(n);
    return out;
  }
  return data;  // a name no reader knows: the bytes as they are, for the reader to refuse the name
}

}  // namespace sextant::test
