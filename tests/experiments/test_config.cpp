// The experiment schema: every problem names the file, the line and the key.
#include <gtest/gtest.h>

#include "sextant/core/error.hpp"
#include "sextant/experiments/experiment_config.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;
using test::write_text;

const char* kValid = R"(name: demo
kind: selftest
seed: 3
repetitions: 2
methods:
  - name: a
  - name: b
sweep:
  x: [1, 2, 3]
  y: {from: 0.5, to: 1.5, step: 0.5}
params:
  sleep_ms: 0
quick:
  repetitions: 1
  sweep:
    x: [1]
)";

/// Parses `text` from a file and returns the InputError's message ("" when it parses).
std::string error_of(const TempDir& tmp, const std::string& text, bool validate_kind = false) {
  const auto file = tmp / "exp.yaml";
  write_text(file, text);
  try {
    const ExperimentConfig c = read_experiment_config(file, false);
    if (validate_kind) run_kind_registry().create(c.kind)->validate(c);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string());
    return e.what();
  }
  return "";
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(ExperimentConfig, ReadsTheSchemaAndAppliesQuickOverrides) {
  TempDir tmp;
  write_text(tmp / "exp.yaml", kValid);
  const ExperimentConfig full = read_experiment_config(tmp / "exp.yaml", false);
  EXPECT_EQ(full.name, "demo");
  EXPECT_EQ(full.kind, "selftest");
  EXPECT_EQ(full.seed, 3u);
  EXPECT_EQ(full.repetitions, 2);
  ASSERT_EQ(full.methods.size(), 2u);
  ASSERT_EQ(full.sweep.size(), 2u);
  EXPECT_EQ(full.sweep[0].values.size(), 3u);
  ASSERT_EQ(full.sweep[1].values.size(), 3u);
  EXPECT_DOUBLE_EQ(full.sweep[1].values[2].as<double>(), 1.5);

  const ExperimentConfig quick = read_experiment_config(tmp / "exp.yaml", true);
  EXPECT_EQ(quick.repetitions, 1);
  EXPECT_EQ(quick.sweep[0].values.size(), 1u);
  EXPECT_EQ(quick.sweep[1].values.size(), 3u);  // maps merge: y is kept
  EXPECT_FALSE(quick.effective["quick"].IsDefined());
}

TEST(ExperimentConfig, UnknownKeyNamesFileLineAndKey) {
  TempDir tmp;
  const std::string msg = error_of(tmp, replace(kValid, "seed: 3", "sed: 3"));
  EXPECT_NE(msg.find("exp.yaml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'sed'"), std::string::npos) << msg;
}

TEST(ExperimentConfig, WrongTypeNamesFileLineAndKey) {
  TempDir tmp;
  const std::string msg = error_of(tmp, replace(kValid, "repetitions: 2", "repetitions: many"));
  EXPECT_NE(msg.find("line 4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'repetitions'"), std::string::npos) << msg;
}

TEST(ExperimentConfig, BadValueNamesFileLineAndKey) {
  TempDir tmp;
  std::string msg = error_of(tmp, replace(kValid, "repetitions: 2", "repetitions: 0"));
  EXPECT_NE(msg.find("line 4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("repetitions"), std::string::npos) << msg;

  msg = error_of(tmp, replace(kValid, "name: demo", "name: Demo Experiment"));
  EXPECT_NE(msg.find("line 1"), std::string::npos) << msg;

  msg = error_of(tmp, replace(kValid, "{from: 0.5, to: 1.5, step: 0.5}", "{from: 2, to: 1}"));
  EXPECT_NE(msg.find("line 10"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'y'"), std::string::npos) << msg;

  msg = error_of(tmp, replace(kValid, "{from: 0.5, to: 1.5, step: 0.5}", "{from: 0, to: 1.0e300}"));
  EXPECT_NE(msg.find("line 10"), std::string::npos) << msg;
  EXPECT_NE(msg.find("10^6"), std::string::npos) << msg;
}

// "Billion laughs": nine levels of aliases, each repeating the previous ten times, stand for 10^9
// nodes in a few lines; merging, hashing or writing the config would expand them.
TEST(ExperimentConfig, AliasBombIsRefusedBeforeAnythingExpandsIt) {
  TempDir tmp;
  std::string bomb =
      std::string(kValid) + "reference:\n  l0: &l0 [lol, lol, lol, lol, lol, lol, lol, lol, lol, lol]\n";
  for (int level = 1; level <= 9; ++level) {
    const std::string prev = "*l" + std::to_string(level - 1);
    bomb += "  l" + std::to_string(level) + ": &l" + std::to_string(level) + " [";
    for (int k = 0; k < 10; ++k) bomb += (k ? ", " : "") + prev;
    bomb += "]\n";
  }
  const std::string msg = error_of(tmp, bomb);
  EXPECT_NE(msg.find("expands to more than 10^6 nodes"), std::string::npos) << msg;
}

TEST(ExperimentConfig, DeepNestingNonScalarKeysAndFoldersAreRefused) {
  TempDir tmp;
  std::string msg = error_of(
      tmp, std::string(kValid) + "reference: " + std::string(100, '[') + std::string(100, ']') + "\n");
  EXPECT_NE(msg.find("nests deeper than 64 levels"), std::string::npos) << msg;
  msg = error_of(tmp, std::string(kValid) + "reference:\n  [a, b]: 1\n");
  EXPECT_NE(msg.find("a map key must be a plain name"), std::string::npos) << msg;
  std::filesystem::create_directories(tmp / "folder.yaml");
  try {
    read_experiment_config(tmp / "folder.yaml", false);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
  }
}

TEST(ExperimentConfig, ErrorsInsideTheQuickBlockPointIntoIt) {
  TempDir tmp;
  const auto file = tmp / "exp.yaml";
  write_text(file, replace(kValid, "  repetitions: 1", "  repetitions: -1"));
  try {
    read_experiment_config(file, true);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 14"), std::string::npos) << e.what();
  }
}

TEST(ExperimentConfig, KindValidationNamesTheKey) {
  TempDir tmp;
  const std::string msg = error_of(tmp, replace(kValid, "sleep_ms: 0", "sleep_ms: -5"), true);
  EXPECT_NE(msg.find("line 12"), std::string::npos) << msg;
  EXPECT_NE(msg.find("sleep_ms"), std::string::npos) << msg;

  const std::string unknown = error_of(tmp, replace(kValid, "sleep_ms: 0", "sleep_ms: 0\n  naps: 2"), true);
  EXPECT_NE(unknown.find("line 13"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("'naps'"), std::string::npos) << unknown;
}

TEST(ExperimentConfig, TheShippedConfigsAreValid) {
  const auto configs = list_experiment_configs(std::filesystem::path(SEXTANT_SOURCE_DIR) / "experiments");
  ASSERT_FALSE(configs.empty());
  for (const auto& file : configs) {
    for (const bool quick : {false, true}) {
      SCOPED_TRACE(file.string());
      const ExperimentConfig c = read_experiment_config(file, quick);
      EXPECT_EQ(file.stem().string(), c.name);
      ASSERT_TRUE(run_kind_registry().contains(c.kind)) << c.kind;
      run_kind_registry().create(c.kind)->validate(c);
    }
  }
}

}  // namespace
}  // namespace sextant

namespace sextant {
namespace {

// Issue 23: a key given twice used to be "the first wins" in the runner while experiment.yaml
// recorded the second; a value listed twice ran twice under one label.
TEST(ExperimentConfig, DuplicateKeysAndSweepValuesAreErrorsAtTheirLine) {
  TempDir tmp;
  std::string msg = error_of(tmp, replace(kValid, "seed: 3", "seed: 3\nseed: 4"));
  EXPECT_NE(msg.find("line 4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("duplicate key 'seed' (first at line 3)"), std::string::npos) << msg;
  msg = error_of(tmp, replace(kValid, "x: [1, 2, 3]", "x: [1, 2, 1]"));
  EXPECT_NE(msg.find("sweep axis 'x': the value '1' is listed twice"), std::string::npos) << msg;
  msg = error_of(tmp, replace(kValid, "x: [1, 2, 3]", "x: [1, \"1\"]"));
  EXPECT_NE(msg.find("listed twice"), std::string::npos) << msg;
}

// Issue 23: the plan's size is checked before anything is allocated, without overflow.
TEST(ExperimentConfig, PlansOverTheRunCapAreRefusedNamingTheAxes) {
  TempDir tmp;
  std::string msg = error_of(
      tmp,
      replace(kValid, "x: [1, 2, 3]", "x: {from: 1, to: 10000, step: 1}\n  z: {from: 1, to: 1000, step: 1}"));
  EXPECT_NE(msg.find("axis 'x' (10000 values) × axis 'z' (1000 values)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("more than 1000000 runs"), std::string::npos) << msg;
  msg = error_of(tmp, replace(kValid, "repetitions: 2", "repetitions: 2147483647"));
  EXPECT_NE(msg.find("2147483647 repetitions"), std::string::npos) << msg;
}

}  // namespace
}  // namespace sextant
