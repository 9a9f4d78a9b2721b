#include "sextant/core/error.hpp"

namespace sextant {
namespace {

std::string compose(const std::string& file, const std::string& where, const std::string& problem) {
  std::string message = file;
  if (!where.empty()) message += ":" + where;
  return message + ": " + problem;
}

}  // namespace

InputError::InputError(std::string file, std::string where, std::string problem)
    : std::runtime_error(compose(file, where, problem)),
      file_(std::move(file)),
      where_(std::move(where)),
      problem_(std::move(problem)) {}

std::string at_line(long line) {
  return "line " + std::to_string(line);
}
std::string at_byte(long long offset) {
  return "byte " + std::to_string(offset);
}

}  // namespace sextant
