// `sextant slurm`'s library side: the sbatch scripts, the array index lists, which shards a resume
// re-submits, and that merged shards do not depend on the number of shards. The real cluster run is
// the ctest `slurm_cluster` (slurm_cluster_test.sh).
#include <algorithm>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "sextant/experiments/slurm.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;

SlurmOptions slurm_options(const std::filesystem::path& dir, std::size_t n) {
  SlurmOptions o;
  o.configs = {dir / "e.yaml"};
  o.name = "st";
  o.array_size = n;
  o.results = dir / "results";
  o.report = dir / "report";
  o.sextant = "/opt/sextant/bin/sextant";
  o.workdir = dir;
  return o;
}

/// Runs shard k/n of e.yaml into the shard root `sextant slurm` gives it (what array task k does).
void run_shard(const SlurmOptions& o, std::size_t k) {
  RunnerOptions r;
  r.results_root = shard_root(o, k);
  r.shard = Shard{k - 1, o.array_size};
  r.jobs = 2;
  r.progress = false;
  run_experiment(o.configs.front(), r);
}

/// runs.csv with the wall-time column ("seconds") blanked: what must not depend on N.
std::string csv_without_seconds(const std::filesystem::path& csv) {
  std::istringstream in(test::read_text(csv));
  std::string line, out;
  long column = -1;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    if (column < 0) column = std::find(fields.begin(), fields.end(), "seconds") - fields.begin();
    if (column < static_cast<long>(fields.size()) && out.size() > 0) fields[column] = "T";
    for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + fields[i];
    out += "\n";
  }
  return out;
}

TEST(SlurmScripts, TheArrayRunsShardKOfNAndTheMergeJobMergesAndReports) {
  TempDir tmp;
  SlurmOptions o = slurm_options(tmp.path(), 4);
  o.quick = true;
  o.partition = "short";
  o.time = "00:30:00";
  o.mem = "4G";
  o.cpus_per_task = 2;
  const std::string array = array_script(o);
  for (const std::string& expected : std::vector<std::string>{
           "#!/bin/bash\n", "#SBATCH --array=1-4\n", "#SBATCH --partition=short\n",
           "#SBATCH --time=00:30:00\n", "#SBATCH --mem=4G\n", "#SBATCH --cpus-per-task=2\n",
           "--shard \"$k/4\"", " --quick", "/opt/sextant/bin/sextant run",
           (tmp / "results" / "_shards").string() + "/\"$k-of-4\"", (tmp / "e.yaml").string(),
           "--jobs \"${SLURM_CPUS_PER_TASK:-1}\""}) {
    EXPECT_NE(array.find(expected), std::string::npos) << expected << "\nin\n" << array;
  }
  const std::string merge = merge_script(o);
  for (const std::string& expected : std::vector<std::string>{
           "$(seq 1 4)",
           "/opt/sextant/bin/sextant merge \"${shards[@]}\" --out " + (tmp / "results").string(),
           "/opt/sextant/bin/sextant report " + (tmp / "results").string() + " --out " +
               (tmp / "report").string()}) {
    EXPECT_NE(merge.find(expected), std::string::npos) << expected << "\nin\n" << merge;
  }
  EXPECT_EQ(merge.find("--array"), std::string::npos);
  EXPECT_EQ(shard_root(o, 3), tmp / "results" / "_shards" / "3-of-4");

  o.partition = "a b";
  std::string why;
  EXPECT_FALSE(o.valid(&why));
  EXPECT_NE(why.find("no spaces"), std::string::npos);
}

TEST(SlurmScripts, ArrayIndicesAreRanges) {
  EXPECT_EQ(array_indices({1, 2, 3, 4}), "1-4");
  EXPECT_EQ(array_indices({3}), "3");
  EXPECT_EQ(array_indices({2, 4, 5, 6, 9}), "2,4-6,9");
  EXPECT_EQ(array_indices({}), "");
}

TEST(SlurmScripts, MergedShardsEqualASingleRunWhateverN) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("st", 7, 3, 0));  // 42 runs
  RunnerOptions single;
  single.results_root = tmp / "single";
  single.jobs = 2;
  single.progress = false;
  run_experiment(tmp / "e.yaml", single);
  const std::string expected_csv = csv_without_seconds(tmp / "single" / "st" / kRunsCsv);
  for (const std::size_t n : {1u, 4u}) {
    const auto dir = tmp / ("n" + std::to_string(n));
    test::write_text(dir / "e.yaml", test::selftest_yaml("st", 7, 3, 0));
    const SlurmOptions o = slurm_options(dir, n);
    std::vector<std::filesystem::path> roots;
    for (std::size_t k = n; k >= 1; --k) {  // in reverse: the order of the shards does not matter
      run_shard(o, k);
      roots.push_back(shard_root(o, k));
    }
    EXPECT_EQ(merge_results(roots, o.results).rows, 42u);
    EXPECT_EQ(csv_without_seconds(o.results / "st" / kRunsCsv), expected_csv) << "N = " << n;
    EXPECT_EQ(test::read_text(o.results / "st" / kEffectiveConfig),
              test::read_text(tmp / "single" / "st" / kEffectiveConfig));
    // runs.jsonl in expansion order, every row with the seed of the single run's row of that key.
    const auto merged = read_rows(o.results / "st" / kRunsJsonl).rows;
    const auto reference = read_rows(tmp / "single" / "st" / kRunsJsonl).rows;
    ASSERT_EQ(merged.size(), reference.size());
    std::map<std::string, const RunRow*> by_key;
    for (const auto& r : reference) by_key[r.key] = &r;
    for (std::size_t i = 0; i < merged.size(); ++i) {
      EXPECT_EQ(merged[i].value("index"), static_cast<double>(i)) << "N = " << n;
      ASSERT_TRUE(by_key.count(merged[i].key));
      EXPECT_EQ(merged[i].seed, by_key[merged[i].key]->seed);
      EXPECT_EQ(merged[i].values, by_key[merged[i].key]->values);
    }
  }
}

TEST(SlurmScripts, ResumeFindsTheMissingAndTheIncompleteShards) {
  TempDir tmp;
  test::write_text(tmp / "e.yaml", test::selftest_yaml("st", 5, 2, 0));  // 20 runs, 5 per shard
  const SlurmOptions o = slurm_options(tmp.path(), 4);
  for (const std::size_t k : {1u, 2u, 4u}) run_shard(o, k);  // task 3 was cancelled
  auto states = shard_states(o);
  ASSERT_EQ(states.size(), 4u);
  for (const auto& s : states) {
    EXPECT_EQ(s.runs, 5u);
    EXPECT_EQ(s.complete(), s.shard != 3) << "shard " << s.shard;
  }
  EXPECT_EQ(states[2].finished, 0u);

  // Task 2 killed after two runs: its runs.jsonl keeps two lines and the start of a third.
  const auto jsonl = shard_root(o, 2) / "st" / kRunsJsonl;
  std::istringstream in(test::read_text(jsonl));
  std::string a, b, c;
  std::getline(in, a);
  std::getline(in, b);
  std::getline(in, c);
  test::write_text(jsonl, a + "\n" + b + "\n" + c.substr(0, c.size() / 2));
  states = shard_states(o);
  EXPECT_EQ(states[1].finished, 2u);
  EXPECT_FALSE(states[1].complete());
  EXPECT_TRUE(states[0].complete());
  EXPECT_TRUE(states[3].complete());

  // Re-running tasks 2 and 3 (what the resume submits) completes them; task 2 redoes only its 3 runs.
  RunnerOptions r;
  r.results_root = shard_root(o, 2);
  r.shard = Shard{1, 4};
  r.progress = false;
  EXPECT_EQ(run_experiment(tmp / "e.yaml", r).executed, 3u);
  run_shard(o, 3);
  for (const auto& s : shard_states(o)) EXPECT_TRUE(s.complete()) << "shard " << s.shard;
}

}  // namespace
}  // namespace sextant
