#include "strategies_causes.hpp"

#include <cmath>

#include "registration/row_keys.hpp"
#include "sextant/eval/statistics.hpp"
#include "sextant/eval/table.hpp"
#include "sextant/eval/verdict.hpp"

namespace sextant {
namespace {

std::vector<double> parameter_values(const std::vector<RegistrationError>& errors, std::size_t p) {
  std::vector<double> v;
  for (const RegistrationError& e : errors)
    if (e.finite) v.push_back(e.parameters[p]);
  return v;
}

/// The median over a method's rows of `seconds_align / kept_fraction`: matching time per point kept, in
/// units of the (same) scans' size.
double time_per_kept_point(const MethodRows& m) {
  std::vector<double> v;
  for (const RunRow* r : m.rows) {
    const double kept = r->value(keys::kKeptFraction), seconds = r->value(keys::kSecondsAlign);
    if (kept > 0 && std::isfinite(seconds)) v.push_back(seconds / kept);
  }
  return v.empty() ? NAN : median_of(v);
}

/// Of parameters 0 … count − 1, the one whose `statistic` of the values is largest (NaN: never chosen).
template <typename Statistic>
std::size_t largest_parameter(const std::vector<RegistrationError>& errors, std::size_t count,
                              Statistic statistic) {
  std::size_t worst = 0;
  double largest = -1;
  for (std::size_t p = 0; p < count; ++p) {
    const double value = statistic(parameter_values(errors, p));
    if (value > largest) largest = value, worst = p;
  }
  return worst;
}

double median_kept(const MethodRows& m) {
  std::vector<double> v;
  for (const RunRow* r : m.rows) v.push_back(r->value(keys::kKeptFraction));
  return v.empty() ? NAN : median_of(v);
}

}  // namespace

std::string sample_size_cause(const MethodRows* fbs, const MethodRows* gbs) {
  if (!fbs || !gbs) return "";
  return "data: the feature sample keeps " + format_number(100 * median_kept(*fbs), 1) +
         " % of the scan (median; GBS " + format_number(100 * median_kept(*gbs), 1) +
         " %; table 5.9's FBS matches 3.19 % of it), and per point kept its matching costs " +
         format_number(time_per_kept_point(*fbs) / time_per_kept_point(*gbs), 2) +
         "× GBS's: its time follows how much of the scan lies on cell-sized planes";
}

std::string sample_bias_cause(const std::vector<std::string>& names,
                              const std::vector<std::vector<RegistrationError>>& errors, std::size_t fbs) {
  if (fbs >= errors.size()) return "";
  const std::size_t worst = largest_parameter(
      errors[fbs], 3, [](const std::vector<double>& v) { return v.empty() ? NAN : std::abs(median_of(v)); });
  std::string list;
  for (std::size_t m = 0; m < errors.size(); ++m) {
    const std::vector<double> v = parameter_values(errors[m], worst);
    if (m != fbs && !v.empty())
      list += (list.empty() ? "" : ", ") + names[m] + " " + format_number(median_of(v), 1) + " cm";
  }
  const std::vector<double> f = parameter_values(errors[fbs], worst);
  if (f.empty()) return "";
  return "data: " + names[fbs] + "'s errors are biased in " + parameter_names()[worst] + ": median " +
         format_number(median_of(f), 1) + " cm (" + list + ")";
}

std::string heavy_tail_cause(const std::vector<std::string>& names,
                             const std::vector<std::vector<RegistrationError>>& errors, std::size_t fbs) {
  if (fbs >= errors.size()) return "";
  const std::size_t worst = largest_parameter(
      errors[fbs], 6, [](const std::vector<double>& v) { return jarque_bera(v).statistic; });
  std::string list;
  for (std::size_t m = 0; m < errors.size(); ++m)
    list += (list.empty() ? "" : ", ") + names[m] + " " +
            format_number(jarque_bera(parameter_values(errors[m], worst)).statistic, 0);
  return "data: every sampler's errors are heavy-tailed here, not FBS's alone: Jarque–Bera on " +
         parameter_names()[worst] + ": " + list + " (5 % critical value 5.99)";
}

}  // namespace sextant
