#pragma once
// Private helper of the eval module: what the offline 3D pages (cloud_view, run_view) write into their
// HTML, once for both: float32 coordinates as base64, JSON strings that are safe inside <script>,
// Debian's three.js files read for inlining, and the box their cameras frame.
#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace sextant::detail {

/// RFC 4648 base64 (with '=' padding).
std::string base64(const std::vector<unsigned char>& bytes);
/// The points' coordinates as little-endian float32 x, y, z, in order.
std::vector<unsigned char> float32_bytes(const std::vector<Eigen::Vector3f>& points);
/// A JSON string that is also safe inside <script>: '<', '>' and '&' as \u escapes.
std::string script_json_string(const std::string& s);
/// ASCII lower case.
std::string lower_ascii(std::string s);
/// "123 456" (thin-space groups of three digits).
std::string grouped(std::size_t n);
/// A script file's text for inlining into a page; InputError naming the file when it cannot be read
/// or holds "</script" (which would end the page's <script> element).
std::string read_inline_script(const std::filesystem::path& path);

/// The 2 % and 98 % quantiles of each axis' values (a few far returns left out); reorders them. Each
/// axis must hold at least one value.
std::pair<Eigen::Vector3d, Eigen::Vector3d> central_box(std::array<std::vector<double>, 3>& axes);

}  // namespace sextant::detail
