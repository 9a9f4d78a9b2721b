// Reading the feature settings from YAML (Sextant::features_yaml).
#include "sextant/features/yaml.hpp"

#include "sextant/core/settings_reader.hpp"

namespace sextant {

MergeThresholds read_merge_thresholds(const YAML::Node& node, const std::string& file,
                                      MergeThresholds defaults) {
  SettingsReader in(node, file);
  MergeThresholds t = defaults;
  in.read("orientation_deg", t.orientation_deg);
  in.read("translation", t.translation);
  in.read("closeness", t.closeness);
  in.read("min_variance", t.min_variance);
  in.finish();
  std::string why;
  if (!t.valid(&why)) in.fail("", why);
  return t;
}

AssociationSettings read_association_settings(const YAML::Node& node, const std::string& file) {
  AssociationSettings s;
  YAML::Node thresholds;
  if (node && node.IsMap()) {
    thresholds = YAML::Clone(node);
    thresholds.remove("search_radius");
  }
  SettingsReader in(node, file);
  in.read("search_radius", s.search_radius);
  s.thresholds = read_merge_thresholds(thresholds, file, s.thresholds);  // the other keys
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

PlaneExtractionSettings read_plane_extraction_settings(const YAML::Node& node, const std::string& file) {
  SettingsReader in(node, file);
  PlaneExtractionSettings s;
  std::string preset;
  // `preset:` first, the other keys override it; not recorded (the resolved settings are).
  in.read_alias("preset", preset);
  if (preset == "thesis")
    s = thesis_feature_sampling();
  else if (!preset.empty())
    in.fail("preset", "key 'preset': '" + preset + "' is not thesis (the only plane extraction preset)");
  in.read("cell_size", s.cell_size);
  in.read("distance_threshold", s.distance_threshold);
  in.read("ransac_iterations", s.ransac_iterations);
  in.read("ransac_confidence", s.ransac_confidence);
  in.read("min_inliers", s.min_inliers);
  in.read("min_inlier_ratio", s.min_inlier_ratio);
  in.read("max_planes_per_cell", s.max_planes_per_cell);
  in.read("refit", s.refit);
  in.read("merge", s.merge);
  if (in.has("merge_thresholds"))
    s.merge_thresholds = read_merge_thresholds(in.child("merge_thresholds"), file);
  in.read("remove_horizontal", s.remove_horizontal);
  in.read("horizontal_max_tilt_deg", s.horizontal_max_tilt_deg);
  in.read("min_landmark_area", s.min_landmark_area);
  in.read("min_landmark_inliers", s.min_landmark_inliers);
  in.read("split_layer", s.split_layer);
  in.read("split_division", s.split_division);
  in.read("refit_inliers", s.refit_inliers);
  in.finish();
  std::string why;
  if (!s.valid(&why)) in.fail("", why);
  return s;
}

}  // namespace sextant
