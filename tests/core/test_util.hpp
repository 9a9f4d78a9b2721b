#pragma once
// Helpers shared by the core tests (plus sextant_test/temp_dir.hpp): 3DTK's pose formula, and an expectation
// that a call throws an InputError whose message names the file, the place and the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <Eigen/Core>

#include "sextant/core/error.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant::test {

/// 3DTK's EulerToMatrix4 (column-major, as quoted in data/README.md), transcribed from its formula:
/// the independent reference for eq. (3.8) and the uos pose conversion.
inline Eigen::Matrix4d threedtk_euler_to_matrix4(const Eigen::Vector3d& t, const Eigen::Vector3d& r) {
  const double sx = std::sin(r[0]), cx = std::cos(r[0]);
  const double sy = std::sin(r[1]), cy = std::cos(r[1]);
  const double sz = std::sin(r[2]), cz = std::cos(r[2]);
  const double m[16] = {cy * cz,
                        sx * sy * cz + cx * sz,
                        -cx * sy * cz + sx * sz,
                        0,
                        -cy * sz,
                        -sx * sy * sz + cx * cz,
                        cx * sy * sz + sx * cz,
                        0,
                        sy,
                        -sx * cy,
                        cx * cy,
                        0,
                        t.x(),
                        t.y(),
                        t.z(),
                        1};
  return Eigen::Map<const Eigen::Matrix4d>(m);  // Eigen's default storage is column-major
}

inline std::filesystem::path data_dir() {
  return SEXTANT_DATA_DIR;
}

/// Runs f and checks it throws InputError naming `file`, with `where` (e.g. "line 3") and a
/// problem containing `problem_part`.
template <class F>
void expect_input_error(F&& f, const std::filesystem::path& file, const std::string& where,
                        const std::string& problem_part) {
  try {
    f();
    ADD_FAILURE() << "expected an InputError for " << file;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string()) << e.what();
    EXPECT_EQ(e.where(), where) << e.what();
    EXPECT_NE(e.problem().find(problem_part), std::string::npos) << e.what();
  }
}

}  // namespace sextant::test
