// Reading the campus settings from YAML (Sextant::synth_yaml).
#include "sextant/synth/yaml.hpp"

#include "sextant/core/settings_reader.hpp"
#include "sextant/synth/settings_fields.hpp"

namespace sextant::synth {
namespace {

template <class Section>
void read_section(SettingsReader& in, const std::string& key, Section& section) {
  SettingsReader sub(in.child(key), in.file());
  visit(section, [&sub](const char* name, auto& field) { sub.read(name, field); });
  sub.finish();
  std::string why;
  if (!section.valid(&why)) {
    // Name the offending key when the reason starts with it.
    const std::string bad = why.substr(0, why.find(' '));
    sub.fail(sub.has(bad) ? bad : "", key + "." + why);
  }
}

}  // namespace

CampusSettings read_campus_settings(const YAML::Node& node, const std::string& file, std::uint64_t* seed) {
  CampusSettings settings;
  SettingsReader in(node, file);
  if (seed) in.read("seed", *seed);
  visit_sections(settings, [&in](const char* name, auto& section) { read_section(in, name, section); });
  in.finish();
  return settings;
}

}  // namespace sextant::synth
