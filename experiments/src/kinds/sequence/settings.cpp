#include "sequence/settings.hpp"

#include "sequence/layouts/layouts.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"

namespace sextant {
namespace {

void read_kf(SettingsReader& in, SequenceParams& p) {
  if (!in.has("kf")) return;
  SettingsReader kf(in.child("kf"), in.file());
  double rotation_deg = p.kf.odometry_sigma_rotation / kRadPerDeg,
         alarm_deg = p.kf.alarm_rotation / kRadPerDeg;
  kf.read("sigma_translation", p.kf.odometry_sigma_translation);
  kf.read("sigma_rotation_deg", rotation_deg);
  kf.read("alarm_translation", p.kf.alarm_translation);
  kf.read("alarm_rotation_deg", alarm_deg);
  kf.read("measurement_noise_scale", p.measurement_noise_scale);
  kf.read("initial_sigma", p.initial_sigma);
  kf.finish();
  p.kf.odometry_sigma_rotation = rotation_deg * kRadPerDeg;
  p.kf.alarm_rotation = alarm_deg * kRadPerDeg;
  std::string why;
  if (!p.kf.valid(&why)) kf.fail("", "key 'kf': " + why);
  if (!(p.measurement_noise_scale > 0))
    kf.fail("measurement_noise_scale", "key 'measurement_noise_scale' must be > 0");
  if (!(p.initial_sigma > 0)) kf.fail("initial_sigma", "key 'initial_sigma' must be > 0");
}

}  // namespace

SequenceParams read_sequence_params(const ExperimentConfig& config) {
  SettingsReader in(config.params, config.file);
  SequenceParams p;
  long first = 0, scans = static_cast<long>(p.scans);
  in.read("first_scan", first);
  in.read("scans", scans);
  if (first < 0) in.fail("first_scan", "key 'first_scan' must be ≥ 0");
  if (scans < 2) in.fail("scans", "key 'scans' must be ≥ 2 (a sequence needs one registration)");
  p.first_scan = static_cast<std::size_t>(first);
  p.scans = static_cast<std::size_t>(scans);

  std::string odometry = "simulated", filter = "none", report = "dead_reckoning";
  in.read("odometry", odometry);
  if (odometry == "simulated") {
    p.odometry = SequenceOdometry::kSimulated;
    if (config.dataset.source != DatasetSource::kSynthetic && !config.dataset.simulates_odometry())
      in.fail("odometry",
              "key 'odometry': simulated odometry needs dataset source: synthetic, or a folder with "
              "simulated_odometry: (use dataset)");
  } else if (odometry == "dataset") {
    p.odometry = SequenceOdometry::kDataset;
  } else {
    in.fail("odometry", "key 'odometry': '" + odometry + "' is not simulated or dataset");
  }
  in.read("filter", filter);
  if (filter == "none") {
    p.filter = SequenceFilter::kNone;
  } else if (filter == "kf") {
    p.filter = SequenceFilter::kKf;
  } else {
    in.fail("filter", "key 'filter': '" + filter + "' is not none or kf");
  }
  read_kf(in, p);
  in.read("report", report);
  p.report = find_sequence_layout(report);
  if (!p.report) in.fail("report", "key 'report': '" + report + "' is not " + sequence_layout_names());
  if (p.report->needs_kf && p.filter != SequenceFilter::kKf)
    in.fail("report", "key 'report': the " + report + " layout needs filter: kf");
  in.read("ellipses_at", p.ellipses_at);
  for (const int k : p.ellipses_at) {
    if (!p.report->ellipses) break;  // only a layout that draws ellipses
    if (k < 1 || static_cast<std::size_t>(k) > p.scans)
      in.fail("ellipses_at",
              "key 'ellipses_at': " + std::to_string(k) + " is not a scan number in [1, scans]");
  }
  in.read("ellipse_scale", p.ellipse_scale);
  if (!(p.ellipse_scale >= 0)) in.fail("ellipse_scale", "key 'ellipse_scale' must be ≥ 0 (0 = automatic)");
  in.finish();
  return p;
}

}  // namespace sextant
