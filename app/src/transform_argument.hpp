#pragma once
// A rigid transform a user gives `sextant match`: --init (six numbers, a 3×4 or 4×4 row-major matrix,
// or a file holding one) and --gt (a matrix file). Every problem is an InputError naming the argument
// or the file.
#include <string>

#include <Eigen/Geometry>

namespace sextant::cli {

/// --init: x,y,z,alpha,beta,gamma [m, deg]; 12 or 16 numbers (a 3×4 or 4×4 row-major matrix, as PCL and
/// small_gicp users hold it); or a file holding such a matrix. At most 10⁶ m of translation.
Eigen::Isometry3d parse_init(const std::string& text);

/// A 3×4 or 4×4 row-major matrix text file (whitespace separated) mapping input into reference.
Eigen::Isometry3d read_ground_truth(const std::string& file);

}  // namespace sextant::cli
