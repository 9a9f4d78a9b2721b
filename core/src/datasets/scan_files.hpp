#pragma once
// Private: finds numbered scan files (scan000.3d, 000000.bin) in a folder, sorted by number.
#include <filesystem>
#include <string>
#include <vector>

namespace sextant::detail {

struct NumberedFile {
  long number = 0;
  std::filesystem::path path;
};

/// Files named <prefix><digits><suffix> (e.g. "scan" + "000" + ".3d"), sorted by number.
std::vector<NumberedFile> numbered_files(const std::filesystem::path& folder, const std::string& prefix,
                                         const std::string& suffix);

/// The folder's own name, also for "a/b/" and "." paths.
std::string folder_name(const std::filesystem::path& folder);

}  // namespace sextant::detail
