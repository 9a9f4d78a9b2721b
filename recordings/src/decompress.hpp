#pragma once
// Private: the chunk compressions of bags and MCAP files, through Debian's libraries: bz2 (libbz2),
// lz4 (liblz4's frame format, which ROS 1's lz4 chunks use too) and zstd (libzstd).
#include <cstdint>
#include <optional>
#include <string>

#include "byte_cursor.hpp"

namespace sextant::recordings_detail {

enum class Compression { none, bz2, lz4, zstd };

/// "none" or "" (uncompressed), "bz2", "lz4", "zstd"; nullopt for any other name.
std::optional<Compression> compression_named(const std::string& name);
std::string to_string(Compression c);

/// The largest chunk or message we decompress [bytes]: a size field beyond it is a broken file, not a
/// reason to allocate.
inline constexpr std::uint64_t kLargestUncompressed = std::uint64_t{1} << 32;

/// `size` bytes of `data` decompressed into exactly `uncompressed_size` bytes. InputError(file, `where`)
/// when the data do not decompress (corrupt) or decompress to another size.
Bytes decompress(Compression compression, const std::uint8_t* data, std::size_t size,
                 std::uint64_t uncompressed_size, const std::string& file, const std::string& where);

/// A zstd frame whose size it records (rosbag2's per-message compression).
Bytes decompress_zstd_frame(const std::uint8_t* data, std::size_t size, const std::string& file,
                            const std::string& where);

}  // namespace sextant::recordings_detail
