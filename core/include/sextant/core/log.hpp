#pragma once
// A small leveled logger writing "[level] message" lines to stderr (thread-safe: one write per
// line). The level is process-wide and set once by the program (e.g. from `--log-level`);
// libraries only log, they never change it.
#include <ostream>
#include <string>

#include "sextant/core/enum_names.hpp"

namespace sextant {

enum class LogLevel { debug = 0, info = 1, warning = 2, error = 3, off = 4 };

/// Messages below this level are dropped; default LogLevel::info.
void set_log_level(LogLevel level);
LogLevel log_level();
/// "debug", "info", "warning" (or "warn"), "error", "off".
inline constexpr EnumNames<LogLevel, 6> kLogLevelNames{"log level",
                                                       {{{LogLevel::debug, "debug"},
                                                         {LogLevel::info, "info"},
                                                         {LogLevel::warning, "warning"},
                                                         {LogLevel::warning, "warn"},
                                                         {LogLevel::error, "error"},
                                                         {LogLevel::off, "off"}}}};
bool from_string(const std::string& text, LogLevel* out);
std::string to_string(LogLevel level);

/// Redirects the log (default std::cerr); nullptr restores stderr. For tests.
void set_log_sink(std::ostream* sink);

void log(LogLevel level, const std::string& message);
inline void log_debug(const std::string& message) {
  log(LogLevel::debug, message);
}
inline void log_info(const std::string& message) {
  log(LogLevel::info, message);
}
inline void log_warning(const std::string& message) {
  log(LogLevel::warning, message);
}
inline void log_error(const std::string& message) {
  log(LogLevel::error, message);
}

}  // namespace sextant
