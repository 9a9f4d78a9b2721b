#include "sextant/filters/sigma_points.hpp"

#include <cmath>
#include <cstdio>

#include <Eigen/QR>

namespace sextant {
namespace {

// Symmetric set: centre (column 0) then +s·eᵢ and −s·eᵢ.
Eigen::MatrixXd symmetric_points(int n, double scale, bool with_centre) {
  const int first = with_centre ? 1 : 0;
  Eigen::MatrixXd xi = Eigen::MatrixXd::Zero(n, 2 * n + first);
  for (int i = 0; i < n; ++i) {
    xi(i, first + i) = scale;
    xi(i, first + n + i) = -scale;
  }
  return xi;
}

class UnscentedRule final : public SigmaPointRule {
 public:
  explicit UnscentedRule(UnscentedSettings s) : s_(s) {}
  std::string name() const override { return "unscented"; }
  // Table 4.2: χ₀ = x̄, χᵢ = x̄ ± {√((n+λ)P)}ᵢ, W₀ᵐ = λ/(n+λ), W₀ᶜ = W₀ᵐ + 1 − α² + β, Wᵢ = 1/(2(n+λ)).
  SigmaPoints generate(int n, Rng& /*rng*/) const override {
    const double kappa = s_.kappa_three_minus_n ? 3.0 - n : s_.kappa;
    const double lambda = s_.alpha * s_.alpha * (n + kappa) - n;
    SigmaPoints sp;
    sp.xi = symmetric_points(n, std::sqrt(n + lambda), true);
    sp.wm = Eigen::VectorXd::Constant(2 * n + 1, 0.5 / (n + lambda));
    sp.wm[0] = lambda / (n + lambda);
    sp.wc = sp.wm;
    sp.wc[0] += 1.0 - s_.alpha * s_.alpha + s_.beta;
    return sp;
  }
  std::string parameters() const override { return "unscented (Table 4.2): 2n+1 points, " + s_.describe(); }

 private:
  UnscentedSettings s_;
};

class CubatureRule final : public SigmaPointRule {
 public:
  std::string name() const override { return "cubature"; }
  // eqs. (4.69)–(4.70): ζ = √n·{±eᵢ}, weights 1/(2n).
  SigmaPoints generate(int n, Rng& /*rng*/) const override {
    SigmaPoints sp;
    sp.xi = symmetric_points(n, std::sqrt(static_cast<double>(n)), false);
    sp.wm = Eigen::VectorXd::Constant(2 * n, 0.5 / n);
    sp.wc = sp.wm;
    return sp;
  }
  std::string parameters() const override {
    return "cubature (eqs. 4.69-4.70): 2n points ±√n·eᵢ, weights 1/(2n); no free parameter";
  }
};

class StochasticIntegrationRule final : public SigmaPointRule {
 public:
  explicit StochasticIntegrationRule(StochasticIntegrationSettings s) : s_(s) {}
  std::string name() const override { return "stochastic_integration"; }
  // Table 4.4 (Genz–Monahan): per iteration χ = ∓ρ·Q·eᵢ, w₀ = 1 − n/ρ², wᵢ = 1/(2ρ²); the
  // N_max iterations are averaged, so all points share the weight 1/N_max and the centre
  // collects the sum of the w₀.
  SigmaPoints generate(int n, Rng& rng) const override {
    const int N = s_.iterations;
    SigmaPoints sp;
    sp.xi = Eigen::MatrixXd::Zero(n, 1 + 2 * n * N);
    sp.wm = Eigen::VectorXd::Zero(1 + 2 * n * N);
    for (int it = 0; it < N; ++it) {
      const Eigen::MatrixXd Q = random_orthogonal(n, rng);
      const double rho = chi_sample(n + 2, rng);
      const Eigen::Index base = 1 + 2 * static_cast<Eigen::Index>(n) * it;
      sp.xi.middleCols(base, n) = -rho * Q;
      sp.xi.middleCols(base + n, n) = rho * Q;
      sp.wm.segment(base, 2 * n).setConstant(0.5 / (rho * rho) / N);
      sp.wm[0] += (1.0 - n / (rho * rho)) / N;
    }
    sp.wc = sp.wm;
    return sp;
  }
  std::string parameters() const override {
    return "stochastic integration (Table 4.4): N_max = " + std::to_string(s_.iterations) +
           " draws of 2n points ±ρ·Q·eᵢ (random Q, ρ ~ χ(n+2)) and the centre";
  }

 private:
  StochasticIntegrationSettings s_;
};

}  // namespace

bool UnscentedSettings::valid(std::string* why) const {
  if (!(alpha > 0.0)) return *why = "alpha must be > 0", false;
  if (!std::isfinite(beta) || !std::isfinite(kappa)) return *why = "beta and kappa must be finite", false;
  if (!kappa_three_minus_n && !(kappa > -1.0))
    return *why = "kappa must be > -1 (n + kappa > 0 for n >= 1)", false;
  return true;
}

std::string UnscentedSettings::describe() const {
  const auto number = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return std::string(buffer);
  };
  return "α = " + number(alpha) + ", β = " + number(beta) +
         ", κ = " + (kappa_three_minus_n ? std::string("3 − n") : number(kappa));
}

bool StochasticIntegrationSettings::valid(std::string* why) const {
  if (iterations < 1) return *why = "iterations (N_max) must be >= 1", false;
  return true;
}

std::unique_ptr<SigmaPointRule> make_unscented_rule(const UnscentedSettings& settings) {
  return std::make_unique<UnscentedRule>(settings);
}
std::unique_ptr<SigmaPointRule> make_cubature_rule() {
  return std::make_unique<CubatureRule>();
}
std::unique_ptr<SigmaPointRule> make_stochastic_integration_rule(
    const StochasticIntegrationSettings& settings) {
  return std::make_unique<StochasticIntegrationRule>(settings);
}

// QR of a Gaussian matrix with the signs of R's diagonal moved into Q (Mezzadri's recipe).
Eigen::MatrixXd random_orthogonal(int n, Rng& rng) {
  Eigen::MatrixXd G(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) G(i, j) = rng.normal();
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(G);
  Eigen::MatrixXd Q = qr.householderQ();
  const Eigen::MatrixXd R = qr.matrixQR();
  for (int j = 0; j < n; ++j)
    if (R(j, j) < 0.0) Q.col(j) = -Q.col(j);
  return Q;
}

double chi_sample(int k, Rng& rng) {
  double sum = 0.0;
  for (int i = 0; i < k; ++i) {
    const double g = rng.normal();
    sum += g * g;
  }
  return std::sqrt(sum);
}

}  // namespace sextant
