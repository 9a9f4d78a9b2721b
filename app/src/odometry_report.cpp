// What `sextant odometry` records and prints of a run (odometry_report.hpp).
#include "odometry_report.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "sextant/pipeline/json.hpp"
#include "sextant/pipeline/odometry_output.hpp"
#include "sextant/pipeline/provenance.hpp"
#include "sextant/pipeline/yaml_json.hpp"

namespace sextant::cli {

RecordingSelection OdometryOptions::recording_selection() const {
  RecordingSelection s;
  s.topic = topic;
  s.start = start;
  if (!std::isnan(duration)) s.duration = duration;
  s.every = every;
  return s;
}

std::string provenance_json(const OdometryOptions& o, const MatcherConfig& config,
                            const DatasetMetadata& meta, const OdometrySettings& s,
                            const OdometryResult& result, std::size_t scans, const std::string& start,
                            double seconds, const std::optional<RunMapSummary>& map) {
  const GitState git = current_git_state();
  Json map_json;  // null without --map-out
  if (map)
    map_json = {{"path", o.map_out},
                {"voxel_m", json_value(map->voxel)},
                {"voxel_from", map->voxel_origin()},
                {"first_scan_median_range_m", json_value(map->median_range)},
                {"after_loop_closure", !o.loop_closure.empty()},
                {"trusted_only", o.map_trusted_only},
                {"points", map->points},
                {"intensity", map->intensity},
                {"scans", map->scans},
                {"scans_left_out", map->scans_left_out},
                {"skipped_points", map->skipped_points}};
  const bool sampler = config.sampler.IsDefined() && !config.sampler.IsNull();
  const Json provenance = {
      {"command", "odometry"},
      {"dataset",
       {{"argument", o.dataset},
        {"name", meta.name},
        {"format", meta.format},
        {"path", meta.path.string()},
        {"scans", meta.scan_count},
        {"campus_seed", o.campus_seed},
        {"poses", o.poses},
        {"topic", o.topic},
        {"start", json_value(o.start)},
        {"duration", std::isnan(o.duration) ? Json() : json_value(o.duration)},
        {"every", o.every},
        {"notes", meta.notes}}},
      {"first", o.first},
      {"scans", scans},
      {"method", o.method},
      {"preset", o.preset},
      {"solver", o.solver},
      {"sampling", o.sampling},
      {"config_file", o.config},
      {"matcher_settings", yaml_to_json(config.matcher)},
      {"sampler_settings", sampler ? yaml_to_json(config.sampler) : Json()},
      {"matcher_resolved", yaml_to_json(config.resolved["matcher"])},
      {"sampler_resolved", yaml_to_json(config.resolved["sampler"])},
      {"guess", to_string(s.guess)},
      {"map", to_string(s.map)},
      {"loop_closure", o.loop_closure},
      {"map_out", map_json},
      {"view", o.view.empty() ? Json() : Json(o.view)},
      {"local_map_scans", s.local_map_scans},
      {"min_range", json_value(s.min_range)},
      {"max_acceleration", json_value(s.max_acceleration)},
      {"sensor",
       {{"declared", to_string(s.sensor)},
        {"used", to_string(result.sensor.kind)},
        {"azimuth_coverage", json_value(result.sensor.azimuth_coverage)}}},
      {"platform",
       {{"declared", to_string(s.platform)},
        {"typical_step_m", result.typical_step ? json_value(*result.typical_step) : Json()},
        {"tolerance_m", json_value(result.tolerance.ambiguity_metres)},
        {"tolerance_deg", json_value(result.tolerance.ambiguity_degrees)}}},
      {"recover", s.recover},
      {"deskew",
       {{"scheme", deskew_scheme(s)},
        {"scans_with_time", result.timed_scans},
        {"scans_deskewed", result.deskewed()},
        {"steps_registered_again", result.registered_again}}},
      {"common_view", s.common_view},
      {"seed", s.seed},
      {"jobs", o.jobs},
      {"git", {{"sha", git.sha}, {"dirty", git.dirty}, {"source", git.source}}},
      {"libraries", Json::parse(library_versions_json())},
      {"host", host_name()},
      {"start", start},
      {"end", iso_time_now()},
      {"seconds", json_value(seconds)}};
  return json_lines(provenance,
                    {"matcher_settings", "sampler_settings", "matcher_resolved", "sampler_resolved"});
}

void print_steps(const OdometryResult& result, std::size_t first) {
  for (std::size_t k = 0; k < result.steps.size(); ++k) {
    const OdometryStep& st = result.steps[k];
    std::cout << "step " << k << " (scans " << first + k << "→" << first + k + 1
              << "): " << (st.converged ? "converged" : "not converged") << ", " << st.iterations
              << " iterations, trust " << to_string(st.quality.trust)
              << (st.quality.reason.empty() ? "" : " (" + st.quality.reason + ")")
              << (st.recovery.empty() ? "" : ", recovery " + st.recovery) << "\n";
  }
}

std::string sensor_line(const OdometrySettings& s, const OdometryResult& r) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(0) << to_string(r.sensor.kind)
      << (s.sensor == SensorKind::automatic ? " (measured: the first scan covers "
                                            : " (declared; the first scan covers ")
      << 100.0 * r.sensor.azimuth_coverage << " % of the azimuth circle)"
      << (r.sensor.kind == SensorKind::spinning ? "" : ", no ring or horizon checks") << "; platform "
      << to_string(s.platform) << std::setprecision(2);
  if (s.platform == Platform::automatic) {
    out << ", typical step ";
    if (r.typical_step)
      out << *r.typical_step << " m";
    else
      out << "unknown";
  }
  out << ": a wrong step is one more than " << r.tolerance.ambiguity_metres << " m or "
      << std::setprecision(1) << r.tolerance.ambiguity_degrees << "° off";
  return out.str();
}

}  // namespace sextant::cli
