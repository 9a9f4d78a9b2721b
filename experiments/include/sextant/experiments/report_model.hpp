#pragma once
// What a run kind hands to the report: tables laid out like the thesis' (ours beside theirs, the
// eval module's Table), SVG figures, interactive 3D scenes (eval's CloudView, written as pages the
// section links to), and the thesis' claims with a verdict computed from our numbers.
#include <cstddef>
#include <string>
#include <vector>

#include "sextant/core/trajectory.hpp"
#include "sextant/eval/cloud_view.hpp"
#include "sextant/eval/html_report.hpp"
#include "sextant/eval/table.hpp"

namespace sextant {

struct ReportFigure {
  std::string id;  ///< file stem, e.g. "success_map_mlndt"
  std::string caption;
  std::string svg;  ///< a complete SVG document
};

/// A trajectory the report writes as `<id>.tum` (TUM format, for evo) beside the tables.
struct ReportTrajectory {
  std::string id;
  std::string caption;
  Trajectory poses;
};

/// A 3D scene the report writes as `<id>.html` (three.js from the report folder's three.min.js)
/// and links from the section, beside the static figures.
struct ReportScene {
  std::string id;  ///< file stem, e.g. "clouds_3d"
  std::string caption;
  CloudView view;
};

struct ReportSection {
  std::string notes;          ///< free text (dataset, deviations from the thesis)
  std::vector<Table> tables;  ///< Table::label is the file stem
  std::vector<ReportFigure> figures;
  std::vector<ReportScene> scenes;
  std::vector<Claim> claims;
  std::vector<ReportTrajectory> trajectories;
};

}  // namespace sextant
