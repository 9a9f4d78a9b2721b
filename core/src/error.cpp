#include "sextant/core/error.hpp"

#include <cstring>

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

FileError::FileError(std::string file, std::string problem, int error_number)
    : InputError(std::move(file), "", std::move(problem)), error_number_(error_number) {}

FileError FileError::from_errno(std::string file, const std::string& what, int error_number) {
  return FileError(std::move(file), error_number ? what + ": " + std::strerror(error_number) : what,
                   error_number);
}

std::string at_line(long line) {
  return "line " + std::to_string(line);
}
std::string at_byte(long long offset) {
  return "byte " + std::to_string(offset);
}

}  // namespace sextant
