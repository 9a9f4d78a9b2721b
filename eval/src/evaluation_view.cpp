// `sextant eval`'s run view (run_view.hpp): the reference, the estimate as the ATE aligned it, and one
// record per pose with its ATE error; a trajectory from a file carries no trust, so nothing is marked
// and the estimate opens coloured by its error.
#include <cmath>
#include <iomanip>
#include <sstream>

#include "sextant/core/pose.hpp"
#include "sextant/core/units.hpp"
#include "sextant/eval/run_view.hpp"
#include "sextant/eval/trajectory_evaluation.hpp"

namespace sextant {

RunView evaluation_run_view(const AssociatedPoses& pairs, const TrajectoryEvaluation& evaluation,
                            const std::string& title, bool timed) {
  RunView view;
  view.title = title;
  view.estimate = evaluation.aligned_estimate;
  view.reference = pairs.reference;
  view.step_name = "pose";
  view.error_name = "ATE: from the reference after the alignment";
  view.colour_by_error = true;
  const std::vector<double>& errors = evaluation.ate.translation_errors;
  for (std::size_t k = 0; k < view.estimate.size(); ++k) {
    RunViewStep s;
    s.number = k;
    s.pose = k;
    s.assessed = false;
    if (timed && k < pairs.stamps.size()) s.stamp = pairs.stamps[k];
    if (k < errors.size()) s.error_m = errors[k];
    if (k < view.reference.size())  // angle(R_ref⁻¹ · R_aligned), the ATE's rotation error
      s.error_deg = rotation_angle(relative(view.reference[k], view.estimate[k])) * kDegPerRad;
    view.steps.push_back(s);
  }
  std::ostringstream caption;
  caption << std::fixed << std::setprecision(3) << view.estimate.size()
          << " poses paired; the estimate aligned onto the reference as for the ATE (RMS "
          << evaluation.ate.translation.rms << " m). No trust is known: nothing is marked.";
  view.caption = caption.str();
  return view;
}

}  // namespace sextant
