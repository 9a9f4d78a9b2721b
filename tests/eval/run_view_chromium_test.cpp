// run_view in a real browser: the page of a 10,000-step run with a 400,000-point map opens in headless
// Chromium (WebGL through SwiftShader) without freezing: within the time limit its script decodes the
// map (capped), every pose and every step, draws one marker per untrusted, not converged and recovered
// step, paints the estimate and the untrusted markers, and the step asked for in the URL ("#step=N")
// is shown with its reason. Skipped when Chromium is not installed.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>

#include "sextant/eval/run_view.hpp"
#include "sextant_test/run_view_page.hpp"
#include "sextant_test/temp_dir.hpp"

namespace sextant {
namespace {

/// A run of `steps` steps along a loop of streets 1.2 km round (a pose per 0.5 m, with a slow
/// height drift), the reference beside it, a map of `points` points along the streets' walls; every
/// 97th step untrusted, every 389th not converged, every 151st recovered.
RunView long_run(std::size_t steps, std::size_t points) {
  RunView view;
  view.title = "10 000 steps";
  const double kPi = 3.14159265358979323846;
  for (std::size_t i = 0; i <= steps; ++i) {
    const double a = 2.0 * kPi * static_cast<double>(i) / static_cast<double>(steps);
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() =
        Eigen::Vector3d(300.0 * std::cos(a) + 40.0 * std::cos(7 * a),
                        200.0 * std::sin(a) + 30.0 * std::sin(5 * a), 0.002 * static_cast<double>(i));
    view.estimate.push_back(T);
    T.translation().z() = 0.0;
    view.reference.push_back(T);
  }
  for (std::size_t k = 0; k < points; ++k) {
    const Eigen::Vector3d p = view.reference[k % steps].translation();
    const double side = (k % 2 ? 8.0 : -8.0), h = static_cast<double>(k % 13);
    view.map.push_back(Eigen::Vector3f(static_cast<float>(p.x() + side), static_cast<float>(p.y() + 0.3 * h),
                                       static_cast<float>(0.5 * h)));
  }
  for (std::size_t i = 0; i < steps; ++i) {
    RunViewStep s;
    s.number = i;
    s.pose = i + 1;
    s.from_scan = i;
    s.to_scan = i + 1;
    s.stamp = 1.6e9 + 0.1 * static_cast<double>(i);
    s.trust = s.first_trust = "ok";
    s.error_m = 0.01 + 0.001 * static_cast<double>(i % 50);
    s.error_deg = 0.05;
    if (i % 97 == 3) {
      s.trusted = false;
      s.trust = "suspect";
      s.recovery = "least_suspect";
      s.reason = "fit 1.43 above 1.1 x the median of the last trusted steps (step " + std::to_string(i) + ")";
    } else if (i % 389 == 7) {
      s.trusted = s.converged = false;
      s.trust = "not_converged";
      s.reason = "no convergence in 60 iterations";
    } else if (i % 151 == 5) {
      s.recovered = true;
      s.first_trust = "low_overlap";
      s.recovery = "wide_basin";
    }
    view.steps.push_back(s);
  }
  return view;
}

TEST(RunViewChromium, TenThousandStepRunOpensWithoutFreezing) {
  if (!test::chromium_installed()) GTEST_SKIP() << "chromium is not installed (apt-get install chromium)";
  test::TempDir tmp;
  const RunView view = long_run(10000, 400000);
  std::size_t untrusted = 0, not_converged = 0, recovered = 0;
  for (const RunViewStep& s : view.steps) {
    untrusted += verdict_of(s) == StepVerdict::untrusted;
    not_converged += verdict_of(s) == StepVerdict::not_converged;
    recovered += verdict_of(s) == StepVerdict::recovered;
  }
  ASSERT_EQ(untrusted, 104u);
  ASSERT_EQ(not_converged, 26u);
  ASSERT_EQ(recovered, 67u);
  write_run_view(view, tmp / "run.html");
  const nlohmann::json data = test::page_data(test::page_text(tmp / "run.html"));
  const std::size_t line = data["estimate"]["line"].size();
  EXPECT_LT(line, 10001u);                                 // decimated …
  EXPECT_GE(line, untrusted + not_converged + recovered);  // … and every marked step kept

  const std::size_t asked = 3 + 97 * 50;  // an untrusted step
  const auto t0 = std::chrono::steady_clock::now();
  const std::string dom =
      test::chromium_dom(tmp / "run.html", "#step=" + std::to_string(asked), tmp / "chromium");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "page " << std::filesystem::file_size(tmp / "run.html") / 1024 << " kB, line " << line
            << " of 10001 vertices; chromium opened it in " << seconds << " s\n";
  ASSERT_FALSE(dom.empty()) << "chromium failed, or the page froze past the time limit";
  EXPECT_EQ(test::dom_attribute(dom, "data-sx-drawn"), "ok") << dom.substr(0, 3000);
  EXPECT_EQ(test::dom_attribute(dom, "data-sx-decoded"), "150000,10001,10000");
  EXPECT_EQ(
      test::dom_attribute(dom, "data-sx-markers"),
      std::to_string(untrusted) + "," + std::to_string(not_converged) + "," + std::to_string(recovered));
  // The first frame painted the scene, the estimate's colour and the untrusted markers' colour.
  std::istringstream painted(test::dom_attribute(dom, "data-sx-painted"));
  std::size_t any = 0, estimate = 0, red = 0;
  char comma = 0;
  painted >> any >> comma >> estimate >> comma >> red;
  EXPECT_GT(any, 10000u) << test::dom_attribute(dom, "data-sx-painted");
  EXPECT_GT(estimate, 200u) << test::dom_attribute(dom, "data-sx-painted");
  EXPECT_GT(red, 50u) << test::dom_attribute(dom, "data-sx-painted");
  // The step asked for is shown with its reason; the list holds every marked step (a row each, and a
  // row for each reason).
  EXPECT_NE(dom.find("<h2>step " + std::to_string(asked) + " · scans " + std::to_string(asked) + " → " +
                     std::to_string(asked + 1) + "</h2>"),
            std::string::npos);
  EXPECT_NE(dom.find("(step " + std::to_string(asked) + ")</td>"), std::string::npos);
  std::size_t rows = 0;
  for (std::size_t at = dom.find("<tr data-step="); at != std::string::npos;
       at = dom.find("<tr data-step=", at + 1))
    ++rows;
  EXPECT_EQ(rows, 2 * (untrusted + not_converged) + recovered);
}

}  // namespace
}  // namespace sextant
