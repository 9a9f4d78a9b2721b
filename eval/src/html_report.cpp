#include "sextant/eval/html_report.hpp"

#include <sstream>

#include "sextant/core/atomic_file.hpp"

namespace sextant {

namespace {

const char* kStyle =
    R"(body{font-family:DejaVu Sans,Arial,sans-serif;margin:0;color:#222}
main.sx-main{max-width:1100px;margin:2em auto;padding:0 1em}
nav.sx-toc{position:fixed;top:0;left:0;bottom:0;width:240px;box-sizing:border-box;overflow-y:auto;padding:1em .9em;background:#f5f6f8;border-right:1px solid #d8dbe0;font-size:.82em;line-height:1.3;z-index:10}
nav.sx-toc p{margin:0 0 .6em;font-weight:bold}nav.sx-toc ol{list-style:none;margin:0;padding:0}nav.sx-toc li{margin:0 0 .45em}
nav.sx-toc a{color:#1a4f9c;text-decoration:none}nav.sx-toc a:hover{text-decoration:underline}
main.sx-main.sx-with-toc{margin-left:max(260px,calc((100vw - 1100px) / 2))}
section{scroll-margin-top:1em}div.sx-wide{overflow-x:auto}p.sx-top{text-align:right;font-size:.85em;margin:1.5em 0 0}p.sx-top a{color:#1a4f9c}
p.sx-view{padding:.4em .6em;background:#eef3fb;border-left:4px solid #3b6fd8}p.sx-view a{font-weight:bold}
@media (max-width:900px){nav.sx-toc{position:sticky;bottom:auto;width:auto;padding:.5em .8em;border-right:0;border-bottom:1px solid #d8dbe0}
nav.sx-toc p{display:none}nav.sx-toc ol{display:flex;gap:1.2em;overflow-x:auto;white-space:nowrap}nav.sx-toc li{margin:0}
main.sx-main.sx-with-toc{margin-left:auto}section{scroll-margin-top:3em}}
h1{margin-bottom:.2em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:2em}
table.sx-table{border-collapse:collapse;margin:1em 0;font-size:.9em}
table.sx-table caption{caption-side:top;text-align:left;font-weight:bold;padding-bottom:.3em}
table.sx-table th,table.sx-table td{padding:.25em .6em;border-bottom:1px solid #ddd}
table.sx-table thead th{border-bottom:2px solid #444}
td.num{text-align:right;font-variant-numeric:tabular-nums}
p.sx-note{font-size:.85em;color:#555}
figure{margin:1em 0}figure img{max-width:100%;border:1px solid #eee}figcaption{font-size:.9em;color:#444}
ul.claims{list-style:none;padding-left:0}ul.claims li{margin:.4em 0;padding:.4em .6em;border-left:4px solid #999;background:#fafafa}
.verdict{font-weight:bold;padding:0 .4em;border-radius:3px;color:#fff}
.v-holds{background:#2a7d2a}.v-does-not-hold{background:#b22222}.v-inconclusive{background:#b8860b}.v-not-comparable{background:#777}
li.c-holds{border-left-color:#2a7d2a}li.c-does-not-hold{border-left-color:#b22222}
li.c-inconclusive{border-left-color:#b8860b}
p.headline{font-size:1.1em;font-weight:600}table.overview td{vertical-align:top}tr.c-holds td:first-child{border-left:4px solid #2a7d2a}tr.c-does-not-hold td:first-child{border-left:4px solid #b22222}tr.c-inconclusive td:first-child{border-left:4px solid #b8860b}
.evidence{display:block;font-size:.88em;color:#444;margin-top:.2em}
.cause{display:block;font-size:.88em;color:#6b3d00;margin-top:.2em}
dl.provenance{display:grid;grid-template-columns:max-content auto;gap:.2em 1em;font-size:.9em}
dl.provenance dt{font-weight:bold}dl.provenance dd{margin:0;font-family:monospace;white-space:pre-wrap}
)";

std::string verdict_class(Verdict v) {
  switch (v) {
    case Verdict::holds: return "holds";
    case Verdict::does_not_hold: return "does-not-hold";
    case Verdict::inconclusive: return "inconclusive";
    case Verdict::not_comparable: return "not-comparable";
  }
  return "not-comparable";
}

std::string render_claim(const Claim& c) {
  std::ostringstream out;
  out << "<li class=\"c-" << verdict_class(c.verdict) << "\"><span class=\"verdict v-"
      << verdict_class(c.verdict) << "\">" << escape_html(to_string(c.verdict)) << "</span> "
      << escape_html(c.statement);
  if (!c.evidence.empty()) out << "<span class=\"evidence\">" << escape_html(c.evidence) << "</span>";
  if (!c.cause.empty()) out << "<span class=\"cause\">cause: " << escape_html(c.cause) << "</span>";
  out << "</li>\n";
  return out.str();
}

}  // namespace

std::string to_string(Verdict verdict) {
  switch (verdict) {
    case Verdict::holds: return "holds";
    case Verdict::does_not_hold: return "does not hold";
    case Verdict::inconclusive: return "inconclusive";
    case Verdict::not_comparable: return "not comparable";
  }
  return "not comparable";
}

HtmlSection& HtmlSection::add_paragraph(const std::string& text) {
  blocks_.push_back("<p>" + escape_html(text) + "</p>\n");
  return *this;
}

HtmlSection& HtmlSection::add_html(const std::string& html) {
  blocks_.push_back(html + "\n");
  return *this;
}

HtmlSection& HtmlSection::add_table(const Table& table) {
  // A table wider than the column beside the contents bar scrolls on its own, not the page.
  blocks_.push_back("<div class=\"sx-wide\">\n" + render_html(table) + "</div>\n");
  return *this;
}

HtmlSection& HtmlSection::add_figure(const std::string& src, const std::string& caption) {
  figures_.push_back(src);
  blocks_.push_back("<figure><img src=\"" + escape_html(src) + "\" alt=\"" + escape_html(caption) +
                    "\"><figcaption>" + escape_html(caption) + "</figcaption></figure>\n");
  return *this;
}

HtmlSection& HtmlSection::add_view(const std::string& src, const std::string& caption) {
  views_.push_back(src);
  blocks_.push_back("<p class=\"sx-view\"><a href=\"" + escape_html(src) +
                    "\">3D view: " + escape_html(caption) +
                    "</a> (an interactive page: drag to rotate, right-drag to pan, wheel to zoom)</p>\n");
  return *this;
}

HtmlSection& HtmlSection::add_claim(const Claim& claim) {
  claims_.push_back(claim);
  return *this;
}

std::string HtmlSection::render() const {
  std::ostringstream out;
  out << "<section id=\"" << escape_html(id_) << "\">\n<h2>" << escape_html(title_) << "</h2>\n";
  for (const std::string& b : blocks_) out << b;
  for (ClaimKind kind : {ClaimKind::thesis, ClaimKind::sanity}) {
    std::string items;
    for (const Claim& c : claims_)
      if (c.kind == kind) items += render_claim(c);
    if (items.empty()) continue;
    out << (kind == ClaimKind::thesis ? "<h3>Claims of the thesis</h3>\n" : "<h3>Sanity checks</h3>\n")
        << "<ul class=\"claims\">\n"
        << items << "</ul>\n";
  }
  out << "<p class=\"sx-top\"><a href=\"#top\">↑ Back to top</a></p>\n</section>\n";
  return out.str();
}

HtmlSection& HtmlReport::add_section(const std::string& id, const std::string& title,
                                     const std::string& toc_title) {
  sections.emplace_back(id, title, toc_title);
  return sections.back();
}

std::string HtmlReport::render() const {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
      << escape_html(title) << "</title>\n<style>\n"
      << kStyle << "</style>\n</head>\n<body>\n";
  if (!sections.empty()) {
    out << "<nav class=\"sx-toc\" aria-label=\"Contents\">\n<p><a href=\"#top\">Contents</a></p>\n<ol>\n";
    for (const HtmlSection& s : sections)
      out << "<li><a href=\"#" << escape_html(s.id()) << "\">" << escape_html(s.toc_title()) << "</a></li>\n";
    if (!provenance.empty()) out << "<li><a href=\"#provenance\">Provenance</a></li>\n";
    out << "</ol>\n</nav>\n";
  }
  out << "<main class=\"sx-main" << (sections.empty() ? "" : " sx-with-toc") << "\">\n<h1 id=\"top\">"
      << escape_html(title) << "</h1>\n";
  if (!subtitle.empty()) out << "<p>" << escape_html(subtitle) << "</p>\n";
  out << front_html;
  for (const HtmlSection& s : sections) out << s.render();
  if (!provenance.empty()) {
    out << "<section id=\"provenance\">\n<h2>Provenance</h2>\n<dl class=\"provenance\">\n";
    for (const auto& [key, value] : provenance)
      out << "<dt>" << escape_html(key) << "</dt><dd>" << escape_html(value) << "</dd>\n";
    out << "</dl>\n<p class=\"sx-top\"><a href=\"#top\">↑ Back to top</a></p>\n</section>\n";
  }
  out << "</main>\n</body>\n</html>\n";
  return out.str();
}

void HtmlReport::write(const std::filesystem::path& path) const {
  write_file_atomically(path, render());
}

}  // namespace sextant
