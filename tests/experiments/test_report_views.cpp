// The report page's navigation and 3D views: the table of contents lists every experiment's
// section (and the provenance) and stays in view; every section leads back to the top; E8's
// fig. 5.17 is linked as a 3D page that exists, shares the report's three.min.js and holds the
// three scans of the match.
#include <gtest/gtest.h>

#include "sextant/experiments/report.hpp"
#include "sextant/experiments/run_row.hpp"
#include "sextant/experiments/runner.hpp"
#include "test_helpers.hpp"

namespace sextant {
namespace {

using test::TempDir;

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ReportViews, ContentsListEverySectionAndFig517IsLinkedIn3D) {
  TempDir tmp;
  RunnerOptions o;
  o.results_root = tmp / "results";
  o.jobs = 2;
  o.quick = true;
  o.progress = false;
  const RunnerSummary room =
      run_experiment(std::filesystem::path(SEXTANT_SOURCE_DIR) / "experiments" / "e08_ekf_mlndt_2d.yaml", o);
  ASSERT_EQ(room.failed, 0u);
  test::write_text(tmp / "a.yaml", test::selftest_yaml("aux_a", 2, 1, 0));
  test::write_text(tmp / "b.yaml", test::selftest_yaml("aux_b", 2, 1, 0));
  ASSERT_EQ(run_experiment(tmp / "a.yaml", o).failed, 0u);
  ASSERT_EQ(run_experiment(tmp / "b.yaml", o).failed, 0u);
  const ReportSummary report = write_report({tmp / "results"}, tmp / "report");
  ASSERT_TRUE(report.failed.empty()) << report.failed.front();
  ASSERT_EQ(report.experiments, 3u);
  const std::string html = test::read_text(report.index_html);

  // Contents: a fixed bar listing each section once, by its title without the run counts.
  const std::size_t nav = html.find("<nav class=\"sx-toc\"");
  ASSERT_NE(nav, std::string::npos);
  const std::string toc = html.substr(nav, html.find("</nav>", nav) - nav);
  std::size_t sections = 0;
  for (std::size_t at = html.find("<section id=\""); at != std::string::npos;
       at = html.find("<section id=\"", at + 1)) {
    const std::string id = html.substr(at + 13, html.find('"', at + 13) - at - 13);
    EXPECT_EQ(occurrences(toc, "<a href=\"#" + id + "\">"), 1u) << id;
    ++sections;
  }
  EXPECT_EQ(sections, 3u + 1u);  // three experiments and the provenance
  EXPECT_EQ(occurrences(toc, "<li>"), sections);
  EXPECT_NE(toc.find(">E8 — EKF + ML-NDT in a 2D room simulation</a>"), std::string::npos) << toc;
  EXPECT_EQ(occurrences(html, "<a href=\"#top\">↑ Back to top</a>"), sections);

  // Fig. 5.17 in 3D, linked from E8's section and from nowhere else.
  const std::string e8 = test::report_section(html, "e08_ekf_mlndt_2d");
  const std::vector<std::string> views = test::view_links(e8);
  ASSERT_EQ(views, (std::vector<std::string>{"e08_ekf_mlndt_2d/scan_match_3d.html"}));
  EXPECT_EQ(test::view_links(html).size(), 1u);
  EXPECT_EQ(report.views, 1u);
  EXPECT_NE(e8.find("e08_ekf_mlndt_2d/scan_match.svg"), std::string::npos);  // the static figure stays
  const auto page_path = tmp / "report" / views.front();
  ASSERT_TRUE(std::filesystem::is_regular_file(page_path));
  EXPECT_TRUE(std::filesystem::is_regular_file(tmp / "report" / "three.min.js"));
  const std::string page = test::read_text(page_path);
  EXPECT_NE(page.find("<script src=\"../three.min.js\"></script>"), std::string::npos);
  EXPECT_EQ(occurrences(page, "{\"color\":"), 3u);  // previous scan, new scan at the guess, after ML-NDT
  for (const RunRow& row : read_rows(room.folder / kRunsJsonl).rows) {
    if (row.repetition != 0) continue;
    for (const char* name : {"reference", "guess", "matched"}) {
      const std::size_t n = row.series.at(std::string("match_") + name + "_x").size();
      EXPECT_NE(page.find("\"count\":" + std::to_string(n) + ","), std::string::npos) << name;
    }
  }
  // The guess and the match are shown one state each; the reference in both.
  EXPECT_NE(page.find("\"poses\":[null,["), std::string::npos);
  EXPECT_NE(page.find("],null],\"points\""), std::string::npos);
  // The Markdown summary links the page too.
  EXPECT_NE(test::read_text(tmp / "report" / "e08_ekf_mlndt_2d" / "e08_ekf_mlndt_2d.md")
                .find("(scan_match_3d.html)"),
            std::string::npos);
}

}  // namespace
}  // namespace sextant
