// Expansion into runs, stable keys, paired seeds and shards.
#include <set>

#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/experiments/run_plan.hpp"
#include "sextant/pipeline/json.hpp"
#include "sextant/pipeline/yaml_json.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

ExperimentConfig parse(const std::string& text) {
  return parse_experiment_config(YAML::Load(text), "mem.yaml", false);
}

TEST(RunPlan, ExpandsTheCartesianProductInAFixedOrder) {
  const auto runs = expand_runs(parse(test::selftest_yaml("p", 3, 2, 0)));
  ASSERT_EQ(runs.size(), 2u * 3u * 2u);
  EXPECT_EQ(runs[0].method, "a");
  EXPECT_EQ(runs[0].point.at("x"), "1");
  EXPECT_EQ(runs[1].repetition, 1);
  EXPECT_EQ(runs[2].point.at("x"), "2");
  EXPECT_EQ(runs[6].method, "b");
  std::set<std::string> keys;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    EXPECT_EQ(runs[i].index, i);
    EXPECT_EQ(runs[i].key.size(), 16u);
    keys.insert(runs[i].key);
  }
  EXPECT_EQ(keys.size(), runs.size());
}

TEST(RunPlan, KeysDependOnContentNotLayout) {
  const auto a = expand_runs(
      parse("name: k\nkind: selftest\nmethods: [{name: m, x: 1, y: 2}]\nparams: {sleep_ms: 0}\n"));
  const auto b = expand_runs(
      parse("name: k\nkind: selftest\nparams:\n  sleep_ms: 0\nmethods:\n  - y: 2\n    x: 1\n    name: m\n"));
  const auto c = expand_runs(
      parse("name: k\nkind: selftest\nmethods: [{name: m, x: 1, y: 3}]\nparams: {sleep_ms: 0}\n"));
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].key, b[0].key);
  EXPECT_NE(a[0].key, c[0].key);
}

TEST(RunPlan, MethodsShareTheSeedOfAPointAndRepetition) {
  const auto runs = expand_runs(parse(test::selftest_yaml("s", 2, 2, 0)));
  EXPECT_EQ(runs[0].seed, runs[4].seed);  // same point and repetition, other method
  EXPECT_NE(runs[0].seed, runs[1].seed);  // other repetition
  EXPECT_NE(runs[0].seed, runs[2].seed);  // other point
}

TEST(RunPlan, ShardsPartitionTheRunsExactly) {
  const auto runs = expand_runs(parse(test::selftest_yaml("sh", 7, 3, 0)));
  for (const std::size_t n : {1u, 2u, 5u, 64u}) {
    std::multiset<std::string> seen;
    for (std::size_t i = 0; i < n; ++i) {
      for (const auto& r : select_shard(runs, Shard{i, n})) seen.insert(r.key);
    }
    ASSERT_EQ(seen.size(), runs.size()) << n;
    for (const auto& r : runs) EXPECT_EQ(seen.count(r.key), 1u);
  }
}

TEST(RunPlan, ParsesShardSpecifications) {
  const Shard s = parse_shard("3/8");
  EXPECT_EQ(s.index, 2u);
  EXPECT_EQ(s.count, 8u);
  for (const char* bad : {"0/4", "5/4", "1/0", "x/2", "2", "/3", "1/", "-1/2"}) {
    EXPECT_THROW(parse_shard(bad), InputError) << bad;
  }
}

TEST(Json, CanonicalFormIsSortedAndTyped) {
  EXPECT_EQ(canonical_json(YAML::Load("{b: 1, a: [x, 2]}")), "{\"a\":[\"x\",\"2\"],\"b\":\"1\"}");
  EXPECT_EQ(to_json(YAML::Load("{b: 1.5, a: [x, true, \"3\"]}")), "{\"b\":1.5,\"a\":[\"x\",true,\"3\"]}");
  EXPECT_EQ(json_number(0.1), "0.1");
  EXPECT_EQ(json_number(std::nan("")), "null");
  EXPECT_EQ(json_string("a\"b\\\n"), "\"a\\\"b\\\\\\n\"");
  EXPECT_EQ(hex64(stable_hash("")), "cbf29ce484222325");  // FNV-1a 64 offset basis
}

}  // namespace
}  // namespace sextant
