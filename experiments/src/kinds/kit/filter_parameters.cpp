#include "kit/filter_parameters.hpp"

#include "sextant/filters/filter.hpp"

namespace sextant {

Table sigma_point_table(const std::vector<FilterMethodSettings>& methods,
                        const std::shared_ptr<const SlamModel>& model) {
  Table t;
  t.caption = "Each filter's sigma-point rule and its parameters";
  t.label = "sigma_points";
  t.note =
      "n is the size of the vector each transform draws points for: the state and the control (prediction, "
      "Table 4.2), the state (update) or the state and the new observation (augmentation, Table 4.3). "
      "Unscented: λ = α²(n + κ) − n, points x̄ ± √(n + λ)·(√P)ᵢ, W₀ᵐ = λ/(n + λ), W₀ᶜ = W₀ᵐ + 1 − α² + β, "
      "Wᵢ = 1/(2(n + λ)). κ = 3 − n is Julier and Uhlmann's choice (the UKF of the thesis' time, eq. 4.84): "
      "points at ±√3 and a centre weight (3 − n)/3 < 0. α = 1, κ = 0 gives the cubature points (eq. 4.70) "
      "with a centre of mean weight 0.";
  t.add_column("method").add_column("filter").add_column("sigma points and parameters");
  for (const FilterMethodSettings& m : methods)
    t.add_row({Cell::text(m.method), Cell::text(m.filter.name()),
               Cell::text(make_filter(m.filter, model)->approximation())});
  return t;
}

bool has_sigma_point_filter(const std::vector<FilterMethodSettings>& methods) {
  for (const FilterMethodSettings& m : methods)
    if (m.filter.get<UkfSettings>() || m.filter.get<CkfSettings>() || m.filter.get<RspkfSettings>())
      return true;
  return false;
}

}  // namespace sextant
