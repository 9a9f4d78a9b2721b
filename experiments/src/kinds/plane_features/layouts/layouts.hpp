#pragma once
// The plane_features kind's studies. A study is one file plus one line in the table of
// layouts.cpp: its `study:` name, the checks of its params, methods, sweep and reference, its
// session and its report.
//   plane_features/merging.cpp     — the three synthetic planes of §4.1, both cases; C_o, C_t,
//                                    C_p (pooled covariance, eq. 4.53) and d_c beside table 4.1
//   plane_features/extraction.cpp  — extraction (cells, RANSAC, merging, ground removal) and
//                                    semantic association on the synthetic campus, precision and
//                                    recall against its true planes (report: extraction_report.cpp)
//
//   params: {study: merging | extraction, ...the study's own keys (each reads `study` too)}
#include <memory>
#include <vector>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_kind.hpp"

namespace sextant {

/// Throws InputError (file, line, key) on any problem of params, methods, sweep or reference.
using PlaneFeaturesValidate = void (*)(const ExperimentConfig& config);
using PlaneFeaturesPrepare = std::unique_ptr<KindSession> (*)(const ExperimentConfig& config);
using PlaneFeaturesReport = ReportSection (*)(const ExperimentConfig& config,
                                              const std::vector<RunSpec>& runs,
                                              const std::vector<const RunRow*>& rows);

struct PlaneFeaturesLayout {
  const char* name = "";  ///< the value of `study:`
  PlaneFeaturesValidate validate = nullptr;
  PlaneFeaturesPrepare prepare = nullptr;
  PlaneFeaturesReport report = nullptr;
};

/// The table, in the order the error message names them.
const std::vector<PlaneFeaturesLayout>& plane_features_layouts();
/// The line of params.study; InputError at its line when it is missing or not in the table.
const PlaneFeaturesLayout& plane_features_layout(const ExperimentConfig& config);

}  // namespace sextant
