// The runner: results, resume, truncated lines, shards + merge, and a SIGKILL mid-sweep.
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;

std::size_t newlines_in(const std::filesystem::path& file) {
  const std::string text = test::read_text(file);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(Runner, WritesRowsCsvAndProvenanceThenSkipsFinishedRuns) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("rt", 3, 1, 0));
  const RunnerSummary first = run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));
  EXPECT_EQ(first.total, 6u);
  EXPECT_EQ(first.executed, 6u);
  EXPECT_EQ(first.failed, 0u);
  const auto folder = tmp / "results" / "rt";
  EXPECT_EQ(read_rows(folder / kRunsJsonl).rows.size(), 6u);
  EXPECT_EQ(newlines_in(folder / kRunsCsv), 7u);
  const std::string provenance = test::read_text(folder / "provenance.json");
  for (const char* field : {"\"git\"", "\"sha\"", "\"dirty\"", "\"libraries\"", "\"host\"", "\"threads\": 2",
                            "\"start\"", "\"end\"", "\"resolved_config\"", "\"seed\""}) {
    EXPECT_NE(provenance.find(field), std::string::npos) << field;
  }
  EXPECT_TRUE(std::filesystem::exists(folder / kEffectiveConfig));

  const RunnerSummary second = run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));
  EXPECT_EQ(second.executed, 0u);
  EXPECT_EQ(second.skipped, 6u);
  EXPECT_EQ(newlines_in(folder / kRunsJsonl), 6u);
}

TEST(Runner, AnInterruptedSweepIsCompletedWithoutDuplicates) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("part", 5, 1, 0));
  RunnerOptions o = test::runner_options(tmp / "results");
  o.max_runs = 4;
  EXPECT_EQ(run_experiment(tmp / "e.yaml", o).executed, 4u);
  const RunnerSummary rest = run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));
  EXPECT_EQ(rest.executed, 6u);
  EXPECT_EQ(rest.skipped, 4u);
  EXPECT_EQ(newlines_in(tmp / "results" / "part" / kRunsJsonl), 10u);
}

TEST(Runner, ToleratesATruncatedLastLine) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("trunc", 2, 1, 0));
  run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));
  const auto jsonl = tmp / "results" / "trunc" / kRunsJsonl;
  // Keep three complete rows and half of the fourth, as a killed writer could leave it.
  std::string text = test::read_text(jsonl);
  std::size_t cut = 0;
  for (int i = 0; i < 3; ++i) cut = text.find('\n', cut) + 1;
  const std::size_t half = cut + (text.find('\n', cut) - cut) / 2;
  test::write_text(jsonl, text.substr(0, half));
  EXPECT_EQ(read_rows(jsonl).rows.size(), 3u);
  EXPECT_EQ(read_rows(jsonl).bad_lines, 1u);

  const RunnerSummary s = run_experiment(tmp / "e.yaml", test::runner_options(tmp / "results"));
  EXPECT_EQ(s.executed, 1u);
  const RowFile rows = read_rows(jsonl);
  EXPECT_EQ(rows.rows.size(), 4u);
  EXPECT_EQ(rows.bad_lines, 1u);  // the truncated line stays, ended by a newline, and is skipped
}

TEST(Runner, ShardsMergeIntoTheWholeSweep) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("sharded", 5, 2, 0));
  std::vector<std::filesystem::path> roots;
  std::size_t executed = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    RunnerOptions o = test::runner_options(tmp / ("shard" + std::to_string(i)));
    o.shard = Shard{i, 3};
    executed += run_experiment(tmp / "e.yaml", o).executed;
    roots.push_back(o.results_root);
    EXPECT_TRUE(std::filesystem::exists(o.results_root / "sharded" / provenance_file_name(o.shard)));
  }
  EXPECT_EQ(executed, 20u);
  EXPECT_EQ(merge_results(roots, tmp / "merged").rows, 20u);
  const RowFile merged = read_rows(tmp / "merged" / "sharded" / kRunsJsonl);
  EXPECT_EQ(merged.rows.size(), 20u);
  EXPECT_EQ(newlines_in(tmp / "merged" / "sharded" / kRunsJsonl), 20u);
  EXPECT_TRUE(std::filesystem::exists(tmp / "merged" / "sharded" / "provenance.shard-2-of-3.json"));

  // The merged root is complete: a rerun there has nothing left to do.
  RunnerOptions o = test::runner_options(tmp / "merged");
  EXPECT_EQ(run_experiment(tmp / "e.yaml", o).executed, 0u);

  // The report reads the shard roots directly too.
  const ReportSummary report = write_report(roots, tmp / "report");
  EXPECT_EQ(report.experiments, 1u);
  EXPECT_NE(test::read_text(tmp / "report" / "sharded" / "runs_per_method.md").find("| 10"),
            std::string::npos);
}

pid_t spawn(const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

int wait_for(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

TEST(Runner, ResumesAfterSigkillMidSweep) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("killed", 30, 1, 40));  // 60 runs × 40 ms on 2 threads
  const auto jsonl = tmp / "results" / "killed" / kRunsJsonl;
  const std::vector<std::string> args{SEXTANT_BINARY,
                                      "run",
                                      (tmp / "e.yaml").string(),
                                      "--results",
                                      (tmp / "results").string(),
                                      "--jobs",
                                      "2",
                                      "--no-progress"};
  const pid_t pid = spawn(args);
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (newlines_in(jsonl) < 6 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(pid, SIGKILL);
  const int status = wait_for(pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep finished before it could be killed";
  const std::size_t before = read_rows(jsonl).rows.size();
  EXPECT_GE(before, 6u);
  EXPECT_LT(before, 60u);

  const int rerun = wait_for(spawn(args));
  ASSERT_TRUE(WIFEXITED(rerun));
  EXPECT_EQ(WEXITSTATUS(rerun), 0);
  const RowFile after = read_rows(jsonl);
  EXPECT_EQ(after.rows.size(), 60u);
  EXPECT_LE(after.bad_lines, 1u);
  // No run was executed twice: every valid line has its own key.
  std::set<std::string> keys;
  std::size_t valid_lines = 0;
  std::istringstream lines(test::read_text(jsonl));
  for (std::string line; std::getline(lines, line);) {
    RunRow row;
    if (parse_json_line(line, row)) {
      ++valid_lines;
      keys.insert(row.key);
    }
  }
  EXPECT_EQ(valid_lines, 60u);
  EXPECT_EQ(keys.size(), 60u);
}

}  // namespace
}  // namespace sextant

namespace sextant {
namespace {

TEST(Cli, ReproduceRunsEveryConfigOfAFolderAndWritesTheReport) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "configs");
  std::filesystem::copy_file(
      std::filesystem::path(SEXTANT_SOURCE_DIR) / "experiments" / "e18_metric_examples.yaml",
      tmp / "configs" / "e18_metric_examples.yaml");
  test::write_text(tmp / "configs" / "e99_selftest.yaml", test::selftest_yaml("e99_selftest", 2, 1, 0));
  test::write_text(tmp / "configs" / "notes.yaml", "not: an experiment\n");  // ignored: not eNN_*.yaml
  const std::vector<std::string> args{SEXTANT_BINARY,  "reproduce",
                                      "--quick",       "--no-progress",
                                      "--experiments", (tmp / "configs").string(),
                                      "--results",     (tmp / "results").string(),
                                      "--report",      (tmp / "report").string()};
  const int status = wait_for(spawn(args));
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(read_rows(tmp / "results" / "e18_metric_examples" / kRunsJsonl).rows.size(), 10u);
  EXPECT_EQ(read_rows(tmp / "results" / "e99_selftest" / kRunsJsonl).rows.size(), 4u);
  const std::string html = test::read_text(tmp / "report" / "index.html");
  EXPECT_NE(html.find("e99_selftest"), std::string::npos);
  EXPECT_NE(html.find("e18_metric_examples"), std::string::npos);
}

// An experiment that cannot start (its dataset folder is missing) is named and counted, the others
// still run and are reported, and the exit status is 1.
TEST(Cli, ReproduceRunsTheOtherExperimentsWhenOneCannotStart) {
  TempDir tmp;
  test::write_text(tmp / "configs" / "e99_selftest.yaml", test::selftest_yaml("e99_selftest", 2, 1, 0));
  test::write_text(
      tmp / "configs" / "e98_missing.yaml",
      "name: e98_missing\nkind: registration\ndataset: {source: folder, path: no_such_folder}\n"
      "methods: [{name: m, matcher: mlndt}]\nsweep: {pair: [0]}\nparams: {pairs: consecutive}\n");
  const std::string command =
      std::string("'") + SEXTANT_BINARY + "' reproduce --quick --no-progress --experiments '" +
      (tmp / "configs").string() + "' --results '" + (tmp / "results").string() + "' --report '" +
      (tmp / "report").string() + "' 2> '" + (tmp / "err.txt").string() + "' > /dev/null";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string err = test::read_text(tmp / "err.txt");
  EXPECT_NE(err.find("e98_missing.yaml not run"), std::string::npos) << err;
  EXPECT_NE(err.find("no_such_folder"), std::string::npos) << err;
  EXPECT_NE(err.find("1 of 2 experiments not run"), std::string::npos) << err;
  EXPECT_EQ(read_rows(tmp / "results" / "e99_selftest" / kRunsJsonl).rows.size(), 4u);
  EXPECT_NE(test::read_text(tmp / "report" / "index.html").find("e99_selftest"), std::string::npos);
}

TEST(Cli, ABadConfigStopsWithFileLineAndKey) {
  TempDir tmp;
  test::write_text(tmp / "bad.yaml", test::selftest_yaml("bad", 2, 1, 0) + "colour: blue\n");
  const std::string command = std::string("'") + SEXTANT_BINARY + "' run '" + (tmp / "bad.yaml").string() +
                              "' --results '" + (tmp / "results").string() + "' 2> '" +
                              (tmp / "err.txt").string() + "'";
  const int status = std::system(command.c_str());
  EXPECT_NE(status, 0);
  const std::string err = test::read_text(tmp / "err.txt");
  EXPECT_NE(err.find("bad.yaml"), std::string::npos) << err;
  EXPECT_NE(err.find("line 12"), std::string::npos) << err;
  EXPECT_NE(err.find("'colour'"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(tmp / "results" / "bad" / kRunsJsonl));
}

}  // namespace
}  // namespace sextant

namespace sextant {
namespace {

// Issue 23: a merge into a folder that already held every row left only the shard's; the same
// shard named twice was silent about the runs no shard had; a differing config was copied over.
TEST(Merge, KeepsTheTargetsRowsAndCountsMissingAndDuplicatedRuns) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("sharded", 5, 2, 0));
  std::vector<std::filesystem::path> roots;
  for (std::size_t i = 0; i < 3; ++i) {
    RunnerOptions o = test::runner_options(tmp / ("shard" + std::to_string(i)));
    o.shard = Shard{i, 3};
    run_experiment(tmp / "e.yaml", o);
    roots.push_back(o.results_root);
  }
  const auto merged_rows = [&] { return read_rows(tmp / "all" / "sharded" / kRunsJsonl).rows.size(); };
  // Shard 0 twice, shard 1 once: the runs of shard 2 are missing, by count and by name.
  MergeSummary m = merge_results({roots[0], roots[0], roots[1]}, tmp / "all");
  ASSERT_EQ(m.experiments.size(), 1u);
  const MergedExperiment& e = m.experiments.front();
  EXPECT_EQ(e.inputs, 2u);  // the same folder named twice counts once
  EXPECT_EQ(e.expected, 20u);
  EXPECT_EQ(e.missing + e.rows, 20u);
  EXPECT_GT(e.missing, 0u);
  EXPECT_EQ(e.missing_runs.size(), e.missing);
  EXPECT_NE(e.missing_runs.front().find("repetition"), std::string::npos) << e.missing_runs.front();
  EXPECT_EQ(e.duplicated, 0u);
  // Everything, then shard 2 alone into the same target: nothing already there is dropped.
  m = merge_results(roots, tmp / "all");
  EXPECT_EQ(merged_rows(), 20u);
  m = merge_results({roots[2]}, tmp / "all");
  EXPECT_EQ(merged_rows(), 20u);
  EXPECT_EQ(m.experiments.front().missing, 0u);
  EXPECT_GT(m.experiments.front().duplicated, 0u);  // shard 2's runs are in the target already
  // A shard of another config is refused, naming both files.
  test::write_text(tmp / "f.yaml", test::selftest_yaml("sharded", 4, 2, 0));
  RunnerOptions other = test::runner_options(tmp / "other");
  run_experiment(tmp / "f.yaml", other);
  try {
    merge_results({other.results_root}, tmp / "all");
    ADD_FAILURE() << "a merge of two configs was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("results of two configs"), std::string::npos) << error.what();
  }
  EXPECT_EQ(merged_rows(), 20u);
}

}  // namespace
}  // namespace sextant

namespace sextant {
namespace {

// Issue 23: a merge took no lock and overwrote a folder a runner was writing. It takes the same
// lock the runner holds (flock on <folder>/.lock), so it is refused while another process holds it.
TEST(Merge, IsRefusedWhileAnotherProcessHoldsTheFoldersLock) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("locked", 2, 1, 0));
  RunnerOptions o = test::runner_options(tmp / "shard");
  run_experiment(tmp / "e.yaml", o);
  std::filesystem::create_directories(tmp / "all" / "locked");
  const int fd = ::open((tmp / "all" / "locked" / ".lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const pid_t child = ::fork();  // flock is per open file: another process must try
  if (child == 0) {
    try {
      merge_results({o.results_root}, tmp / "all");
    } catch (const InputError&) {
      ::_exit(7);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 7) << "the merge did not stop at the lock";
  ::close(fd);
  EXPECT_EQ(merge_results({o.results_root}, tmp / "all").rows, 4u);  // 2 methods × 2 points
}

}  // namespace
}  // namespace sextant
