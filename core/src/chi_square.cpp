#include "sextant/core/chi_square.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

#include <cmath>
#include <stdexcept>

namespace sextant {

double chi_square_cdf(double x, double dof) {
  if (!(dof > 0.0)) throw std::invalid_argument("chi_square_cdf: dof must be > 0");
  if (!(x > 0.0)) return 0.0;
  if (std::isinf(x)) return 1.0;
  return boost::math::cdf(boost::math::chi_squared_distribution<double>(dof), x);
}

double chi_square_quantile(double p, double dof) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("chi_square_quantile: p must lie in (0, 1)");
  if (!(dof > 0.0) || std::isinf(dof)) throw std::invalid_argument("chi_square_quantile: dof must be > 0");
  return boost::math::quantile(boost::math::chi_squared_distribution<double>(dof), p);
}

double normal_quantile(double p) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("normal_quantile: p must lie in (0, 1)");
  return boost::math::quantile(boost::math::normal_distribution<double>(), p);
}

}  // namespace sextant
