#include "number_options.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

#include "sextant/core/threads.hpp"

namespace sextant::cli {
namespace {

std::string number_text(double value) {
  std::string text = std::to_string(value);
  text.erase(text.find_last_not_of('0') + 1);
  if (!text.empty() && text.back() == '.') text.pop_back();
  return text;
}

}  // namespace

CLI::Validator whole_number(std::uint64_t min, std::uint64_t max) {
  const std::string range = max == std::numeric_limits<std::uint64_t>::max()
                                ? "≥ " + std::to_string(min)
                                : "in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  return CLI::Validator(
      [min, max, range](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error == std::errc::result_out_of_range || (error == std::errc() && value > max))
          return "'" + text + "' is too large: expected a whole number " + range;
        if (error != std::errc() || end != text.data() + text.size() || value < min)
          return "expected a whole number " + range + ", got '" + text + "'";
        return "";
      },
      "COUNT " + range);
}

CLI::Validator finite_number(double min, bool strictly) {
  const std::string bound = (strictly ? "> " : "≥ ") + number_text(min);
  return CLI::Validator(
      [min, strictly, bound](std::string& text) -> std::string {
        errno = 0;
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size())
          return "expected a number " + bound + ", got '" + text + "'";
        if (!std::isfinite(value) || errno == ERANGE)
          return "expected a finite number " + bound + ", got '" + text + "'";
        if (strictly ? !(value > min) : !(value >= min))
          return "expected a number " + bound + ", got '" + text + "'";
        return "";
      },
      "NUMBER " + bound);
}

CLI::Validator worker_threads() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        long long jobs = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), jobs);
        if (error != std::errc() || end != text.data() + text.size())
          return "expected a number of threads (0: every core), got '" + text + "'";
        std::string problem = worker_threads_problem(jobs, "");
        return problem.empty() ? "" : problem.substr(2);  // without the argument: CLI11 names it
      },
      "THREADS 0 (every core) … " + std::to_string(max_worker_threads()));
}

}  // namespace sextant::cli
