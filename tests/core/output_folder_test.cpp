// OutputFolder: one output folder, one run, all or nothing (issue 64, class 5).
#include "sextant/core/output_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "test_util.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using test::write_text;

std::set<std::string> names_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

void write_run(const fs::path& target, const std::set<std::string>& files) {
  OutputFolder folder(target, "a test");
  for (const auto& name : files) write_text(folder.staging() / name, name + " of this run\n");
  EXPECT_FALSE(fs::exists(target / *files.begin())) << "visible before the commit";
  folder.commit();
}

TEST(OutputFolder, ARerunReplacesTheWholeSet) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  write_run(out, {"trajectory.tum", "loop_closures.csv", "chained"});
  write_run(out, {"trajectory.tum", "steps.csv"});
  EXPECT_EQ(names_in(out), (std::set<std::string>{kMarkerFile, "trajectory.tum", "steps.csv"}));
  // Nothing else is left in the parent: no staging folder, no earlier set, no lock file.
  EXPECT_EQ(names_in(tmp.path()), std::set<std::string>{"out"});
}

TEST(OutputFolder, ARunThatDoesNotFinishLeavesTheEarlierSet) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  write_run(out, {"trajectory.tum"});
  {
    OutputFolder folder(out, "a test");
    write_text(folder.staging() / "steps.csv", "half\n");
  }  // a failed run: no commit
  EXPECT_EQ(names_in(out), (std::set<std::string>{kMarkerFile, "trajectory.tum"}));
  EXPECT_EQ(names_in(tmp.path()), std::set<std::string>{"out"});
}

TEST(OutputFolder, TheStagingFolderOfAKilledRunIsRemovedByTheNext) {
  TempDir tmp;
  write_text(tmp / ".out.partial-99999" / "trajectory.tum", "of a killed run\n");
  write_text(tmp / ".out.previous-99999" / "trajectory.tum", "of a killed swap\n");
  write_text(tmp / ".other.partial-99999" / "x", "another folder's, kept\n");
  write_run(tmp / "out", {"steps.csv"});
  EXPECT_EQ(names_in(tmp.path()), (std::set<std::string>{"out", ".other.partial-99999"}));
}

TEST(OutputFolder, TwoRunsIntoOneFolderAtOnceTheSecondIsRefused) {
  TempDir tmp;
  OutputFolder first(tmp / "out", "a test");
  test::expect_input_error([&] { OutputFolder second(tmp / "out", "a test"); }, tmp / "out", "",
                           "another sextant process writes this output folder now");
  // A sibling folder is another target: not refused.
  OutputFolder sibling(tmp / "other", "a test");
  sibling.commit();
  first.commit();
  EXPECT_TRUE(fs::exists(tmp / "out" / kMarkerFile));
}

TEST(OutputFolder, FilesSextantDidNotWriteAreNeverReplaced) {
  TempDir tmp;
  write_text(tmp / "thesis" / "chapter1.tex", "mine\n");
  test::expect_input_error([&] { OutputFolder folder(tmp / "thesis", "a test"); }, tmp / "thesis", "",
                           "holds files sextant did not write (e.g. 'chapter1.tex')");
  EXPECT_EQ(names_in(tmp / "thesis"), std::set<std::string>{"chapter1.tex"});
  write_text(tmp / "notes.txt", "mine\n");
  test::expect_input_error([&] { OutputFolder folder(tmp / "notes.txt", "a test"); }, tmp / "notes.txt", "",
                           "is a file, not a folder");
  EXPECT_EQ(names_in(tmp.path()), (std::set<std::string>{"thesis", "notes.txt"}));
  // An empty folder is taken.
  fs::create_directory(tmp / "empty");
  write_run(tmp / "empty", {"a"});
  EXPECT_EQ(names_in(tmp / "empty"), (std::set<std::string>{kMarkerFile, "a"}));
}

TEST(OutputFolder, ALinkToAFolderReplacesTheFolderItPointsTo) {
  TempDir tmp;
  write_run(tmp / "real", {"old"});
  fs::create_directory_symlink(tmp / "real", tmp / "link");
  write_run(tmp / "link/", {"new"});
  EXPECT_TRUE(fs::is_symlink(tmp / "link"));
  EXPECT_EQ(names_in(tmp / "real"), (std::set<std::string>{kMarkerFile, "new"}));
}

}  // namespace
}  // namespace sextant
