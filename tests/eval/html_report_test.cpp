#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include "sextant/eval/html_report.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/eval/sparsity.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

HtmlReport sample_report() {
  HtmlReport page;
  page.title = "Sextant <report>";
  auto& s = page.add_section("e18", "E18 — Metric examples");
  s.add_paragraph("Wulf & Kümmerle on the thesis' toy cases.");
  Table t;
  t.caption = "Table 6.1";
  t.add_column("case").add_compared_column("Wulf").add_compared_column("Kümmerle");
  t.add_row({Cell::text("1"), Cell::number(1.5), Cell::number(1.5), Cell::number(2.449), Cell::number(2.45)});
  s.add_table(t);
  s.add_figure("e18/plot.svg", "A figure");
  s.add_figure("e18/sparsity.png", "Sparsity");
  s.add_claim({"Kümmerle is larger than Wulf", Verdict::holds, "2.45 > 1.5"});
  s.add_claim({"Magic", Verdict::does_not_hold, "0 < 1"});
  page.add_section("e19", "E19").add_claim({"EKF best", Verdict::not_comparable, "no data"});
  page.provenance.push_back({"git", "abc123 (dirty)"});
  return page;
}

TEST(HtmlReport, RendersSectionsClaimsAndProvenance) {
  const std::string html = sample_report().render();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<title>Sextant &lt;report&gt;</title>"), std::string::npos);
  EXPECT_NE(html.find("<a href=\"#e18\">E18 — Metric examples</a>"), std::string::npos);
  EXPECT_NE(html.find("Wulf &amp; Kümmerle"), std::string::npos);
  EXPECT_NE(html.find("<th colspan=\"2\">Kümmerle</th>"), std::string::npos);
  EXPECT_NE(html.find("<img src=\"e18/plot.svg\" alt=\"A figure\">"), std::string::npos);
  EXPECT_NE(html.find("v-holds\">holds</span> Kümmerle is larger than Wulf"), std::string::npos);
  EXPECT_NE(html.find("v-not-comparable\">not comparable</span> EKF best"), std::string::npos);
  EXPECT_NE(html.find("v-does-not-hold\">does not hold</span> Magic"), std::string::npos);
  EXPECT_NE(html.find("<dt>git</dt><dd>abc123 (dirty)</dd>"), std::string::npos);
  EXPECT_EQ(sample_report().sections[0].figures().size(), 2u);
  EXPECT_EQ(to_string(Verdict::not_comparable), "not comparable");
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The table of contents stays in view (fixed side bar), lists every section (by its short title
// when given) and the provenance, and every section leads back to the top.
TEST(HtmlReport, StickyContentsListEverySectionAndSectionsLeadBackToTheTop) {
  HtmlReport page = sample_report();
  page.add_section("e01", "E1 — Basin <quick, n = 4 runs>", "E1 — Basin");
  const std::string html = page.render();
  const std::size_t nav = html.find("<nav class=\"sx-toc\"");
  ASSERT_NE(nav, std::string::npos);
  const std::string toc = html.substr(nav, html.find("</nav>", nav) - nav);
  EXPECT_NE(html.find("nav.sx-toc{position:fixed;"), std::string::npos);
  EXPECT_NE(html.find("nav.sx-toc{position:sticky;"), std::string::npos);  // narrow screens: a top bar
  std::size_t sections = 0;
  for (std::size_t at = html.find("<section id=\""); at != std::string::npos;
       at = html.find("<section id=\"", at + 1)) {
    const std::string id = html.substr(at + 13, html.find('"', at + 13) - at - 13);
    EXPECT_NE(toc.find("<a href=\"#" + id + "\">"), std::string::npos) << id;
    ++sections;
  }
  EXPECT_EQ(sections, 4u);  // e18, e19, e01 and the provenance
  EXPECT_EQ(occurrences(toc, "<li>"), sections);
  EXPECT_NE(toc.find("<a href=\"#e01\">E1 — Basin</a>"), std::string::npos);  // the short title
  EXPECT_NE(html.find("<h2>E1 — Basin &lt;quick, n = 4 runs&gt;</h2>"), std::string::npos);
  // One "back to top" per section, and the top exists.
  EXPECT_EQ(occurrences(html, "<p class=\"sx-top\"><a href=\"#top\">"), sections);
  EXPECT_NE(html.find("<h1 id=\"top\">"), std::string::npos);
  // Without sections there is no contents bar.
  HtmlReport empty;
  EXPECT_EQ(empty.render().find("<nav"), std::string::npos);
}

TEST(HtmlReport, ViewsAreLinkedAndEscaped) {
  HtmlReport page;
  page.add_section("e01", "E1").add_view("e01/clouds_3d.html", "before & after").add_figure("e01/a.svg", "A");
  const std::string html = page.render();
  EXPECT_NE(html.find("<a href=\"e01/clouds_3d.html\">3D view: before &amp; after</a>"), std::string::npos);
  EXPECT_EQ(page.sections[0].views(), (std::vector<std::string>{"e01/clouds_3d.html"}));
  EXPECT_EQ(page.sections[0].figures().size(), 1u);  // a view is not a figure
}

/// Writes the sample page with its figures into `dir`; `skip_png` leaves one image missing.
fs::path write_sample(const fs::path& dir, bool skip_png) {
  fs::remove_all(dir);
  XYPlot plot;
  plot.add_line("a", {0, 1, 2}, {0, 1, 4});
  write_svg(render_svg(plot), dir / "e18" / "plot.svg");
  if (!skip_png) {
    std::vector<std::pair<std::size_t, std::size_t>> entries{{0, 0}, {1, 1}, {2, 2}, {0, 2}};
    write_png(sparsity_image(sparsity_grid(3, 3, entries), 20), dir / "e18" / "sparsity.png");
  }
  sample_report().write(dir / "index.html");
  return dir / "index.html";
}

// Renders the page in headless Chromium through scripts/check_report_html.sh. The browser check
// must run, not skip: scripts/test.sh installs Debian's chromium, so a missing browser is a failure.
TEST(HtmlReport, RendersWithoutBrokenImagesInChromium) {
  ASSERT_EQ(std::system("command -v chromium >/dev/null 2>&1"), 0)
      << "chromium is not installed: scripts/test.sh installs it (apt-get install chromium)";
  const fs::path dir = fs::temp_directory_path() / "sextant_eval_html_test";
  const std::string script = std::string(SEXTANT_SOURCE_DIR) + "/scripts/check_report_html.sh";
  const std::string good = "'" + script + "' '" + write_sample(dir, false).string() + "' >/dev/null 2>&1";
  EXPECT_EQ(std::system(good.c_str()), 0);
  const std::string bad = "'" + script + "' '" + write_sample(dir, true).string() + "' >/dev/null 2>&1";
  const int status = std::system(bad.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sextant
