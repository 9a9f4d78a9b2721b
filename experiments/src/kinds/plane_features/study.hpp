#pragma once
// The `plane_features` kind, one file per study:
//   plane_features/merging.cpp     — the three synthetic planes of §4.1, both cases; C_o, C_t,
//                                    C_p (pooled covariance, eq. 4.53) and d_c beside table 4.1
//   plane_features/extraction.cpp  — extraction (cells, RANSAC, merging, ground removal) and
//                                    semantic association on the synthetic campus, precision and
//                                    recall against its true planes (report: ..._extraction_report.cpp)
//
//   params: {study: merging | extraction, ...the study's own keys (each reads `study` too)}
#include <memory>
#include <string>
#include <vector>

#include "sextant/experiments/report_model.hpp"
#include "sextant/experiments/run_kind.hpp"

namespace sextant {

class PlaneFeaturesStudy {
 public:
  virtual ~PlaneFeaturesStudy() = default;
  /// Throws InputError (file, line, key) on any problem of params, methods, sweep or reference.
  virtual void validate(const ExperimentConfig& config) const = 0;
  virtual std::unique_ptr<KindSession> prepare(const ExperimentConfig& config) const = 0;
  virtual ReportSection report(const ExperimentConfig& config, const std::vector<RunSpec>& runs,
                               const std::vector<const RunRow*>& rows) const = 0;
};

std::unique_ptr<PlaneFeaturesStudy> make_merging_study();
std::unique_ptr<PlaneFeaturesStudy> make_extraction_study();

}  // namespace sextant
