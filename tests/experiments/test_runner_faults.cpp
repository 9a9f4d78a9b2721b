// Runner faults (issue 13): results folder unwritable, disk full, a config edited between runs,
// two runners on the same folder, a corrupted line in runs.jsonl. (SIGKILL mid-sweep then resume
// is Runner.ResumesAfterSigkillMidSweep in test_runner.cpp.)
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;

template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

bool has_temporary_files(const std::filesystem::path& folder) {
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().filename().string().find(".tmp.") != std::string::npos) return true;
  }
  return false;
}

TEST(RunnerFaults, ASecondRunnerOnTheSameFolderIsRefused) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("locked", 2, 1, 0));
  std::filesystem::create_directories(tmp / "results" / "locked");
  // Another process holding the lock (a separate open file description conflicts like one).
  const int fd = ::open((tmp / "results" / "locked" / ".lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string message =
      input_error_of([&] { run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results")); });
  EXPECT_NE(message.find("another sextant process is running this experiment"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(tmp / "results" / "locked" / kRunsJsonl));
  ::close(fd);  // the holder ends: the next run goes ahead
  EXPECT_EQ(run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results")).executed, 4u);
}

TEST(RunnerFaults, UnwritableResultsFolderIsAClearError) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("nowrite", 2, 1, 0));
  // A results root below a regular file cannot be created, root or not.
  test::write_text(tmp / "file", "x");
  RunnerOptions o = test::runner_options(tmp / "results");
  o.results_root = tmp / "file" / "results";
  std::string message = input_error_of([&] { run_experiment(tmp / "e.yaml", o); });
  EXPECT_NE(message.find("cannot create the results folder"), std::string::npos) << message;
  if (::geteuid() == 0) {
    GTEST_SKIP() << "running as root: a chmod 555 folder stays writable for root, so the permission case "
                    "is only checked for other users";
  }
  std::filesystem::create_directories(tmp / "ro" / "nowrite");
  ::chmod((tmp / "ro" / "nowrite").c_str(), 0555);
  o.results_root = tmp / "ro";
  message = input_error_of([&] { run_experiment(tmp / "e.yaml", o); });
  ::chmod((tmp / "ro" / "nowrite").c_str(), 0755);
  EXPECT_NE(message.find("not writable"), std::string::npos) << message;
}

// Disk full, injected without privileges: RLIMIT_FSIZE makes every write past the limit fail
// (EFBIG, SIGXFSZ ignored) exactly where a full disk would fail with ENOSPC.
TEST(RunnerFaults, DiskFullKeepsWhatWasWrittenAndLeavesNoHalfFile) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("full", 5, 1, 0));
  RunnerOptions o = test::runner_options(tmp / "results");
  o.max_runs = 3;
  o.jobs = 1;
  run_experiment(tmp / "e.yaml", o);
  const auto folder = tmp / "results" / "full";
  const std::string jsonl_before = test::read_text(folder / kRunsJsonl);
  const std::string csv_before = test::read_text(folder / kRunsCsv);
  const std::string provenance_before = test::read_text(folder / "provenance.json");

  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto previous = ::signal(SIGXFSZ, SIG_IGN);
  const rlimit tight{static_cast<rlim_t>(jsonl_before.size() + 20), old.rlim_max};
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &tight), 0);
  o.max_runs = 0;
  const std::string message = input_error_of([&] { run_experiment(tmp / "e.yaml", o); });
  ::setrlimit(RLIMIT_FSIZE, &old);
  ::signal(SIGXFSZ, previous);

  EXPECT_TRUE(message.find("write failed") != std::string::npos ||
              message.find("cannot append a line") != std::string::npos)
      << message;
  EXPECT_NE(message.find("kept"), std::string::npos) << message;
  EXPECT_FALSE(has_temporary_files(folder));
  // Nothing already written is lost and no file is half-written.
  const std::string jsonl_after = test::read_text(folder / kRunsJsonl);
  EXPECT_EQ(jsonl_after.substr(0, jsonl_before.size()), jsonl_before);
  EXPECT_EQ(read_rows(folder / kRunsJsonl).bad_lines, 0u);
  EXPECT_EQ(test::read_text(folder / kRunsCsv), csv_before);
  EXPECT_FALSE(test::read_text(folder / "provenance.json").empty());
  (void)provenance_before;

  const RunnerSummary rest =
      run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));  // space again
  EXPECT_EQ(rest.skipped + rest.executed, 10u);
  EXPECT_EQ(read_rows(folder / kRunsJsonl).rows.size(), 10u);
}

TEST(RunnerFaults, ACorruptedLineIsNamedAndTheRestIsUsed) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("corrupt", 3, 1, 0));
  run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));
  const auto folder = tmp / "results" / "corrupt";
  std::string text = test::read_text(folder / kRunsJsonl);
  const std::size_t second = text.find('\n') + 1;
  text.replace(second, 10, "#garbage!#");  // line 2 no longer parses
  test::write_text(folder / kRunsJsonl, text);

  const RunnerSummary s = run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));
  EXPECT_EQ(s.executed, 1u);  // only the run of the corrupted line is redone
  EXPECT_EQ(s.skipped, 5u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("runs.jsonl:2: unreadable line skipped"), std::string::npos) << s.warnings[0];

  write_report({tmp / "results"}, tmp / "report");
  const std::string md = test::read_text(tmp / "report" / "corrupt" / "corrupt.md");
  EXPECT_NE(md.find("runs.jsonl:2: unreadable line skipped"), std::string::npos) << md;
  EXPECT_NE(md.find("Runs: 6 of 6 found"), std::string::npos) << md;
}

TEST(RunnerFaults, AnEditedConfigGetsNewRunsAndTheOldRowsStayApart) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("edited", 2, 1, 0));
  run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));
  std::string edited = test::selftest_yaml("edited", 2, 1, 0);
  edited.replace(edited.find("seed: 7"), 7, "seed: 8");
  test::write_text(tmp / "e.yaml", edited);
  const RunnerSummary s = run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));
  EXPECT_EQ(s.executed, 4u);  // new keys: nothing of the old config is reused
  EXPECT_EQ(s.skipped, 0u);
  const auto folder = tmp / "results" / "edited";
  EXPECT_EQ(read_rows(folder / kRunsJsonl).rows.size(), 8u);  // the old rows are kept

  write_report({tmp / "results"}, tmp / "report");
  const std::string md = test::read_text(tmp / "report" / "edited" / "edited.md");
  EXPECT_NE(md.find("Runs: 4 of 4 found"), std::string::npos) << md;
  EXPECT_NE(md.find("Shown: the config in " + (folder / kEffectiveConfig).string() + " (fingerprint "),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("4 rows in runs.jsonl belong to another config or profile"), std::string::npos) << md;
}

}  // namespace
}  // namespace sextant
