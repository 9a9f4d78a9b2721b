// `sextant synth --out DIR [--scans N] [--seed S] [--config FILE] [--preview FILE]`: writes the
// built-in synthetic campus (docs/synthetic_campus.md) as a uos folder.
#include <chrono>
#include <iostream>
#include <memory>
#include <string>

#include "commands.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/synth/campus_io.hpp"

namespace sextant::cli {
namespace {

struct SynthOptions {
  std::string out;
  std::string config;
  std::string preview;
  int scans = -1;  ///< −1: keep the configured number
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
  if (o.scans >= 0) settings.trajectory.scans = o.scans;
  std::string why;
  if (!settings.valid(&why)) throw InputError("--scans", "", why);
  const auto start = std::chrono::steady_clock::now();
  const synth::Campus campus = synth::generate_campus(settings, seed);
  synth::write_campus(campus, o.out);
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
  cmd->add_option("--scans", options->scans, "Number of scans (default: the configured 468)");
  auto* seed = cmd->add_option("--seed", options->seed, "Random seed (default 1, or the config's seed)");
  cmd->add_option("--config", options->config,
                  "YAML campus settings (world, trajectory, sensor, odometry, gnss)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--preview", options->preview, "Also write a top-down SVG preview to this file");
  cmd->add_option("--preview-scan", options->preview_scan, "Scan drawn in the preview (default 0)");
  cmd->callback([options, seed, &exit_code] {
    options->seed_given = seed->count() > 0;
    exit_code = guarded([&] { return run_synth(*options); });
  });
}

}  // namespace sextant::cli
