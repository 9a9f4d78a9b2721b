#include "registration/scenes.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include <tbb/parallel_for.h>

#include "sextant/core/error.hpp"
#include "sextant/core/io/cloud_io.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/core/units.hpp"
#include "sextant/matchers/ndt_grid.hpp"
#include "sextant/matchers/ndt_matcher.hpp"
#include "sextant/matchers/yaml.hpp"

namespace sextant {
namespace {

SceneSpec read_scene(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  SceneSpec s;
  in.require("name", s.name);
  in.read("scan", s.scan);
  in.read("second", s.second);
  const std::filesystem::path base = std::filesystem::path(file).parent_path();
  const auto path_of = [&](const char* key, std::string& out) {
    if (!in.read(key, out)) return;
    std::filesystem::path p(out);
    if (p.is_relative()) p = base / p;
    out = p.lexically_normal().string();
  };
  path_of("reference", s.reference);
  path_of("input", s.input);
  path_of("truth", s.truth);
  std::vector<double> pose;
  if (in.read("truth_pose", pose)) {
    if (pose.size() != 6) in.fail("truth_pose", "key 'truth_pose': expected [x, y, z, α, β, γ] in m and deg");
    s.truth_pose = to_isometry(
        Pose6{pose[0], pose[1], pose[2], pose[3] * kRadPerDeg, pose[4] * kRadPerDeg, pose[5] * kRadPerDeg});
  }
  in.finish();
  const bool files = !s.reference.empty() || !s.input.empty();
  if (files == (s.scan >= 0))
    in.fail("name", "scene '" + s.name + "': give either scan (dataset) or reference and input (files)");
  if (files && (s.reference.empty() || s.input.empty()))
    in.fail("name", "scene '" + s.name + "': a file scene needs both reference and input");
  if (files && s.truth.empty() == !s.truth_pose.has_value())
    in.fail("name", "scene '" + s.name + "': a file scene needs exactly one of truth (file) and truth_pose");
  if (!files && (!s.truth.empty() || s.truth_pose))
    in.fail("name", "scene '" + s.name + "': a dataset scene takes its truth from the dataset");
  if (!files && s.second < 0) s.second = s.scan + 1;
  if (!files && s.second == s.scan) in.fail("second", "key 'second': must differ from 'scan'");
  return s;
}

std::size_t scene_index(const DisplacedSettings& settings, const std::string& name) {
  for (std::size_t k = 0; k < settings.scenes.size(); ++k)
    if (settings.scenes[k].name == name) return k;
  return settings.scenes.size();
}

void require_file(const ExperimentConfig& config, const SceneSpec& scene, const std::string& path) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError(config.file, "",
                     "scene '" + scene.name + "': file '" + path + "' does not exist (or is not a file)");
}

Eigen::Isometry3d read_matrix_file(const std::string& path) {
  std::ifstream in(path);
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) in >> M(r, c);
  if (!in) throw InputError(path, "", "expected a 4×4 matrix (p_reference = T · p_input)");
  Eigen::Isometry3d T;
  T.matrix() = M;
  return T;
}

/// The NDT grid's cell edge for this reference: the first `ndt` method's cell_size, or the
/// volume split into volume_divisions cubes (the default 64 = ML-NDT layer 2, §5.1.1.1).
double ndt_cell_edge(const ExperimentConfig& config, const PointCloud& reference) {
  int divisions = 64;
  for (const auto& m : config.methods) {
    const YAML::Node matcher = m.node["matcher"];
    if (!matcher.IsDefined() || matcher.as<std::string>() != "ndt") continue;
    const NdtSettings s = read_ndt_settings(m.node["settings"], config.file);
    if (s.cell_size > 0) return s.cell_size;
    divisions = s.volume_divisions;
    break;
  }
  return layer_geometry(reference.bounds(), divisions, 1).cell_edge;
}

}  // namespace

DisplacedSettings read_displaced_settings(const ExperimentConfig& config, const RegistrationParams& params) {
  DisplacedSettings s;
  if (!params.displaced.IsDefined() || params.displaced.IsNull()) {
    SceneSpec legacy;
    legacy.name = "scan_" + std::to_string(params.scan);
    legacy.scan = static_cast<long>(params.scan);
    legacy.second = static_cast<long>(params.second);
    s.cells = false;
    s.scenes.push_back(legacy);
    return s;
  }
  SettingsReader in(params.displaced, config.file);
  std::string unit = "ndt_cell";
  in.read("offset_unit", unit);
  if (unit != "ndt_cell" && unit != "m")
    in.fail("offset_unit", "key 'offset_unit': '" + unit + "' is not ndt_cell or m");
  s.cells = unit == "ndt_cell";
  const YAML::Node scenes = in.child("scenes");
  if (!scenes.IsSequence() || scenes.size() == 0)
    in.fail("scenes", "key 'scenes': expected a list of scenes");
  std::set<std::string> names;
  for (const auto& node : scenes) {
    s.scenes.push_back(read_scene(node, config.file));
    if (!names.insert(s.scenes.back().name).second)
      throw InputError(config.file, at_line(yaml_line(node)),
                       "scene name '" + s.scenes.back().name + "' repeats");
  }
  if (const YAML::Node snap = in.child("snapshot"); snap.IsDefined() && !snap.IsNull()) {
    SettingsReader r(snap, config.file);
    SnapshotSpec p;
    r.require("scene", p.scene);
    r.read("offset", p.offset);
    r.read("direction", p.direction);
    r.read("yaw", p.yaw);
    r.finish();
    if (!names.count(p.scene)) r.fail("scene", "key 'scene': no scene named '" + p.scene + "'");
    s.snapshot = p;
  }
  in.read("snapshot_points", s.snapshot_points);
  if (s.snapshot_points < 10) in.fail("snapshot_points", "key 'snapshot_points' must be ≥ 10");
  in.finish();
  return s;
}

void check_displaced_sweep(const ExperimentConfig& config, const DisplacedSettings& settings) {
  if (const SweepAxis* axis = find_axis(config, "scene")) {
    for (const auto& v : axis->values) {
      const std::string name = v.IsScalar() ? v.as<std::string>() : YAML::Dump(v);
      if (scene_index(settings, name) == settings.scenes.size())
        throw InputError(config.file, at_line(yaml_line(v)),
                         "sweep axis 'scene': no scene named '" + name + "'");
    }
  } else if (settings.scenes.size() > 1) {
    throw InputError(config.file, "", "key 'sweep': several scenes need an axis 'scene' listing their names");
  }
  if (const SweepAxis* axis = find_axis(config, "direction")) {
    for (const auto& v : axis->values) {
      const double d = v.as<double>();
      if (d != 0 && d != 1 && d != 2 && d != 3)
        throw InputError(config.file, at_line(yaml_line(v)),
                         "key 'direction': " + YAML::Dump(v) + " is not 0, 1, 2 or 3");
    }
  }
}

Direction direction_of(int direction) {
  switch (direction) {
    case 1: return {90.0, -1.0};
    case 2: return {180.0, -1.0};
    case 3: return {270.0, 1.0};
    default: return {0.0, 1.0};
  }
}

DisplacedScenes::DisplacedScenes(const ExperimentConfig& config, const RegistrationParams& params,
                                 const Dataset& dataset)
    : settings_(read_displaced_settings(config, params)), scenes_(settings_.scenes.size()) {
  for (const SceneSpec& s : settings_.scenes) {
    if (s.scan >= 0) {
      for (const long i : {s.scan, s.second})
        if (static_cast<std::size_t>(i) >= dataset.size())
          throw InputError(config.file, "",
                           "scene '" + s.name + "': scan " + std::to_string(i) + " is past the dataset's " +
                               std::to_string(dataset.size()) + " scans");
      if (!dataset.ground_truth(static_cast<std::size_t>(s.scan)) ||
          !dataset.ground_truth(static_cast<std::size_t>(s.second)))
        throw InputError(config.file, "",
                         "scene '" + s.name + "': the dataset has no ground truth for this pair");
    } else {
      for (const std::string* path : {&s.reference, &s.input, &s.truth})
        if (!path->empty()) require_file(config, s, *path);
    }
  }
  tbb::parallel_for(std::size_t{0}, scenes_.size(), [&](std::size_t k) {
    const SceneSpec& s = settings_.scenes[k];
    Scene& out = scenes_[k];
    if (s.scan >= 0) {
      const auto a = static_cast<std::size_t>(s.scan), b = static_cast<std::size_t>(s.second);
      out.reference = dataset.scan(a);
      out.input = dataset.scan(b);
      out.truth = relative(*dataset.ground_truth(a), *dataset.ground_truth(b));
    } else {
      out.reference = read_cloud(s.reference);
      out.input = read_cloud(s.input);
      out.truth = s.truth_pose ? *s.truth_pose : read_matrix_file(s.truth);
    }
    out.cell_edge = ndt_cell_edge(config, out.reference);
  });
}

DisplacedCase DisplacedScenes::displace(const RunSpec& run) const {
  DisplacedCase c;
  const auto it = run.point.find("scene");
  c.scene = it == run.point.end() ? 0 : scene_index(settings_, it->second);
  const Scene& scene = scenes_.at(c.scene);
  c.reference = &scene.reference;
  c.cell_edge = scene.cell_edge;
  const double offset = point_value(run, "offset", 0.0), direction = point_value(run, "direction", 0.0);
  const Direction d = direction_of(static_cast<int>(direction));
  c.offset_m = offset * (settings_.cells ? scene.cell_edge : 1.0);
  c.heading_deg = d.heading_deg;
  c.yaw_deg = d.yaw_sign * point_value(run, "yaw", 0.0);
  const double tx = point_value(run, "tx", 0.0);
  // Move the input so that the true transform becomes the offset D; the guess stays identity.
  const Pose6 offset_pose{tx + c.offset_m * std::cos(c.heading_deg * kRadPerDeg),
                          c.offset_m * std::sin(c.heading_deg * kRadPerDeg),
                          0,
                          0,
                          0,
                          c.yaw_deg * kRadPerDeg};
  const Eigen::Isometry3d D = to_isometry(offset_pose);
  c.input = scene.input.transformed(D.inverse() * scene.truth);
  c.truth = D;
  if (settings_.snapshot) {
    const SnapshotSpec& p = *settings_.snapshot;
    c.snapshot = settings_.scenes[c.scene].name == p.scene && offset == p.offset &&
                 direction == p.direction && point_value(run, "yaw", 0.0) == p.yaw;
  }
  return c;
}

std::vector<double> snapshot_points(const PointCloud& cloud, int count) {
  std::vector<float> z;
  z.reserve(cloud.size());
  for (const auto& p : cloud.points()) z.push_back(p.z());
  if (z.empty()) return {};
  std::sort(z.begin(), z.end());
  const float lo = z[z.size() * 30 / 100], hi = z[std::min(z.size() - 1, z.size() * 95 / 100)];
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (cloud[i].z() >= lo && cloud[i].z() <= hi) kept.push_back(i);
  const std::size_t stride = std::max<std::size_t>(1, kept.size() / static_cast<std::size_t>(count));
  std::vector<double> out;
  for (std::size_t k = 0; k < kept.size(); k += stride)
    for (int j = 0; j < 3; ++j) out.push_back(cloud[kept[k]][j]);
  return out;
}

}  // namespace sextant
