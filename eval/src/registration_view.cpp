// A registration as a cloud view: the reference, and the input placed by the initial guess and by
// the result, in two states the page switches between.
#include "sextant/eval/cloud_view.hpp"

namespace sextant {

CloudView registration_view(const PointCloud& reference, const PointCloud& input,
                            const Eigen::Isometry3d& T_initial, const Eigen::Isometry3d& T_result,
                            const std::string& title) {
  CloudView view;
  view.title = title;
  view.caption =
      "The input mapped into the reference frame by the initial guess (before) and by the "
      "registration's result (after).";
  view.states = {"before (initial guess)", "after (result)"};
  view.clouds.push_back({"reference", reference, "", {}, {}});
  view.clouds.push_back({"input", input, "", {T_initial, T_result}, {}});
  return view;
}

void write_registration_view(const std::filesystem::path& path, const PointCloud& reference,
                             const PointCloud& input, const Eigen::Isometry3d& T_initial,
                             const Eigen::Isometry3d& T_result, const std::string& title) {
  write_cloud_view(registration_view(reference, input, T_initial, T_result, title), path);
}

}  // namespace sextant
