#pragma once
// Temporary folders and files for the experiments tests.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace sextant::test {

/// A fresh folder under the system temp dir, removed at the end of the test.
class TempFolder {
 public:
  TempFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() / ("sextant-exp-" + std::string(info->test_suite_name()) +
                                                      "-" + info->name() + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// A selftest experiment with `points` sweep values × 2 methods × `reps` repetitions.
inline std::string selftest_yaml(const std::string& name, int points, int reps, int sleep_ms) {
  return "name: " + name + "\nkind: selftest\nrepetitions: " + std::to_string(reps) +
         "\nseed: 7\nmethods:\n  - name: a\n  - name: b\nsweep:\n  x: {from: 1, to: " +
         std::to_string(points) + "}\nparams:\n  sleep_ms: " + std::to_string(sleep_ms) + "\n";
}

}  // namespace sextant::test
