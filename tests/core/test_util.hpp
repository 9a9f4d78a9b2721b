#pragma once
// Helpers shared by the core tests: a fresh temporary folder per test, and an expectation that
// a call throws an InputError whose message names the file, the place and the problem.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sextant/core/error.hpp"

namespace sextant::test {

/// A temporary folder removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() / ("sextant_core_" + std::string(info->test_suite_name()) +
                                                      "_" + info->name() + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
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
