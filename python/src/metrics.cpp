// sextant.metrics: the trajectory metrics of eval/trajectory_metrics.hpp (ATE, RPE, KITTI drift,
// Wulf, Kümmerle) over N×4×4 pose arrays, returning dicts of floats and per-pose error arrays, and
// whether a reference is a car's path (eval/vehicle_slip.hpp), and poses on the ground plane
// (eval/ground_plane.hpp). A metric whose inputs fail the
// library's checks (lengths, too few poses, non-finite) raises.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "sextant/eval/ground_plane.hpp"
#include "sextant/eval/trajectory_evaluation.hpp"
#include "sextant/eval/trajectory_metrics.hpp"
#include "sextant/eval/vehicle_slip.hpp"

namespace sextant::python {
namespace {

PoseList read_poses(const py::handle& poses, const char* what) {
  return poses_from_array(poses, what);
}

void check(const MetricStatus& status, const char* metric) {
  if (!status.ok) throw py::value_error(std::string(metric) + ": " + status.message);
}

py::dict stats(const SampleStats& s) {
  py::dict d;
  d["count"] = s.count;
  d["mean"] = s.mean;
  d["std"] = s.std;
  d["min"] = s.min;
  d["max"] = s.max;
  d["rms"] = s.rms;
  d["median"] = s.median;
  return d;
}

Alignment alignment_named(const std::string& name) {
  Alignment a;
  if (!from_string(name, &a))
    throw py::value_error("alignment: unknown '" + name + "' (known: none, se3, sim3, origin)");
  return a;
}

/// The RMS and the statistics of a metric's translation and rotation errors.
void put_errors(py::dict& d, const SampleStats& translation, const SampleStats& rotation) {
  d["translation_rms"] = translation.rms;
  d["rotation_rms"] = rotation.rms;
  d["translation"] = stats(translation);
  d["rotation"] = stats(rotation);
}

py::dict ate(const py::object& reference, const py::object& estimate, const std::string& alignment) {
  const AteResult r = absolute_trajectory_error(
      read_poses(estimate, "estimate"), read_poses(reference, "reference"), alignment_named(alignment));
  check(r.status, "ate");
  py::dict d;
  put_errors(d, r.translation, r.rotation);
  d["translation_errors"] = vector_array(r.translation_errors);
  py::array_t<double> rotation({3, 3}), translation(3);
  auto R = rotation.mutable_unchecked<2>();
  auto t = translation.mutable_unchecked<1>();
  for (int i = 0; i < 3; ++i) {
    t(i) = r.alignment.translation(i);
    for (int j = 0; j < 3; ++j) R(i, j) = r.alignment.rotation(i, j);
  }
  py::dict a;
  a["rotation"] = rotation;
  a["translation"] = translation;
  a["scale"] = r.alignment.scale;
  d["alignment"] = a;
  return d;
}

py::dict rpe(const py::object& reference, const py::object& estimate, double delta, const std::string& unit,
             bool all_pairs, double tolerance) {
  RpeSettings s;
  if (unit == "frames") {
    s.unit = RpeSettings::Unit::frames;
  } else if (unit == "meters" || unit == "metres") {
    s.unit = RpeSettings::Unit::meters;
  } else {
    throw py::value_error("unit: unknown '" + unit + "' (known: frames, meters)");
  }
  s.delta = delta;
  s.all_pairs = all_pairs;
  s.tolerance = tolerance;
  const RpeResult r =
      relative_pose_error(read_poses(estimate, "estimate"), read_poses(reference, "reference"), s);
  check(r.status, "rpe");
  py::dict d;
  put_errors(d, r.translation, r.rotation);
  d["translation_errors"] = vector_array(r.translation_errors);
  d["rotation_errors"] = vector_array(r.rotation_errors);
  py::array_t<long long> pairs({static_cast<py::ssize_t>(r.pairs.size()), py::ssize_t{2}});
  auto p = pairs.mutable_unchecked<2>();
  for (std::size_t k = 0; k < r.pairs.size(); ++k) {
    p(static_cast<py::ssize_t>(k), 0) = static_cast<long long>(r.pairs[k].first);
    p(static_cast<py::ssize_t>(k), 1) = static_cast<long long>(r.pairs[k].second);
  }
  d["pairs"] = pairs;
  // The signed mean of E_ij per axis and its standard error (a bias every step shares).
  const auto vec3 = [](const Eigen::Vector3d& v) { return vector_array({v.x(), v.y(), v.z()}); };
  d["mean_rotation_vector"] = vec3(r.mean_rotation_vector);
  d["rotation_vector_standard_error"] = vec3(r.rotation_vector_standard_error);
  d["mean_translation"] = vec3(r.mean_translation);
  d["translation_standard_error"] = vec3(r.translation_standard_error);
  // The motions' scale error along the reference's motion (fraction), its standard error and pairs.
  d["scale_error"] = r.scale_error;
  d["scale_standard_error"] = r.scale_standard_error;
  d["scale_pairs"] = r.scale_pairs;
  return d;
}

py::dict kitti(const py::object& reference, const py::object& estimate, const std::vector<double>& lengths,
               std::size_t step) {
  KittiDriftSettings s;
  s.segment_lengths = lengths;
  s.step = step;
  const KittiDriftResult r =
      kitti_drift(read_poses(estimate, "estimate"), read_poses(reference, "reference"), s);
  check(r.status, "kitti_drift");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  py::dict d;
  d["segments"] = r.segments;
  d["translation"] = r.translation;  // segments > 0: the library's status says so
  d["rotation"] = r.rotation;
  py::list per_length;
  for (const KittiSegmentDrift& l : r.per_length) {
    py::dict e;
    e["length"] = l.length;
    e["segments"] = l.segments;
    e["translation"] = l.segments ? l.translation : nan;
    e["rotation"] = l.segments ? l.rotation : nan;
    per_length.append(e);
  }
  d["per_length"] = per_length;
  return d;
}

py::dict wulf(const py::object& reference, const py::object& estimate) {
  const WulfResult r = wulf_metric(read_poses(estimate, "estimate"), read_poses(reference, "reference"));
  check(r.status, "wulf");
  py::dict d;
  d["position_rms"] = r.position_rms;
  d["orientation_rms"] = r.orientation_rms;
  d["position_errors"] = vector_array(r.position_errors);
  d["orientation_errors"] = vector_array(r.orientation_errors);
  return d;
}

py::dict kuemmerle(const py::object& reference, const py::object& estimate, const py::object& relations) {
  const PoseList est = read_poses(estimate, "estimate");
  KummerleResult r;
  if (relations.is_none()) {
    r = kummerle_metric(est, read_poses(reference, "reference"));
  } else {
    std::vector<PoseRelation> list;
    for (const py::handle item : relations) {
      const py::tuple t = py::reinterpret_borrow<py::object>(item).cast<py::tuple>();
      if (t.size() != 2 && t.size() != 3)
        throw py::value_error("relations: expected (i, j) or (i, j, reference_motion 4×4) tuples");
      PoseRelation rel;
      rel.i = t[0].cast<std::size_t>();
      rel.j = t[1].cast<std::size_t>();
      if (t.size() == 3) {
        rel.has_reference_motion = true;
        rel.reference_motion = transform_from_array(t[2], "relations: reference_motion");
      }
      list.push_back(rel);
    }
    const PoseList ref = reference.is_none() ? PoseList{} : read_poses(reference, "reference");
    r = kummerle_metric(est, ref, list);
  }
  check(r.status, "kuemmerle");
  py::dict d;
  d["translation_rms"] = r.translation_rms;
  d["rotation_rms"] = r.rotation_rms;
  d["translation_errors"] = vector_array(r.translation_errors);
  d["rotation_errors"] = vector_array(r.rotation_errors);
  return d;
}

py::dict car_slip(const py::object& poses, double min_chord) {
  if (!(min_chord > 0.0)) throw py::value_error("vehicle_slip: min_chord must be positive");
  const VehicleSlip s = vehicle_slip(read_poses(poses, "poses"), min_chord);
  py::dict d;
  d["mounting"] = s.mounting;
  d["slip"] = vector_array(s.slip);
  return d;
}

py::array_t<double> flat(const py::object& poses) {
  return poses_array(on_ground_plane(read_poses(poses, "poses")));
}

}  // namespace

void bind_metrics(py::module_& m) {
  py::module_ metrics = m.def_submodule(
      "metrics",
      "Trajectory metrics over N×4×4 pose arrays (world ← body, associated by index, same length), from "
      "eval/trajectory_metrics.hpp. Arguments are (reference, estimate); metres and radians. Non-finite "
      "or non-rigid poses, different lengths and too few poses raise ValueError.");
  metrics.def(
      "ate", &ate,
      "Absolute trajectory error: the estimate is aligned onto the reference by `alignment` — 'se3' "
      "(default: rigid Umeyama on the positions, evo's semantics), 'sim3' (with scale), 'origin' (the "
      "first poses made equal: T = ref₀·est₀⁻¹) or 'none' — "
      "then translation error ‖p_ref − align(p_est)‖ and rotation error angle(R_ref⁻¹·R_align·R_est) "
      "per pose. Returns translation_rms (the ATE, m), rotation_rms (rad), translation and rotation "
      "statistics (count, mean, std, min, max, rms, median), translation_errors (per pose) and "
      "the alignment applied (rotation 3×3, translation 3, scale).",
      py::arg("reference"), py::arg("estimate"), py::arg("alignment") = "se3");
  metrics.def(
      "rpe", &rpe,
      "Relative pose error (evo's evo_rpe): pairs (i, j) `delta` apart in 'frames' (default 1: "
      "consecutive poses) or 'meters' along the reference; consecutive non-overlapping pairs, or a "
      "pair from every pose with all_pairs=True (meters: accepted when |path − delta| ≤ tolerance). "
      "E_ij = (ref_i⁻¹ ref_j)⁻¹ (est_i⁻¹ est_j); returns translation_rms (m), rotation_rms (rad), "
      "statistics, per-pair errors, the pairs (K×2), and per axis the signed mean of E_ij in pose "
      "i's frame with its standard error: mean_rotation_vector (rad), rotation_vector_standard_error, "
      "mean_translation (m), translation_standard_error (a bias every step shares lies many "
      "standard errors from 0); scale_error, the motions' shortfall (< 0) or excess along the "
      "reference's motion over its path (a fraction), with scale_standard_error and scale_pairs "
      "(pairs whose reference moves at least 1 cm).",
      py::arg("reference"), py::arg("estimate"), py::arg("delta") = 1.0, py::arg("unit") = "frames",
      py::arg("all_pairs") = false, py::arg("tolerance") = 0.1);
  metrics.def(
      "kitti_drift", &kitti,
      "KITTI odometry devkit drift: for every `step`-th first frame and each length L, the first frame "
      "more than L further along the reference; errors ‖t(E)‖/L and angle(E)/L averaged. Returns "
      "segments (count), translation (fraction: ×100 for KITTI's %), rotation (rad/m), and per_length "
      "entries (NaN for a length no segment fits). A path shorter than the shortest length raises "
      "ValueError (the library's status).",
      py::arg("reference"), py::arg("estimate"),
      py::arg("segment_lengths") = std::vector<double>{100, 200, 300, 400, 500, 600, 700, 800},
      py::arg("step") = 10);
  metrics.def("wulf", &wulf,
              "Wulf's absolute errors (thesis eqs. 6.1–6.3), no alignment: e_pos,i = ‖p_i − p_i*‖, e_ori,i = "
              "‖(α, β, γ)_i − (α, β, γ)_i*‖ with each angle difference wrapped to (−π, π]; returns "
              "position_rms (m), orientation_rms (rad) and the per-pose errors.",
              py::arg("reference"), py::arg("estimate"));
  metrics.def("kuemmerle", &kuemmerle,
              "Kümmerle's relative displacement error (thesis eq. 6.6), translation and rotation separately: "
              "δ_ij = x_i⁻¹ x_j, ε = δ*_ij⁻¹ δ_ij over consecutive pairs, or over `relations`: (i, j) pairs, "
              "or (i, j, reference_motion 4×4) with the reference displacement given (reference may then be "
              "None). Returns translation_rms (m), rotation_rms (rad) and the per-relation errors.",
              py::arg("reference"), py::arg("estimate"), py::arg("relations") = py::none());
  metrics.def(
      "vehicle_slip", &car_slip,
      "Whether `poses` (N×4×4, world ← sensor, z up) are a car's path, as `sextant eval --car-slip`: "
      "a car follows an arc over one step, whose chord leaves the start heading at half the heading "
      "change. Returns mounting, the car's axis of travel in the sensor frame as a yaw (rad; NaN when "
      "no step moves `min_chord` metres), and slip, per step k (pose k to k + 1) the chord's signed "
      "component across that arc (m, left positive; NaN when the mounting is unknown). A reference "
      "step that slips far more than a car can is no reference for that step.",
      py::arg("poses"), py::arg("min_chord") = 0.5);
  metrics.def(
      "on_ground_plane", &flat,
      "`poses` (N×4×4, world ← body, z up) with their x, y and heading only: no height, roll or pitch. "
      "Any metric of both trajectories so projected judges the motion over the ground alone, as "
      "`sextant eval --ground-plane` (for a reference whose height and tilt cannot be trusted). Each "
      "trajectory is projected in its own world frame: align the estimate onto the reference first "
      "(`ate`'s alignment) when their frames differ.",
      py::arg("poses"));
}

}  // namespace sextant::python
