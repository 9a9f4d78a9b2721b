#pragma once
// An assessed, trusted registration quality with a given overlap and fit ratio, for the tests of the
// trust rules (registration_quality.hpp, horizon_check.hpp, sequence_trust.hpp).
#include "sextant/matchers/registration_result.hpp"

namespace sextant::test {

inline RegistrationQuality trusted(double overlap, double fit) {
  RegistrationQuality q;
  q.assessed = true;
  q.trust = Trust::kOk;
  q.overlap = overlap;
  q.fit_ratio = fit;
  return q;
}

}  // namespace sextant::test
