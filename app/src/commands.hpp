#pragma once
// Each `sextant` subcommand lives in its own file cli/cmd_<name>.cpp and registers itself with
// one add_<name>_command(app, exit_code) function declared here and called from main.cpp.
// The subcommand's callback sets exit_code = guarded([&] { ... return 0; }).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

namespace sextant::cli {

/// Exit status of every subcommand (docs/bad_input.md).
inline constexpr int kExitRuntimeError = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitUntrusted = 3;  ///< a registration that is not converged or not trusted

/// How much a subcommand prints besides its results and errors (main.cpp's -q/--quiet and
/// -v/--verbose): quiet leaves the results alone (no progress, notes or summaries), verbose adds
/// the detail behind them (match: the iterations; odometry: one line per step; eval: the drift per
/// segment length).
enum class Verbosity { kQuiet, kNormal, kVerbose };
Verbosity verbosity();
void set_verbosity(Verbosity v);

/// "sextant 0.1.0 (commit 1a2b3c4d5e6f, dirty)": --version and the first line of `sextant version`.
std::string version_line();

/// Runs a subcommand body: an exception becomes "sextant: error: <message>" on stderr and exit code 1.
int guarded(const std::function<int()>& body);

/// ./experiments when it exists, else the source tree's experiments/ (`reproduce`, `slurm reproduce`).
std::filesystem::path default_experiments_folder();

// One line per subcommand (keep sorted).
void add_convert_command(CLI::App& app, int& exit_code);
void add_eval_command(CLI::App& app, int& exit_code);
void add_info_command(CLI::App& app, int& exit_code);
void add_match_command(CLI::App& app, int& exit_code);
void add_merge_command(CLI::App& app, int& exit_code);
void add_odometry_command(CLI::App& app, int& exit_code);
void add_report_command(CLI::App& app, int& exit_code);
void add_reproduce_command(CLI::App& app, int& exit_code);
void add_run_command(CLI::App& app, int& exit_code);
void add_slurm_command(CLI::App& app, int& exit_code);
void add_synth_command(CLI::App& app, int& exit_code);
void add_version_command(CLI::App& app, int& exit_code);

}  // namespace sextant::cli
