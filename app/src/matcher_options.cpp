#include "matcher_options.hpp"

#include "sextant/core/settings_reader.hpp"

namespace sextant::cli {
namespace {

/// The flags as a request, with the --config file's maps (InputError naming the file).
MatcherRequest matcher_request(const MatcherOptions& o) {
  MatcherRequest r;
  r.method = o.method;
  r.preset = o.preset;
  r.solver = o.solver;
  r.sampling = o.sampling;
  if (!o.config.empty()) {
    SettingsReader in(load_yaml_file(o.config), o.config);
    r.matcher = in.child("matcher");
    r.sampler = in.child("sampler");
    in.finish();
  }
  r.matcher_where = o.config.empty() ? "matcher settings (--method, --preset, --solver)" : o.config;
  r.sampler_where = o.config.empty() ? "sampler settings (--sampling)" : o.config;
  return r;
}

}  // namespace

MatcherConfig read_matcher_config(const MatcherOptions& o, bool wide_basin) {
  return sextant::read_matcher_config(matcher_request(o), Face::cli, wide_basin);
}

}  // namespace sextant::cli
