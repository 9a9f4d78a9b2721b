#pragma once
// The report's index.html: sections holding paragraphs, tables, figures and the thesis' claims
// with a verdict computed from our numbers, then a provenance block. Self-contained (inline CSS),
// images referenced by relative path.
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
};

class HtmlSection {
 public:
  HtmlSection(std::string id, std::string title) : id_(std::move(id)), title_(std::move(title)) {}

  HtmlSection& add_paragraph(const std::string& text);  ///< plain text (escaped)
  HtmlSection& add_html(const std::string& html);       ///< raw HTML fragment (not escaped)
  HtmlSection& add_table(const Table& table);
  /// `src` relative to the page (e.g. "e02/errors.svg"); `caption` below the image.
  HtmlSection& add_figure(const std::string& src, const std::string& caption);
  HtmlSection& add_claim(const Claim& claim);

  const std::string& id() const { return id_; }
  const std::string& title() const { return title_; }
  const std::vector<std::string>& figures() const { return figures_; }
  const std::vector<Claim>& claims() const { return claims_; }
  /// The section as HTML (blocks in insertion order, then the thesis' claims, then the sanity checks).
  std::string render() const;

 private:
  std::string id_, title_;
  std::vector<std::string> blocks_;
  std::vector<std::string> figures_;
  std::vector<Claim> claims_;
};

struct HtmlReport {
  std::string title = "Sextant report";
  std::string subtitle;
  std::string front_html;  ///< raw HTML shown first, before the contents (e.g. the experiments' overview)
  std::vector<HtmlSection> sections;
  std::vector<std::pair<std::string, std::string>> provenance;  ///< key, value

  HtmlSection& add_section(const std::string& id, const std::string& title);
  /// Whole page: a claim summary (thesis claims per verdict, sanity checks apart), the front HTML, a table
  /// of contents, sections, provenance.
  std::string render() const;
  /// Renders and writes atomically.
  void write(const std::filesystem::path& path) const;
};

}  // namespace sextant
