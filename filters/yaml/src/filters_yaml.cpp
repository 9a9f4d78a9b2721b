// The plane-SLAM settings from YAML (Sextant::filters_yaml).
#include <memory>

#include "sextant/core/settings_reader.hpp"
#include "sextant/features/yaml.hpp"
#include "sextant/filters/plane_slam_model.hpp"
#include "sextant/filters/yaml.hpp"

namespace sextant {

PlaneSlamSettings read_plane_slam_settings(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  PlaneSlamSettings s;
  YAML::Node filter_settings;
  in.read("filter", s.filter);
  if (in.has("filter_settings")) filter_settings = YAML::Clone(in.child("filter_settings"));
  if (in.has("extraction")) s.extraction = read_plane_extraction_settings(in.child("extraction"), file);
  if (in.has("association")) s.association = read_association_settings(in.child("association"), file);
  in.read("sigma_xy", s.sigma_xy);
  in.read("sigma_z", s.sigma_z);
  in.read("sigma_roll_pitch", s.sigma_roll_pitch);
  in.read("sigma_yaw", s.sigma_yaw);
  in.read("sigma_normal", s.sigma_normal);
  in.read("sigma_distance", s.sigma_distance);
  in.read("initial_sigma_translation", s.initial_sigma_translation);
  in.read("initial_sigma_rotation", s.initial_sigma_rotation);
  in.read("p0_scale", s.p0_scale);
  in.read("gate_probability", s.gate_probability);
  in.read("merge_semantics", s.merge_semantics);
  in.read("particle_association", s.particle_association);
  in.read("record_pose_covariance", s.record_pose_covariance);
  in.finish();
  std::string why;
  const bool valid = s.valid(&why);
  if (!valid && !default_filter(s.filter)) in.fail("", why);  // an unknown filter first
  if (filter_settings && !filter_settings.IsNull() && !filter_settings.IsMap())
    in.fail("", "filter_settings must be a map");
  if (!valid) in.fail("", why);
  // The filter's own keys are read now, so a typo fails before a long run starts.
  s.filter_factory =
      filter_factory(read_filter_spec(s.filter, filter_settings, file, PlaneSlamModel().pose_dim()));
  return s;
}

}  // namespace sextant
