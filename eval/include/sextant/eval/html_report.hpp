#pragma once
// The report's index.html: sections holding paragraphs, tables, figures, links to interactive 3D
// views and the thesis' claims with a verdict computed from our numbers, then a provenance block.
// A table of contents stays in view (a fixed side bar; a sticky top bar on narrow screens) and
// every section ends with a link back to the top. Self-contained (inline CSS, no script), images
// and views referenced by relative path.
//
//   HtmlReport page;
//   page.title = "Sextant reproduction report";
//   auto& s = page.add_section("e02", "E2 — Overall accuracy on 100 scans");
//   s.add_table(table).add_figure("e02/errors.svg", "Error per scan");
//   s.add_claim({"ML-NDT succeeds more often than NDT", Verdict::holds, "98 % vs 90 % (ours 97 / 88)"});
//   page.provenance.push_back({"git", "abc123 (dirty)"});
//   page.write("report/index.html");
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "sextant/eval/table.hpp"

namespace sextant {

/// A claim's outcome, decided on an interval (see verdict.hpp): `inconclusive` when the interval
/// straddles the claim, `not_comparable` when there is nothing to decide on.
enum class Verdict { holds, does_not_hold, inconclusive, not_comparable };

/// "holds", "does not hold", "inconclusive", "not comparable".
std::string to_string(Verdict verdict);

/// A thesis claim is counted on the front page; a sanity check (e.g. "beats the odometry guess")
/// guards the experiment itself and is listed apart from the thesis' claims.
enum class ClaimKind { thesis, sanity };

struct Claim {
  std::string statement;  ///< the thesis' claim, e.g. "ML-NDT is about 4× faster than NDT"
  Verdict verdict = Verdict::not_comparable;
  std::string evidence;  ///< the numbers behind the verdict
  ClaimKind kind = ClaimKind::thesis;
  /// Why a claim does not hold, from the run's own measurements: "<kind>: …", the kind one of data (which
  /// property, measured), implementation, unfair test or the thesis (what it reports that cannot be
  /// reproduced, and why). Shown as a line "cause: …" under the evidence; empty: none measured.
  std::string cause = {};
};

class HtmlSection {
 public:
  HtmlSection(std::string id, std::string title, std::string toc_title = "")
      : id_(std::move(id)), title_(std::move(title)), toc_title_(std::move(toc_title)) {}

  HtmlSection& add_paragraph(const std::string& text);  ///< plain text (escaped)
  HtmlSection& add_html(const std::string& html);       ///< raw HTML fragment (not escaped)
  HtmlSection& add_table(const Table& table);
  /// `src` relative to the page (e.g. "e02/errors.svg"); `caption` below the image.
  HtmlSection& add_figure(const std::string& src, const std::string& caption);
  /// A link to an interactive page (e.g. a cloud_view 3D scene), `src` relative to the page.
  HtmlSection& add_view(const std::string& src, const std::string& caption);
  HtmlSection& add_claim(const Claim& claim);

  const std::string& id() const { return id_; }
  const std::string& title() const { return title_; }
  /// The entry in the table of contents: the short title when given, else the title.
  const std::string& toc_title() const { return toc_title_.empty() ? title_ : toc_title_; }
  const std::vector<std::string>& figures() const { return figures_; }
  const std::vector<std::string>& views() const { return views_; }
  const std::vector<Claim>& claims() const { return claims_; }
  /// The section as HTML (blocks in insertion order, then the thesis' claims, then the sanity checks).
  std::string render() const;

 private:
  std::string id_, title_, toc_title_;
  std::vector<std::string> blocks_;
  std::vector<std::string> figures_, views_;
  std::vector<Claim> claims_;
};

struct HtmlReport {
  std::string title = "Sextant report";
  std::string subtitle;
  std::string front_html;  ///< raw HTML shown first (e.g. the experiments' headline and overview)
  std::vector<HtmlSection> sections;
  std::vector<std::pair<std::string, std::string>> provenance;  ///< key, value

  /// `toc_title`: a shorter entry for the table of contents (empty = the title).
  HtmlSection& add_section(const std::string& id, const std::string& title,
                           const std::string& toc_title = "");
  /// Whole page: the table of contents (every section and the provenance), a claim summary (thesis
  /// claims per verdict, sanity checks apart), the front HTML, sections, provenance.
  std::string render() const;
  /// Renders and writes atomically.
  void write(const std::filesystem::path& path) const;
};

}  // namespace sextant
