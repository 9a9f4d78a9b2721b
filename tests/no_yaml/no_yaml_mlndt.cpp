// A library user's ML-NDT registration: settings in code, no YAML anywhere (this program links
// Sextant::matchers alone; tests/no_yaml/CMakeLists.txt). A room of planes and boxes is moved by a
// known pose; ML-NDT (the MlndtMatcher, then register_pair with a typed MatcherChoice) must find it.
#include <cmath>
#include <cstdio>

#include "sextant/core/pose.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/matchers/matcher_choice.hpp"
#include "sextant/matchers/mlndt_matcher.hpp"
#include "sextant/matchers/mlndt_presets.hpp"
#include "sextant/matchers/register_pair.hpp"
#include "sextant/matchers/samplers.hpp"

namespace {

using sextant::PointCloud;

/// Points on an axis-aligned box surface [lo, hi], every `step` metres.
void add_box(PointCloud& cloud, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi, float step) {
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (float side : {lo[axis], hi[axis]})
      for (float a = lo[u]; a <= hi[u]; a += step)
        for (float b = lo[v]; b <= hi[v]; b += step) {
          Eigen::Vector3f p;
          p[axis] = side;
          p[u] = a;
          p[v] = b;
          cloud.push_back(p);
        }
  }
}

PointCloud room() {
  PointCloud cloud;
  add_box(cloud, {-10.0f, -7.0f, 0.0f}, {10.0f, 7.0f, 3.0f}, 0.2f);  // walls, floor, ceiling
  add_box(cloud, {-4.0f, -2.0f, 0.0f}, {-2.5f, 1.0f, 1.2f}, 0.1f);   // furniture
  add_box(cloud, {3.0f, 2.0f, 0.0f}, {5.0f, 3.0f, 2.0f}, 0.1f);
  add_box(cloud, {1.0f, -5.0f, 0.0f}, {1.6f, -4.4f, 2.5f}, 0.1f);
  return cloud;
}

bool near(const char* what, const Eigen::Isometry3d& truth, const Eigen::Isometry3d& found) {
  const Eigen::Isometry3d error = truth.inverse() * found;
  const double cm = 100.0 * sextant::translation_norm(error);
  const double deg = sextant::rotation_angle(error) * 180.0 / M_PI;
  std::printf("%s: %.2f cm, %.3f deg off\n", what, cm, deg);
  return cm < 5.0 && deg < 0.5;
}

}  // namespace

int main() {
  // p_reference = truth · p_input: the input is the room seen from a pose 0.6 m and 6° away.
  const Eigen::Isometry3d truth = sextant::to_isometry({0.5, -0.3, 0.05, 0.0, 0.0, 6.0 * M_PI / 180.0});
  const PointCloud reference = room();
  const PointCloud input = reference.transformed(truth.inverse());

  sextant::MlndtSettings settings;  // the library's defaults (the `default` preset), changed in code
  settings.pyramid.layers = 3;
  settings.optimizer.max_iterations = 60;
  std::string why;
  if (!settings.valid(&why)) {
    std::printf("invalid settings: %s\n", why.c_str());
    return 1;
  }
  sextant::MlndtMatcher matcher(settings);
  matcher.set_reference(reference);
  sextant::Rng rng(7);
  const sextant::GridSampler sampler(sextant::GridSamplerSettings{0.5, 5, 3});
  const PointCloud sample = input.subset(sampler.select(input, rng));
  const sextant::RegistrationResult direct = matcher.align(sample, Eigen::Isometry3d::Identity());
  bool ok = near("MlndtMatcher", truth, direct.T);

  sextant::PairRegistrationRequest request;  // the policy of `sextant match`, chosen in code
  request.matcher = sextant::matcher_choice(settings);
  request.sampler = sextant::sampler_factory(sextant::GridSamplerSettings{0.5, 5, 3});
  request.init = Eigen::Isometry3d::Identity();
  const sextant::PairRegistration pair = sextant::register_pair(reference, input, request);
  ok = near("register_pair", truth, pair.match.result.T) && ok;

  // The thesis' exact settings, asked for in code (mlndt_presets.hpp).
  const std::optional<sextant::MlndtSettings> thesis = sextant::mlndt_preset("thesis");
  const bool thesis_ok = thesis && thesis->optimizer.solver == sextant::SolverKind::kNewton &&
                         thesis->optimizer.step_control == sextant::StepControl::kNone &&
                         std::isinf(thesis->max_distance) && thesis->unmatched_penalty == 50.0 &&
                         !thesis->precision.enabled() && !sextant::mlndt_preset("fastest");
  std::printf("the thesis preset in code: %s\n", thesis_ok ? "as the thesis" : "wrong");
  return ok && thesis_ok ? 0 : 1;
}
