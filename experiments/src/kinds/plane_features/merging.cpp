// E10 (§4.1, table 4.1, figs 4.1–4.2): three synthetic planes with normal [0 1 0] and
// d ~ N(0, 0.2) (variance 0.2, per point) spanning x and the in-plane axis z; case 2 shifts
// planes 2 and 3 by 5 units along y. One run = one repetition: both cases from the same noise,
// drawn from Rng(seed + repetition) (repetition 0 is the fixed-seed table; the others give the
// claims their intervals). C_p is the Mahalanobis distance with the pooled covariance of
// eq. (4.53), the square root of the thesis' printed quadratic form (merging.hpp says why).
//
//   params:
//     study: merging
//     noise_variance: 0.2
//     planes: [{x: [0, 10, 2], z: [0, 10, 2]}, {x: [15, 25, 1], z: [0, 10, 1]}, {x: [15, 45, 1], z: [0, 10,
//     1]}] case2_shift: 5           # planes 2 and 3 move this far along y in case 2 thresholds:
//     {orientation_deg: 15, translation: 0.75, closeness: 10}
//   reference: {case1: {"1-2": [C_o, C_t, C_p, d_c], "1-3": [...]}, case2: {...}, jump_band_factor: 2}
#include <cmath>

#include "kit/number_format.hpp"
#include "kit/reference_values.hpp"
#include "plane_features/layouts/layouts.hpp"
#include "plane_features/merging.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/eval/verdict.hpp"
#include "sextant/features/merging.hpp"
#include "sextant/features/yaml.hpp"

namespace sextant {
namespace {

Grid read_grid(SettingsReader& in, const std::string& key) {
  std::vector<double> v;
  in.require(key, v);
  if (v.size() != 3 || !(v[2] > 0) || v[1] < v[0])
    in.fail(key, "key '" + key + "': [from, to, step] with from <= to and step > 0");
  return {v[0], v[1], v[2]};
}

MergingParams read_merging_params(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  std::string study;
  in.read("study", study);
  MergingParams p;
  in.read("noise_variance", p.noise_variance);
  const YAML::Node planes = in.child("planes");
  if (!planes.IsSequence() || planes.size() != 3) in.fail("planes", "key 'planes': three planes {x, z}");
  for (const auto& plane : planes) {
    SettingsReader pin(plane, config.file);
    const Grid x = read_grid(pin, "x"), z = read_grid(pin, "z");
    pin.finish();
    p.planes.emplace_back(x, z);
  }
  in.read("case2_shift", p.case2_shift);
  p.thresholds = read_merge_thresholds(in.child("thresholds"), config.file);
  in.finish();
  if (!(p.noise_variance >= 0)) in.fail("noise_variance", "key 'noise_variance' must be >= 0");
  return p;
}

const char* const kPairs[2] = {"12", "13"};
const char* const kCriteria[4] = {"co", "ct", "cp", "dc"};

std::string key(int c, int pair, const char* criterion) {
  return "case" + std::to_string(c) + "_" + kPairs[pair] + "_" + criterion;
}

class MergingSession : public KindSession {
 public:
  MergingSession(MergingParams p, std::uint64_t seed) : p_(std::move(p)), seed_(seed) {}
  void run(const RunSpec& run, RunRow& row) const override {
    for (int c = 1; c <= 2; ++c) {
      const std::vector<PlaneLandmark> planes =
          make_case(p_, c, seed_ + static_cast<std::uint64_t>(run.repetition)).planes;
      for (int pair = 0; pair < 2; ++pair) {
        const MergeCriteria m =
            merge_criteria(planes[0], planes[static_cast<std::size_t>(pair + 1)], p_.thresholds.min_variance);
        const double v[4] = {m.orientation_deg, m.translation, m.closeness, m.centre_distance};
        for (int k = 0; k < 4; ++k) row.values[key(c, pair, kCriteria[k])] = v[k];
        row.values[key(c, pair, "passes")] = m.passes(p_.thresholds) ? 1.0 : 0.0;
      }
      row.values["case" + std::to_string(c) + "_merged_planes"] =
          static_cast<double>(merge_planes(planes, p_.thresholds).planes.size());
    }
  }

 private:
  MergingParams p_;
  std::uint64_t seed_;
};

/// reference.caseN["1-2"] = [C_o, C_t, C_p, d_c] (or missing).
std::vector<double> reference_row(const YAML::Node& reference, int c, int pair) {
  const YAML::Node block =
      child_or_null(child_or_null(reference, "case" + std::to_string(c)), pair == 0 ? "1-2" : "1-3");
  if (!block.IsSequence() || block.size() != 4) return std::vector<double>(4, NAN);
  std::vector<double> v;
  for (const auto& x : block) v.push_back(x.as<double>());
  return v;
}

}  // namespace

void validate_merging_study(const ExperimentConfig& config) {
  (void)read_merging_params(config);
  for (const auto& m : config.methods) {
    SettingsReader in(m.node, config.file);
    std::string name;
    in.require("name", name);
    in.finish();
  }
  if (config.methods.size() != 1 || !config.sweep.empty())
    throw InputError(config.file, "", "key 'methods': the merging study takes one method and no sweep");
  SettingsReader ref(config.reference, config.file);
  for (const char* c : {"case1", "case2"}) {
    std::map<std::string, std::vector<double>> rows;
    ref.read(c, rows);
    for (const auto& [pair, v] : rows)
      if ((pair != "1-2" && pair != "1-3") || v.size() != 4)
        ref.fail(c, std::string("key '") + c + "': pairs \"1-2\", \"1-3\" of [C_o, C_t, C_p, d_c]");
  }
  double factor = 2;
  ref.read("jump_band_factor", factor);
  ref.finish();
  if (!(factor > 1)) ref.fail("jump_band_factor", "key 'jump_band_factor' must be > 1");
}

std::unique_ptr<KindSession> prepare_merging_study(const ExperimentConfig& config) {
  return std::make_unique<MergingSession>(read_merging_params(config), config.seed);
}

ReportSection merging_study_report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                                   const std::vector<const RunRow*>& rows) {
  const MergingParams p = read_merging_params(config);
  std::vector<const RunRow*> ok;
  const RunRow* first = nullptr;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (!rows[i] || !rows[i]->ok) continue;
    ok.push_back(rows[i]);
    if (runs[i].repetition == 0) first = rows[i];
  }
  const auto values = [&](const std::string& name) {
    std::vector<double> v;
    for (const RunRow* r : ok) v.push_back(r->value(name));
    return v;
  };
  ReportSection section;
  section.notes = "Planes with normal [0 1 0] and d ~ N(0, " + format_number(p.noise_variance, 2) +
                  ") per point (variance), spanning x and the in-plane axis z (the thesis writes y for it, "
                  "which its normal "
                  "rules out); case 2 shifts planes 2 and 3 by " +
                  format_number(p.case2_shift, 1) +
                  " along y. C_p is the Mahalanobis distance with the pooled covariance of eq. (4.53), i.e. "
                  "the square root "
                  "of the quadratic form the thesis prints (its magnitudes and t_p = 10 fit the distance); "
                  "the column C_p² "
                  "gives the printed form. Table 4.1 is repetition 0 (seed " +
                  std::to_string(config.seed) + "); the claims use all " + std::to_string(ok.size()) +
                  " repetitions (seeds " + std::to_string(config.seed) +
                  " + r). Deviations: the thesis' random draw is unknown, so single values differ by chance.";

  Table t41;
  t41.caption =
      "Table 4.1: merging tests in two cases (ours, seed " + std::to_string(config.seed) + " | thesis)";
  t41.label = "table_4_1";
  t41.add_column("case").add_column("planes");
  t41.add_compared_column("C_o [deg]").add_compared_column("C_t [m]").add_compared_column("C_p");
  t41.add_number_column("C_p² (printed form)", 2).add_compared_column("d_c [m]");
  Table spread;
  spread.caption = "Merging tests over the repetitions: mean [95 % interval]";
  spread.label = "merging_repetitions";
  spread.add_column("case").add_column("planes");
  for (const char* h : {"C_o [deg]", "C_t [m]", "C_p", "d_c [m]"}) spread.add_column(h);
  for (int c = 1; c <= 2; ++c) {
    for (int pair = 0; pair < 2; ++pair) {
      const std::vector<double> ref = reference_row(config.reference, c, pair);
      std::vector<Cell> cells{Cell::text("case " + std::to_string(c)),
                              Cell::text(pair == 0 ? "1 and 2" : "1 and 3")};
      std::vector<Cell> spread_cells = cells;
      for (int k = 0; k < 4; ++k) {
        const double ours = first ? first->value(key(c, pair, kCriteria[k])) : NAN;
        cells.push_back(number_or_missing(ours));
        cells.push_back(number_or_missing(ref[static_cast<std::size_t>(k)]));
        if (k == 2) cells.push_back(number_or_missing(ours * ours));
        spread_cells.push_back(
            Cell::text(describe(mean_interval(values(key(c, pair, kCriteria[k]))), "", 2)));
      }
      t41.add_row(std::move(cells));
      spread.add_row(std::move(spread_cells));
    }
  }
  section.tables.push_back(t41);
  section.tables.push_back(spread);
  section.figures.push_back(merging_problem_figure(p, config.seed));
  section.figures.push_back(planes_figure(p, 1, config.seed));
  section.figures.push_back(planes_figure(p, 2, config.seed));

  XYPlot scatter{"C_p against d_c over the repetitions",
                 "d_c, centre distance [m]",
                 "C_p (Mahalanobis distance, unitless)",
                 {}};
  scatter.log_y = true;
  for (int c = 1; c <= 2; ++c)
    for (int pair = 0; pair < 2; ++pair)
      scatter.add_scatter("case " + std::to_string(c) + ", planes 1 and " + (pair == 0 ? "2" : "3"),
                          values(key(c, pair, "dc")), values(key(c, pair, "cp")));
  scatter.series.push_back({"t_p",
                            {10, 30},
                            {p.thresholds.closeness, p.thresholds.closeness},
                            PlotSeries::Style::line,
                            "#999999"});
  section.figures.push_back({"cp_against_dc", "C_p separates the cases where d_c does not (every repetition)",
                             render_svg(scatter)});

  // Claims, over the repetitions.
  const auto ratio = [&](const std::string& num, const std::string& den) {
    std::vector<double> r;
    const std::vector<double> a = values(num), b = values(den);
    for (std::size_t i = 0; i < a.size(); ++i) r.push_back(a[i] / b[i]);
    return mean_interval(r);
  };
  const Interval dc12 = ratio(key(2, 0, "dc"), key(1, 0, "dc")),
                 dc13 = ratio(key(2, 1, "dc"), key(1, 1, "dc"));
  // A sanity check, not a test of the thesis: d_c is fixed by the scene's geometry (case 2 moves the
  // centres of planes 2 and 3 by the 5 m shift, d_c → √(d_c² + 5²)), and the point noise hardly moves
  // the centres, so the ratio's interval has width ≈ 0 and cannot come out otherwise.
  section.claims.push_back(
      {"The scene keeps d_c nearly the same in both cases (case 2 / case 1 within ±10 %), so only the "
       "other criteria can tell them apart",
       verdict_all({verdict_in_band(dc12, 0.9, 1.1), verdict_in_band(dc13, 0.9, 1.1)}),
       "d_c ratio planes 1–2 " + describe(dc12, "×", 3) + ", 1–3 " + describe(dc13, "×", 3) +
           " (set by the scene: the 5 m shift gives √(d_c² + 5²) / d_c)",
       ClaimKind::sanity});
  const Interval dcp =
      bootstrap_paired_mean_difference(values(key(1, 1, "cp")), values(key(1, 0, "cp")), config.seed);
  const Interval ddc =
      bootstrap_paired_mean_difference(values(key(1, 1, "dc")), values(key(1, 0, "dc")), config.seed + 1);
  section.claims.push_back(
      {"Case 1: comparing the larger coplanar patch (plane 3) lowers C_p although d_c grows",
       verdict_all({verdict_less(dcp, 0.0), verdict_greater(ddc, 0.0)}),
       "C_p(1–3) − C_p(1–2) " + describe(dcp) + "; d_c(1–3) − d_c(1–2) " + describe(ddc)});
  const double tp = p.thresholds.closeness;
  std::vector<Verdict> sides;
  std::string evidence;
  for (int c = 1; c <= 2; ++c)
    for (int pair = 0; pair < 2; ++pair) {
      const Interval i = mean_interval(values(key(c, pair, "cp")));
      sides.push_back(c == 1 ? verdict_less(i, tp) : verdict_greater(i, tp));
      evidence += std::string(evidence.empty() ? "" : "; ") + "case " + std::to_string(c) + " 1–" +
                  (pair == 0 ? "2 " : "3 ") + describe(i);
    }
  section.claims.push_back({"C_p jumps when the patches are not coplanar: case 1 below t_p = " +
                                format_number(tp, 0) + " (merge), case 2 above (no merge)",
                            verdict_all(sides), evidence});
  const double factor = reference_number(config.reference, "jump_band_factor").value_or(2.0);
  std::vector<Verdict> magnitude;
  std::string magnitude_evidence;
  for (int pair = 0; pair < 2; ++pair) {
    const std::vector<double> r1 = reference_row(config.reference, 1, pair),
                              r2 = reference_row(config.reference, 2, pair);
    const double thesis = r2[2] / r1[2];
    const Interval ours = ratio(key(2, pair, "cp"), key(1, pair, "cp"));
    magnitude.push_back(std::isfinite(thesis) ? verdict_in_band(ours, thesis / factor, thesis * factor)
                                              : Verdict::not_comparable);
    magnitude_evidence += std::string(pair == 0 ? "" : "; ") + "planes 1–" + (pair == 0 ? "2" : "3") +
                          ": ours " + describe(ours, "×") + ", thesis " + format_number(thesis, 1) + "×";
  }
  section.claims.push_back({"The jump of C_p from case 1 to case 2 has the thesis' size (within a factor " +
                                format_number(factor, 0) + ")",
                            verdict_all(magnitude), magnitude_evidence});
  std::size_t right = 0;
  for (const RunRow* r : ok)
    right += r->value("case1_merged_planes") == 1.0 && r->value("case2_merged_planes") == 2.0 ? 1 : 0;
  section.claims.push_back(
      {"Region growing merges case 1 into one plane and case 2 into two (plane 1; planes 2+3) "
       "in every repetition",
       ok.empty() ? Verdict::not_comparable : (right == ok.size() ? Verdict::holds : Verdict::does_not_hold),
       std::to_string(right) + " of " + std::to_string(ok.size()) + " repetitions", ClaimKind::sanity});
  return section;
}

}  // namespace sextant
