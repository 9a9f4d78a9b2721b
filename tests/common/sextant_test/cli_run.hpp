#pragma once
// Runs the `sextant` command line (the binary named by SEXTANT_CLI) for the end-to-end tests.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace sextant::test {

struct CliRun {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr
};

/// `sextant <arguments>` through the shell, its output and exit code (−1 when it did not exit).
inline CliRun run_cli(const std::string& cli, const std::string& arguments) {
  CliRun r;
  const std::string command = cli + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe)) r.output += buffer.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace sextant::test
