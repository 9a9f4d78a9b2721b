// The rigid transforms a user gives `sextant match` (transform_argument.hpp).
#include "transform_argument.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"

namespace sextant::cli {
namespace {

/// A guess beyond this is no guess between two scans (PCL's peers abort the process on 1e39) [m].
constexpr double kMaxGuessMetres = 1e6;

/// A 3×4 or 4×4 row-major matrix (12 or 16 numbers) as a rigid transform; InputError at `where`.
Eigen::Isometry3d rigid_matrix(const std::vector<double>& values, const std::string& where) {
  if (values.size() != 12 && values.size() != 16)
    throw InputError(where, "",
                     "expected 12 (3×4) or 16 (4×4) numbers, found " + std::to_string(values.size()));
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  for (std::size_t i = 0; i < values.size(); ++i)
    M(static_cast<int>(i / 4), static_cast<int>(i % 4)) = values[i];
  if (!M.allFinite() || !M.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1)))
    throw InputError(where, "", "the matrix is not finite or its last row is not 0 0 0 1");
  if (const std::string why = rigid_problem(M.topLeftCorner<3, 3>(), M.topRightCorner<3, 1>()); !why.empty())
    throw InputError(where, "", "not a rigid transform: " + why);
  Eigen::Isometry3d T;
  T.matrix() = M;
  return T;
}

/// The numbers of `text`, separated by commas and/or white space; InputError naming the first
/// that is not one.
std::vector<double> numbers_in(const std::string& text, const std::string& where,
                               const std::string& expected) {
  std::vector<double> values;
  std::string item;
  std::stringstream in(text);
  while (in >> item) {
    std::stringstream parts(item);
    for (std::string part; std::getline(parts, part, ',');) {
      if (part.empty()) continue;
      try {
        std::size_t used = 0;
        values.push_back(std::stod(part, &used));
        if (used != part.size()) throw std::invalid_argument(part);
      } catch (const std::exception&) {
        throw InputError(where, "", "'" + part + "' is not a number (expected " + expected + ")");
      }
    }
  }
  return values;
}

std::string file_text(const std::string& file, const std::string& what) {
  std::ifstream in(file);
  if (!in) throw InputError(file, "", "cannot open the " + what);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

Eigen::Isometry3d parse_init(const std::string& text) {
  const char* expected = "x,y,z,alpha,beta,gamma in m and deg, a 3×4 or 4×4 matrix, or a matrix file";
  const bool file = std::filesystem::is_regular_file(text);
  const std::string where = file ? text : "--init";
  const std::vector<double> values =
      numbers_in(file ? file_text(text, "--init matrix file") : text, where, expected);
  Eigen::Isometry3d T;
  if (values.size() == 6 && !file) {
    if (!Eigen::Map<const Vector6d>(values.data()).allFinite())
      throw InputError("--init", "",
                       "expected six finite numbers x,y,z,alpha,beta,gamma (m, deg), got '" + text + "'");
    T = to_isometry(Pose6{values[0], values[1], values[2], values[3] / kDegPerRad, values[4] / kDegPerRad,
                          values[5] / kDegPerRad});
  } else if (values.size() == 12 || values.size() == 16) {
    T = rigid_matrix(values, where);
  } else {
    throw InputError(
        where, "",
        "expected " + std::string(expected) + "; found " + std::to_string(values.size()) + " numbers");
  }
  if (T.translation().norm() > kMaxGuessMetres)
    throw InputError("--init", "",
                     "the translation is farther than 10^6 m (" + text + "): not a guess between two scans");
  return T;
}

Eigen::Isometry3d read_ground_truth(const std::string& file) {
  return rigid_matrix(numbers_in(file_text(file, "ground-truth matrix file"), file, "a 3×4 or 4×4 matrix"),
                      file);
}

}  // namespace sextant::cli
