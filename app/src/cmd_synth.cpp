// `sextant synth --out DIR [--scans N] [--stretch-route-to M] [--seed S] [--config FILE]
// [--preview FILE]`: writes the built-in synthetic campus (docs/synthetic_campus.md) as a uos
// folder. --scans keeps the first N scans of the route (trajectory.first_scans); the route keeps
// its spacing. --stretch-route-to divides the whole route into M scans (trajectory.scans).
#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "number_options.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/output_folder.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/synth/campus_io.hpp"
#include "sextant/synth/yaml.hpp"

namespace sextant::cli {
namespace {

struct SynthOptions {
  std::string out;
  std::string config;
  std::string preview;
  int scans = -1;    ///< −1: keep the configured number (trajectory.first_scans)
  int stretch = -1;  ///< −1: keep the configured route division (trajectory.scans)
  std::uint64_t seed = 1;
  bool seed_given = false;
  std::size_t preview_scan = 0;
};

int run_synth(const SynthOptions& o) {
  std::uint64_t seed = o.seed;
  synth::CampusSettings settings;
  if (!o.config.empty()) {
    std::uint64_t config_seed = seed;
    settings = synth::read_campus_settings(load_yaml_file(o.config), o.config, &config_seed);
    if (!o.seed_given) seed = config_seed;
  }
  if (o.stretch >= 0) {
    if (o.stretch < 1) throw InputError("--stretch-route-to", "", "must be at least 1");
    settings.trajectory.scans = o.stretch;
    if (o.scans < 0 && settings.trajectory.first_scans > o.stretch)
      throw InputError("--stretch-route-to", "",
                       "the config keeps the first " + std::to_string(settings.trajectory.first_scans) +
                           " scans, more than the " + std::to_string(o.stretch) + " of the stretched route");
  }
  if (o.scans >= 0) {
    if (o.scans < 1 || o.scans > settings.trajectory.scans)
      throw InputError("--scans", "",
                       "must be in [1, " + std::to_string(settings.trajectory.scans) +
                           "], the scans of the route (--stretch-route-to changes the route's division)");
    settings.trajectory.first_scans = o.scans;
  }
  std::string why;
  if (!settings.valid(&why)) throw InputError(o.config.empty() ? "--scans" : o.config, "", why);
  OutputFolder folder(o.out, "sextant synth");
  const auto start = std::chrono::steady_clock::now();
  const synth::Campus campus = synth::generate_campus(settings, seed);
  synth::write_campus(campus, folder.staging());
  folder.commit();
  if (!o.preview.empty()) {
    if (o.preview_scan >= campus.size()) throw InputError("--preview-scan", "", "no such scan");
    synth::write_campus_preview_svg(campus, o.preview_scan, o.preview);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "wrote " << campus.size() << " scans, " << campus.world->landmarks.size()
            << " landmarks (seed " << seed << ") to " << o.out << " in " << seconds << " s\n";
  return 0;
}

}  // namespace

void add_synth_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SynthOptions>();
  auto* cmd = app.add_subcommand("synth", "Write the built-in synthetic campus dataset (uos layout)");
  cmd->add_option("--out", options->out, "Output folder")->required();
  cmd->add_option("--scans", options->scans,
                  "Write only the first N scans of the route (default: all; the route keeps its spacing)")
      ->check(whole_number(1, synth::kMaxRouteScans));
  cmd->add_option("--stretch-route-to", options->stretch,
                  "Divide the whole route into M scans instead of 468 (M = 30 puts scans ~45 m apart)")
      ->check(whole_number(1, synth::kMaxRouteScans));
  auto* seed = cmd->add_option("--seed", options->seed, "Random seed (default 1, or the config's seed)")
                   ->check(whole_number());
  cmd->add_option("--config", options->config,
                  "YAML campus settings (world, trajectory, sensor, odometry, gnss)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--preview", options->preview, "Also write a top-down SVG preview to this file");
  cmd->add_option("--preview-scan", options->preview_scan, "Scan drawn in the preview (default 0)")
      ->check(whole_number());
  cmd->callback([options, seed, &exit_code] {
    options->seed_given = seed->count() > 0;
    exit_code = guarded([&] { return run_synth(*options); });
  });
}

}  // namespace sextant::cli
