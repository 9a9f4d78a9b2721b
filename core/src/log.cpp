#include "sextant/core/log.hpp"

#include <atomic>
#include <iostream>
#include <mutex>
#include <stdexcept>

namespace sextant {
namespace {

std::atomic<int> g_level{static_cast<int>(LogLevel::info)};
std::mutex g_mutex;
std::ostream* g_sink = nullptr;  // guarded by g_mutex; nullptr = std::cerr

}  // namespace

void set_log_level(LogLevel level) {
  g_level = static_cast<int>(level);
}
LogLevel log_level() {
  return static_cast<LogLevel>(g_level.load());
}

LogLevel parse_log_level(const std::string& name) {
  if (name == "debug") return LogLevel::debug;
  if (name == "info") return LogLevel::info;
  if (name == "warning" || name == "warn") return LogLevel::warning;
  if (name == "error") return LogLevel::error;
  if (name == "off") return LogLevel::off;
  throw std::invalid_argument("unknown log level '" + name + "' (known: debug info warning error off)");
}

const char* log_level_name(LogLevel level) {
  switch (level) {
    case LogLevel::debug: return "debug";
    case LogLevel::info: return "info";
    case LogLevel::warning: return "warning";
    case LogLevel::error: return "error";
    case LogLevel::off: return "off";
  }
  return "?";
}

void set_log_sink(std::ostream* sink) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_sink = sink;
}

void log(LogLevel level, const std::string& message) {
  if (level == LogLevel::off || static_cast<int>(level) < g_level.load()) return;
  const std::string line = std::string("[") + log_level_name(level) + "] " + message + "\n";
  std::lock_guard<std::mutex> lock(g_mutex);
  std::ostream& out = g_sink ? *g_sink : std::cerr;
  out << line << std::flush;
}

}  // namespace sextant
