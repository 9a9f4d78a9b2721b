// sextant.match(): one registration of a pair as `sextant match` makes it (match_request.hpp), with
// the GIL released while it runs, and the MatchResult it returns.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "match_request.hpp"
#include "python_yaml.hpp"
#include "sextant/matchers/register_pair.hpp"
#include "sextant/matchers/registration_quality.hpp"
#include "sextant/pipeline/matcher_request.hpp"

namespace sextant::python {
namespace {

/// What sextant.match() returns (attributes only; see the docstrings in bind_match).
struct MatchResult {
  py::array_t<double> T, H, covariance, centre;
  py::tuple pose;
  bool converged = false, trusted = false;
  std::string termination, trust, trust_reason, search, method, preset, sampling, fallback;
  int iterations = 0;
  double seconds = 0, reference_seconds = 0, sampling_seconds = 0, score = 0, kept_fraction = 0;
  double overlap = 0, constraint_ratio = 0, fit_ratio = 0;
  std::size_t matched_points = 0, input_points = 0;
};

MatchResult to_python(const MatchOutcome& o, const MatcherConfig& config) {
  const RegistrationResult& r = o.match.result;
  MatchResult out;
  out.T = transform_array(r.T);
  out.H = matrix6_array(r.H);
  out.covariance = matrix6_array(registration_covariance(r.H));
  out.centre = vector_array({o.centre.x(), o.centre.y(), o.centre.z()});
  const Pose6 p = to_pose6(r.T);
  out.pose = py::make_tuple(p.x, p.y, p.z, p.alpha, p.beta, p.gamma);
  out.converged = r.converged;
  out.trusted = r.quality.trusted();
  out.termination = to_string(r.why);
  out.trust = to_string(r.quality.trust);
  out.trust_reason = r.quality.reason;
  out.search = o.search;
  out.method = config.request.method;
  out.preset = config.preset;
  out.sampling = config.request.sampling;
  out.fallback = r.fallback;
  out.iterations = r.iterations;
  out.seconds = r.seconds;
  out.reference_seconds = o.match.reference_seconds;
  out.sampling_seconds = o.match.sampling_seconds;
  out.score = r.score;
  out.kept_fraction = o.match.kept_fraction;
  out.overlap = r.quality.overlap;
  out.constraint_ratio = r.quality.constraint_ratio;
  out.fit_ratio = r.quality.fit_ratio;
  out.matched_points = r.matched_points;
  out.input_points = r.input_points;
  return out;
}

MatchResult match(const py::object& reference, const py::object& input, const py::object& init,
                  const std::string& method, const py::object& preset, const std::string& sampling,
                  std::uint64_t seed, const py::object& wide_basin, const py::object& sampler_settings,
                  const py::kwargs& settings) {
  MatcherRequest asked = matcher_request("match()", method, preset, sampling, settings, sampler_settings);
  MatchRequest request;
  request.seed = seed;
  if (!init.is_none()) request.init = transform_from_array(init, "init");
  if (py::isinstance<py::bool_>(wide_basin) && !wide_basin.cast<bool>()) {
    request.wide_basin_retry = false;
  } else if (py::isinstance<py::bool_>(wide_basin) || py::isinstance<py::dict>(wide_basin)) {
    if (asked.matcher["wide_basin"].IsDefined())
      throw py::value_error("wide_basin is given twice (argument and setting)");
    asked.matcher["wide_basin"] = py::isinstance<py::dict>(wide_basin)
                                      ? yaml_from_python(wide_basin, "wide_basin")
                                      : YAML::Node(YAML::NodeType::Map);
  } else if (!wide_basin.is_none()) {
    throw py::type_error("wide_basin: expected None, True, False or a dict of wide-basin settings");
  }
  const MatcherConfig config = read_matcher_config(asked, Face::python);
  request.spec = config.spec;
  const PointCloud reference_cloud = cloud_from_object(reference, "reference", Borrowing::kInPlace);
  const PointCloud input_cloud = cloud_from_object(input, "input", Borrowing::kInPlace);
  MatchOutcome outcome;
  {
    const py::gil_scoped_release release;
    outcome = run_match_request(reference_cloud, input_cloud, request);
  }
  return to_python(outcome, config);
}

std::string repr(const MatchResult& r) {
  const auto t = r.T.unchecked<2>();
  char text[256];
  std::snprintf(text, sizeof text,
                "MatchResult(trust='%s', converged=%s, iterations=%d, t=[%.4f, %.4f, %.4f], overlap=%.3f)",
                r.trust.c_str(), r.converged ? "True" : "False", r.iterations, t(0, 3), t(1, 3), t(2, 3),
                r.overlap);
  return text;
}

constexpr char kMatchDoc[] = R"doc(Register one pair of scans, as ``sextant match`` does.

Returns the rigid transform T that maps input points into the reference frame
(p_reference = T · p_input) and the library's assessment of it.

Arguments:
  reference, input: the clouds, each an N×3 (x y z) or N×4 (x y z intensity) NumPy array of float32
      or float64 in metres, or a file path read with read_cloud(). A C-contiguous N×3 float32 array
      (what read_cloud() returns) is read in place, without a copy: do not change it from another
      thread while match() runs (it releases the GIL). Other arrays are copied once into the
      library's float32 cloud. NaN/Inf rows are a ValueError.
  init: 4×4 initial guess (rigid). None: the identity, and the wide basin searches yaw and x/y around
      it first (``sextant match`` without --init). With a guess the guess is refined and an untrusted
      result is registered again with the wide basin, as the CLI does.
  method: matcher name: mlndt (default), fbmlndt, ndt, icp_p2p, icp_p2l, pcl_ndt, pcl_icp, pcl_gicp.
  preset: mlndt/fbmlndt settings preset: "default" (when None), "thesis", "outdoor"
      (docs/matcher_defaults.md); an InputError for other matchers.
  sampling: input sampler: all, regular, random, gbs (default), fbs.
  seed: seed of the sampler's random choices (the CLI's --seed).
  wide_basin: None (the CLI's choice above), False (--no-wide-basin: never search or retry), True or a
      dict of wide-basin settings (always search with them: a ``wide_basin:`` map in --config).
  sampler_settings: dict of sampler settings (the ``sampler:`` map of --config), None for defaults.
  **settings: matcher settings, as the ``matcher:`` map of --config (e.g. solver="lm", layers=6);
      an unknown key or a bad value raises InputError.

The result is identical to ``sextant match reference input`` with the same options (same seed, same
sampler, same presets): the same calls in the same order.)doc";

}  // namespace

void bind_match(py::module_& m) {
  py::class_<MatchResult>(m, "MatchResult",
                          "The result of match(): the transform, its Hessian and covariance, and trust.")
      .def_readonly("T", &MatchResult::T, "4×4 float64: p_reference = T · p_input")
      .def_readonly(
          "pose", &MatchResult::pose,
          "T as (x, y, z, alpha, beta, gamma): metres and radians, R = Rx(alpha)·Ry(beta)·Rz(gamma)")
      .def_readonly("H", &MatchResult::H,
                    "6×6 Hessian of the matcher's score at the solution over the parameters (x, y, z, "
                    "alpha, beta, gamma) in metres and radians (Euler angles as in pose). NDT and ML-NDT: "
                    "the second derivative of the score over the pose vector of T (ML-NDT's score is a sum "
                    "of Mahalanobis terms, dimensionless, so H is in 1/m², 1/(m·rad), 1/rad²); ICP: the "
                    "Gauss–Newton information JᵀJ of a small increment applied on the left of T; PCL's "
                    "peers: the negated Hessian of PCL's NDT score, or zeros (no Hessian).")
      .def_readonly("centre", &MatchResult::centre,
                    "the point registered about [m], in the clouds' coordinates: (0, 0, 0), their origin, "
                    "unless the clouds lie far from it (georeferenced), when it is the middle of the "
                    "reference's box; H and the covariance are about it, T is in the clouds' coordinates")
      .def_readonly("covariance", &MatchResult::covariance,
                    "6×6 R = H⁻¹ (the thesis' eq. 3.50), same parameter order as H, in m², m·rad, rad²; all "
                    "NaN when H is not positive definite (a degenerate scene, or a matcher without H). Not a "
                    "calibrated noise: the thesis' filters scale it (for a score that is a sum of eᵀC⁻¹e the "
                    "Gaussian likelihood's covariance is 2·H⁻¹).")
      .def_readonly("converged", &MatchResult::converged, "the optimiser's step became small")
      .def_readonly("termination", &MatchResult::termination,
                    "why the optimiser stopped: converged, max_iterations, too_few_correspondences, ...")
      .def_readonly("trust", &MatchResult::trust,
                    "the library's assessment: ok, not_converged, degenerate, low_overlap or suspect")
      .def_readonly("trust_reason", &MatchResult::trust_reason, "empty when trust is ok, else why not")
      .def_readonly("trusted", &MatchResult::trusted, "trust == 'ok' (``sextant match`` exits 0)")
      .def_readonly("iterations", &MatchResult::iterations, "optimiser iterations")
      .def_readonly("seconds", &MatchResult::seconds, "registration time [s] (the CLI's 'seconds')")
      .def_readonly("reference_seconds", &MatchResult::reference_seconds,
                    "time to build the reference model (grids, trees) [s]")
      .def_readonly("sampling_seconds", &MatchResult::sampling_seconds, "time to sample the input [s]")
      .def_readonly("score", &MatchResult::score, "the matcher's score at the solution")
      .def_readonly("matched_points", &MatchResult::matched_points, "input points matched at the solution")
      .def_readonly("input_points", &MatchResult::input_points,
                    "input points offered to the matcher (after sampling)")
      .def_readonly("kept_fraction", &MatchResult::kept_fraction, "sampled / all input points")
      .def_readonly("overlap", &MatchResult::overlap, "matched / input points (after sampling) [fraction]")
      .def_property_readonly(
          "matched_fraction",
          [](const MatchResult& r) {
            return r.input_points
                       ? static_cast<double>(r.matched_points) / static_cast<double>(r.input_points)
                       : std::numeric_limits<double>::quiet_NaN();
          },
          "matched_points / input_points (NaN without input points), as `sextant match --json`; the "
          "overlap of the trust assessment")
      .def_readonly("constraint_ratio", &MatchResult::constraint_ratio,
                    "weakest / strongest eigenvalue of H with rotations scaled to metres (NaN: no H)")
      .def_readonly("fit_ratio", &MatchResult::fit_ratio,
                    "mean matched score / its prediction (0: the matcher predicts none)")
      .def_readonly("search", &MatchResult::search,
                    "how the result was found (from the guess, wide basin, retry)")
      .def_readonly("method", &MatchResult::method, "the matcher")
      .def_readonly("preset", &MatchResult::preset, "the preset applied ('' for matchers without presets)")
      .def_readonly("sampling", &MatchResult::sampling, "the sampler")
      .def_readonly("fallback", &MatchResult::fallback, "empty, or what the matcher fell back to and why")
      .def("__repr__", &repr);
  m.def("match", &match, kMatchDoc, py::arg("reference"), py::arg("input"), py::arg("init") = py::none(),
        py::arg("method") = "mlndt", py::arg("preset") = py::none(), py::arg("sampling") = "gbs",
        py::arg("seed") = 1, py::arg("wide_basin") = py::none(), py::arg("sampler_settings") = py::none());
}

}  // namespace sextant::python
