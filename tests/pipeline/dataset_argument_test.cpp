// The dataset a user names (pipeline/dataset_argument.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sextant/core/error.hpp"
#include "sextant/pipeline/dataset_argument.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

std::string problem_of(const std::string& name, const std::optional<std::string>& poses, Face face) {
  try {
    open_dataset_argument(name, poses, 1, face);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(DatasetArgument, TheCampusByNameBringsItsOwnGroundTruth) {
  EXPECT_TRUE(names_builtin_campus("campus"));
  EXPECT_TRUE(names_builtin_campus("synthetic"));
  EXPECT_FALSE(names_builtin_campus("campus/"));
  const auto campus = open_dataset_argument("campus", std::nullopt, 1, Face::cli);
  EXPECT_GT(campus->size(), 100u);
  EXPECT_TRUE(campus->ground_truth(0).has_value());
  const std::string cli = problem_of("campus", "poses.txt", Face::cli);
  EXPECT_NE(cli.find("--poses"), std::string::npos) << cli;
  EXPECT_NE(cli.find("the campus brings its own ground truth"), std::string::npos) << cli;
  EXPECT_EQ(problem_of("campus", "poses.txt", Face::python).rfind("poses", 0), 0u);
}

TEST(DatasetArgument, AMissingFolderOrAFileIsNamed) {
  const fs::path dir = fs::temp_directory_path() / "sextant_dataset_argument_test";
  fs::create_directories(dir);
  const std::string missing = (dir / "nothing here").string();
  const std::string a = problem_of(missing, std::nullopt, Face::cli);
  EXPECT_EQ(a.rfind(missing, 0), 0u) << a;
  EXPECT_NE(a.find("no such dataset folder"), std::string::npos) << a;
  const fs::path file = dir / "scan.xyz";
  std::ofstream(file) << "1 2 3\n";
  const std::string b = problem_of(file.string(), std::nullopt, Face::python);
  EXPECT_NE(b.find("is a file, expected a dataset folder"), std::string::npos) << b;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sextant
