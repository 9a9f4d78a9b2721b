#pragma once
// The feature settings from YAML (target Sextant::features_yaml; the library itself takes the plain
// structs). Every problem (an unknown key, a wrong type, an invalid value) is an InputError naming
// the file, the line and the key.
//
//   PlaneExtractionSettings s = read_plane_extraction_settings(node, "exp.yaml");
#include <string>

#include <yaml-cpp/yaml.h>

#include "sextant/features/association.hpp"
#include "sextant/features/extraction.hpp"
#include "sextant/features/merging.hpp"

namespace sextant {

/// Reads orientation_deg, translation, closeness, min_variance; unknown keys are errors.
MergeThresholds read_merge_thresholds(const YAML::Node& node, const std::string& file,
                                      MergeThresholds defaults = {});

/// Keys: search_radius and the merge thresholds' keys (read_merge_thresholds).
AssociationSettings read_association_settings(const YAML::Node& node, const std::string& file);

/// Keys: the field names of PlaneExtractionSettings; `merge_thresholds` is a map read by
/// read_merge_thresholds.
PlaneExtractionSettings read_plane_extraction_settings(const YAML::Node& node, const std::string& file);

}  // namespace sextant
