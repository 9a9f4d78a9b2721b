// SettingsRecording: every key a SettingsReader reads, with the value it ends with (given or
// default), children nested under their key, aliases left out, nothing recorded outside a recording.
#include <gtest/gtest.h>

#include "sextant/core/settings_reader.hpp"

namespace sextant {
namespace {

struct Inner {
  int count = 3;
};
struct Outer {
  double size = 1.5;
  std::string name = "default";
  std::vector<std::string> axes{"x", "y"};
  bool legacy = false;
  Inner inner;
};

Inner read_inner(const YAML::Node& node) {
  SettingsReader in(node, "t.yaml");
  Inner s;
  in.read("count", s.count);
  in.finish();
  return s;
}

Outer read_outer(const YAML::Node& node) {
  SettingsReader in(node, "t.yaml");
  Outer s;
  in.read("size", s.size);
  in.read("name", s.name);
  in.read("axes", s.axes);
  in.read_alias("old_legacy", s.legacy);
  s.inner = read_inner(in.child("inner"));
  in.finish();
  return s;
}

TEST(SettingsRecording, RecordsGivenValuesAndDefaultsNestedByKey) {
  SettingsRecording recording;
  (void)read_outer(YAML::Load("{size: 2.5, old_legacy: true, inner: {}}"));
  const YAML::Node r = recording.resolved();
  EXPECT_EQ(r["size"].as<double>(), 2.5);             // given
  EXPECT_EQ(r["name"].as<std::string>(), "default");  // default kept
  EXPECT_EQ(r["axes"].as<std::vector<std::string>>(), (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(r["inner"]["count"].as<int>(), 3);
  EXPECT_FALSE(r["old_legacy"].IsDefined()) << "an alias is not recorded";
  EXPECT_EQ(r.size(), 4u);
  // The record reads back to the same settings and records the same again.
  const YAML::Node again = YAML::Clone(r);
  SettingsRecording second;
  const Outer s = read_outer(again);
  EXPECT_EQ(s.size, 2.5);
  EXPECT_EQ(YAML::Dump(second.resolved()), YAML::Dump(r));
}

TEST(SettingsRecording, AbsentChildrenRecordTheirDefaultsAndNothingOutsideARecording) {
  YAML::Node resolved;
  {
    SettingsRecording recording;
    (void)read_outer(YAML::Node());
    resolved = YAML::Clone(recording.resolved());
  }
  EXPECT_EQ(resolved["inner"]["count"].as<int>(), 3);
  EXPECT_EQ(resolved["size"].as<double>(), 1.5);
  // No recording alive: readers work as before (and nothing leaks into the last recording).
  const Outer s = read_outer(YAML::Load("{size: 9}"));
  EXPECT_EQ(s.size, 9.0);
  EXPECT_EQ(resolved["size"].as<double>(), 1.5);
}

}  // namespace
}  // namespace sextant
