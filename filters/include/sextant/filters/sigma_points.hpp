#pragma once
// Sigma-point rules as interchangeable parts of one sigma-point filter. A rule gives points ξᵢ
// in standard-normal space with mean and covariance weights; the filter maps them through
// x̄ + L·ξᵢ with P = L·Lᵀ (Cholesky). The point set of N_max stochastic-integration iterations
// is the union of every iteration's points with weights divided by N_max, which is exactly
// the running mean μ ← μ + (S − μ)/i of Table 4.4.
#include <memory>
#include <string>

#include <Eigen/Core>

#include "sextant/core/rng.hpp"

namespace sextant {

struct SigmaPoints {
  Eigen::MatrixXd xi;  ///< n × m, one point per column, standard-normal space
  Eigen::VectorXd wm;  ///< mean weights (sum 1)
  Eigen::VectorXd wc;  ///< covariance weights
};

class SigmaPointRule {
 public:
  virtual ~SigmaPointRule() = default;
  virtual std::string name() const = 0;
  /// Points for an n-dimensional Gaussian; random rules draw from rng.
  virtual SigmaPoints generate(int n, Rng& rng) const = 0;
  /// The rule and its parameters in words, e.g. "unscented: 2n+1 points, α = 1, β = 0, κ = 3 − n".
  virtual std::string parameters() const = 0;
};

/// Unscented transform (Tables 4.2–4.3): 2n+1 points ±√(n+λ)·eᵢ, λ = α²(n+κ) − n.
/// The defaults (α = 1, β = 2, κ = 0) put the 2n outer points at ±√n·eᵢ with weight 1/(2n): the
/// cubature points, with a zero-weight centre (covariance weight β). The thesis' UKF is Julier and
/// Uhlmann's: κ = 3 − n with α = 1, β = 0 (n + κ = 3, eq. 4.84); its centre weight (3 − n)/3 is
/// negative for n > 3 — exact on linear models (tests/filters), indefinite covariances when P is
/// large against the models' curvature (§5.2.1.2, fig. 5.31).
struct UnscentedSettings {
  double alpha = 1.0;  ///< spread of the points (thesis-era default 1e-3 gives a large negative W₀)
  double beta = 2.0;   ///< prior knowledge of the distribution (2 is optimal for Gaussians)
  double kappa = 0.0;  ///< secondary scaling
  bool kappa_three_minus_n = false;  ///< Julier's heuristic κ = 3 − n instead (negative W₀ for n > 3)
  bool valid(std::string* why) const;
  /// "α = 1, β = 0, κ = 3 − n" (the parameters as set).
  std::string describe() const;
};

/// Cubature rule (eqs. 4.69–4.70): 2n points ±√n·eᵢ, weights 1/(2n).
/// Stochastic integration rule (Table 4.4): per iteration a uniformly random orthogonal Q and a
/// radius ρ ~ χ(n+2); points ±ρ·Q·eᵢ with weights 1/(2ρ²) and the centre with 1 − n/ρ².
struct StochasticIntegrationSettings {
  int iterations = 20;  ///< N_max
  bool valid(std::string* why) const;
};

std::unique_ptr<SigmaPointRule> make_unscented_rule(const UnscentedSettings& settings);
std::unique_ptr<SigmaPointRule> make_cubature_rule();
std::unique_ptr<SigmaPointRule> make_stochastic_integration_rule(
    const StochasticIntegrationSettings& settings);

/// A uniformly (Haar) distributed random orthogonal n × n matrix.
Eigen::MatrixXd random_orthogonal(int n, Rng& rng);
/// A draw from the χ distribution with k degrees of freedom.
double chi_sample(int k, Rng& rng);

}  // namespace sextant
