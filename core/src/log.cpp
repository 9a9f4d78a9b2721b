#include "sextant/core/log.hpp"

#include <atomic>
#include <iostream>
#include <mutex>

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

bool from_string(const std::string& text, LogLevel* out) {
  return from_name(kLogLevelNames, text, out);
}

std::string to_string(LogLevel level) {
  return name_of(kLogLevelNames, level);
}

void set_log_sink(std::ostream* sink) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_sink = sink;
}

void log(LogLevel level, const std::string& message) {
  if (level == LogLevel::off || static_cast<int>(level) < g_level.load()) return;
  const std::string line = "[" + to_string(level) + "] " + message + "\n";
  std::lock_guard<std::mutex> lock(g_mutex);
  std::ostream& out = g_sink ? *g_sink : std::cerr;
  out << line << std::flush;
}

}  // namespace sextant
