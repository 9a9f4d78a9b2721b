#pragma once
// The shared MulRan Riverside02 excerpt, for the real-sequence tests (they skip when it is absent).
#include <filesystem>

namespace sextant::test {

/// ../shared/data/mulran_riverside02 beside the repository.
inline const std::filesystem::path kMulran =
    std::filesystem::path(SEXTANT_SHARED_DATA_DIR) / "mulran_riverside02";

}  // namespace sextant::test
