// The thesis' comparative claims of a plane_slam experiment, declared in params.claims and decided
// on our rows — the statement and the threshold come from the config, the verdict from intervals
// over the repetitions (verdict.hpp):
//
//   claims:
//     - {statement: "UKF's maximum error below the EKF's (thesis 4 m vs 8 m)", type: less,
//        a: ukf, b: [ekf], measure: max_error_m}
//     - {statement: "...", type: below, a: ukf, measure: max_error_m, value: 3.0}
//     - {statement: "...", type: ratio_in_band, a: ckf, b: [ukf], measure: max_error_m, band: [0.8, 1.25]}
//     - {statement: "...", type: in_band, a: seif, measure: final_error_m, band: [0.45, 1.8]}
//     - {statement: "...", type: fails_more, a: ukf, b: [ckf], point: "1000"}
//
//   less / greater    paired mean difference a − b (bootstrap over repetitions) < 0 / > 0, for every b
//   below / above     bootstrap median of a < value / > value
//   in_band           bootstrap median of a within band
//   ratio_in_band     bootstrap ratio of medians a / b within band
//   fails_more        share of repetitions with a failed filter step, a − b (Newcombe, paired) > 0
// `point` picks the sweep point (p0_scale label); default: the first.
#include <cmath>
#include <map>
#include <set>

#include "kit/row_keys.hpp"
#include "plane_slam/report.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/eval/verdict.hpp"

namespace sextant {
namespace {

struct DeclaredClaim {
  std::string statement, type, a, measure, point;
  std::vector<std::string> b;
  double value = NAN;
  std::vector<double> band;
};

const std::set<std::string>& claim_types() {
  static const std::set<std::string> types{"less",    "greater",       "below",     "above",
                                           "in_band", "ratio_in_band", "fails_more"};
  return types;
}

DeclaredClaim read_claim(const YAML::Node& node, const std::string& file,
                         const std::vector<std::string>& methods, const std::vector<std::string>& points) {
  SettingsReader in(node, file);
  DeclaredClaim c;
  in.require("statement", c.statement);
  in.require("type", c.type);
  in.require("a", c.a);
  in.read("measure", c.measure);
  in.read("point", c.point);
  if (in.has("b")) {
    const YAML::Node b = node["b"];
    if (b.IsScalar())
      c.b.push_back(b.Scalar());
    else
      in.read("b", c.b);
  }
  in.read("value", c.value);
  in.read("band", c.band);
  in.finish();
  if (!claim_types().count(c.type))
    in.fail("type", "key 'type': '" + c.type +
                        "' is not less, greater, below, above, in_band, ratio_in_band or fails_more");
  const auto known = [&](const std::string& m) {
    for (const auto& name : methods)
      if (name == m) return true;
    return false;
  };
  if (!known(c.a)) in.fail("a", "key 'a': '" + c.a + "' is not a method of this experiment");
  for (const auto& b : c.b)
    if (!known(b)) in.fail("b", "key 'b': '" + b + "' is not a method of this experiment");
  const bool pair =
      c.type == "less" || c.type == "greater" || c.type == "ratio_in_band" || c.type == "fails_more";
  if (pair && c.b.empty()) in.fail("b", "key 'b': type " + c.type + " compares a with b");
  if (c.type != "fails_more" && c.measure.empty()) in.fail("measure", "key 'measure': a row value name");
  if ((c.type == "below" || c.type == "above") && !std::isfinite(c.value))
    in.fail("value", "key 'value': type " + c.type + " needs a threshold");
  if ((c.type == "in_band" || c.type == "ratio_in_band") && (c.band.size() != 2 || !(c.band[0] < c.band[1])))
    in.fail("band", "key 'band': [lo, hi] with lo < hi");
  if (!c.point.empty() && points.size() > 0) {
    bool found = false;
    for (const auto& p : points) found = found || p == c.point;
    if (!found) in.fail("point", "key 'point': '" + c.point + "' is not a p0_scale value of the sweep");
  }
  return c;
}

std::vector<std::string> method_names(const ExperimentConfig& config) {
  std::vector<std::string> names;
  for (const auto& m : config.methods) names.push_back(m.name);
  return names;
}

std::vector<std::string> sweep_points(const ExperimentConfig& config) {
  std::vector<std::string> points;
  for (const auto& axis : config.sweep)
    for (const YAML::Node& v : axis.values) points.push_back(v.IsScalar() ? v.Scalar() : YAML::Dump(v));
  return points;
}

/// Per repetition: did the filter fail a step? Runs the failures ended count as failed.
std::map<int, bool> failed(const MethodRows& g) {
  std::map<int, bool> out;
  for (const RunRow* r : g.rows) {
    const double f = r->value(keys::kFailedSteps);
    out[r->repetition] = std::isfinite(f) && f > 0.0;
  }
  for (const RunRow* r : g.ended) out[r->repetition] = true;
  return out;
}

/// The repetitions both groups have, paired (compare_paired_successes pairs by index).
PairedRates paired_failures(const MethodRows& a, const MethodRows& b) {
  const std::map<int, bool> fa = failed(a), fb = failed(b);
  std::vector<bool> va, vb;
  for (const auto& [rep, f] : fa) {
    const auto it = fb.find(rep);
    if (it == fb.end()) continue;
    va.push_back(f);
    vb.push_back(it->second);
  }
  return compare_paired_successes(va, vb);
}

Claim decide(const DeclaredClaim& c, const PlaneSlamRows& data, std::uint64_t seed) {
  Claim out{c.statement, Verdict::not_comparable, "", ClaimKind::thesis};
  const std::string point = c.point.empty() ? data.points.front() : c.point;
  const MethodRows* a = data.find(c.a, point);
  if (!a || (a->rows.empty() && (c.type != "fails_more" || a->ended.empty()))) {
    out.evidence = "no finished runs of " + c.a;
    return out;
  }
  const std::string where = point.empty() ? "" : " at " + point_text(point);
  if (c.type == "below" || c.type == "above" || c.type == "in_band") {
    const Interval m = bootstrap_median(a->values(c.measure), seed);
    out.verdict = c.type == "below"   ? verdict_less(m, c.value)
                  : c.type == "above" ? verdict_greater(m, c.value)
                                      : verdict_in_band(m, c.band[0], c.band[1]);
    out.evidence = c.a + " median " + c.measure + where + " = " + describe(m) +
                   (c.type == "in_band" ? "; band [" + format_number(c.band[0], 2, "n/a") + ", " +
                                              format_number(c.band[1], 2, "n/a") + "]"
                                        : "; threshold " + format_number(c.value, 2, "n/a"));
    return out;
  }
  std::vector<Verdict> verdicts;
  for (const std::string& name : c.b) {
    const MethodRows* b = data.find(name, point);
    if (!b || (b->rows.empty() && (c.type != "fails_more" || b->ended.empty()))) {
      verdicts.push_back(Verdict::not_comparable);
      out.evidence += (out.evidence.empty() ? "" : "; ") + ("no finished runs of " + name);
      continue;
    }
    std::string text;
    if (c.type == "ratio_in_band") {
      const Interval r = bootstrap_ratio_of_medians(a->values(c.measure), b->values(c.measure), seed);
      verdicts.push_back(verdict_in_band(r, c.band[0], c.band[1]));
      text = c.a + "/" + name + " " + c.measure + " = " + describe(r, "×") + ", band [" +
             format_number(c.band[0], 2, "n/a") + ", " + format_number(c.band[1], 2, "n/a") + "]";
    } else if (c.type == "fails_more") {
      const PairedRates r = paired_failures(*a, *b);
      verdicts.push_back(verdict_greater(r.difference, 0.0));
      text = "runs with a failed step: " + describe(r);
    } else {
      const Interval d = bootstrap_paired_mean_difference(a->values(c.measure), b->values(c.measure), seed);
      verdicts.push_back(c.type == "less" ? verdict_less(d, 0.0) : verdict_greater(d, 0.0));
      text = c.a + " − " + name + " " + c.measure + " = " + describe(d);
    }
    out.evidence += (out.evidence.empty() ? "" : "; ") + text;
  }
  out.verdict = verdict_all(verdicts);
  out.evidence += where;
  return out;
}

}  // namespace

void check_plane_slam_claims(const ExperimentConfig& config, const PlaneSlamParams& params) {
  if (!params.claims || params.claims.IsNull()) return;
  for (const YAML::Node& node : params.claims)
    (void)read_claim(node, config.file, method_names(config), sweep_points(config));
}

std::vector<Claim> declared_claims(const ExperimentConfig& config, const PlaneSlamParams& params,
                                   const PlaneSlamRows& data) {
  std::vector<Claim> out;
  if (!params.claims || params.claims.IsNull()) return out;
  std::uint64_t seed = config.seed * 1000003u;
  for (const YAML::Node& node : params.claims)
    out.push_back(
        decide(read_claim(node, config.file, method_names(config), sweep_points(config)), data, ++seed));
  return out;
}

void check_plane_slam_reference(const ExperimentConfig& config) {
  const YAML::Node& ref = config.reference;
  if (!ref.IsDefined() || ref.IsNull()) return;
  if (!ref.IsMap()) throw InputError(config.file, at_line(yaml_line(ref)), "key 'reference' must be a map");
  // With a p0_scale sweep the thesis' numbers belong to one of its points (E13: P0 = 1e-6·I).
  const std::vector<std::string> points = sweep_points(config);
  if (!points.empty() && ref.size() > 0) {
    const YAML::Node at = ref["p0_scale"];
    if (!at.IsDefined())
      throw InputError(config.file, at_line(yaml_line(ref)),
                       "key 'reference': with a p0_scale sweep, say at which p0_scale the thesis' numbers "
                       "hold (reference.p0_scale)");
    bool found = false;
    for (const std::string& p : points) {
      try {
        found = found || (at.IsScalar() && std::stod(p) == at.as<double>());
      } catch (const std::exception&) {
      }
    }
    if (!found)
      throw InputError(config.file, at_line(yaml_line(at)),
                       "key 'p0_scale': '" + (at.IsScalar() ? at.Scalar() : std::string("?")) +
                           "' is not a p0_scale value of the sweep");
  }
  // Every leaf under reference is a number, null or text (table / figure ids); nested maps by name.
  for (const auto& entry : ref) {
    const YAML::Node v = entry.second;
    if (!v.IsMap()) continue;
    for (const auto& leaf : v) {
      if (leaf.second.IsNull() || !leaf.second.IsScalar()) continue;
      try {
        (void)leaf.second.as<double>();
      } catch (const YAML::Exception&) {
        throw InputError(
            config.file, at_line(yaml_line(leaf.second)),
            "key '" + leaf.first.as<std::string>() + "': '" + leaf.second.Scalar() + "' is not a number");
      }
    }
  }
}

}  // namespace sextant
