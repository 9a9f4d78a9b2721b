#pragma once
// Each `sextant` subcommand lives in its own file and adds itself to the app here.
#include <CLI/CLI.hpp>

namespace sextant::cli {

/// Runs a subcommand body: an exception becomes a message on stderr and exit code 1.
int guarded(const std::function<int()>& body);

}  // namespace sextant::cli
