#pragma once
// What a run kind hands to the report: tables laid out like the thesis' (ours beside theirs, the
// eval module's Table), SVG figures, and the thesis' claims with a verdict computed from our numbers.
#include <cstddef>
#include <string>
#include <vector>

#include "sextant/eval/html_report.hpp"
#include "sextant/eval/table.hpp"

namespace sextant {

struct ReportFigure {
  std::string id;  ///< file stem, e.g. "success_map_mlndt"
  std::string caption;
  std::string svg;  ///< a complete SVG document
};

struct ReportSection {
  std::string notes;          ///< free text (dataset, deviations from the thesis)
  std::vector<Table> tables;  ///< Table::label is the file stem
  std::vector<ReportFigure> figures;
  std::vector<Claim> claims;
};

}  // namespace sextant
