#include "report_overview.hpp"

#include "report_causes.hpp"

#include <array>
#include <cctype>

#include "sextant/eval/table.hpp"

namespace sextant {
namespace {

constexpr int kThesisExperiments = 19;

using VerdictCounts = std::array<std::size_t, 4>;  // indexed by Verdict
/// The verdicts as counts read ("3 hold"), in Verdict's order.
constexpr const char* kVerdictCountNames[] = {"hold", "do not hold", "inconclusive", "not comparable"};

std::size_t total(const VerdictCounts& c) {
  return c[0] + c[1] + c[2] + c[3];
}

struct Counts {
  VerdictCounts thesis{}, sanity{};
  std::size_t thesis_total() const { return total(thesis); }
};

Counts count(const std::vector<Claim>& claims) {
  Counts c;
  for (const Claim& claim : claims)
    ++(claim.kind == ClaimKind::sanity ? c.sanity : c.thesis)[static_cast<std::size_t>(claim.verdict)];
  return c;
}

bool is_thesis_experiment(const OverviewEntry& e) {
  const int n = experiment_number(e.id);
  return n >= 1 && n <= kThesisExperiments;
}

std::string label(const OverviewEntry& e) {
  const int n = experiment_number(e.id);
  return n > 0 ? "E" + std::to_string(n) : e.id;
}

std::string runs_text(const OverviewEntry& e) {
  std::string text = std::to_string(e.runs_found) + "/" + std::to_string(e.runs_expected);
  if (!e.profile.empty()) text += " (" + e.profile + ")";
  return e.runs_failed > 0 ? text + ", " + std::to_string(e.runs_failed) + " failed" : text;
}

std::string held_text(const Counts& c) {
  std::string text = std::to_string(c.thesis[0]) + " / " + std::to_string(c.thesis_total());
  if (total(c.sanity) > 0)
    text += " · sanity " + std::to_string(c.sanity[0]) + " / " + std::to_string(total(c.sanity));
  return text;
}

std::string html_rows(const std::vector<OverviewEntry>& entries, bool extensions) {
  std::string out;
  for (const OverviewEntry& e : entries) {
    if (is_thesis_experiment(e) == extensions) continue;
    const Counts c = count(e.claims);
    const std::string cls = !e.failure.empty()                ? "does-not-hold"
                            : c.thesis[1] > 0                 ? "does-not-hold"
                            : c.thesis[2] > 0                 ? "inconclusive"
                            : c.thesis[0] == c.thesis_total() ? "holds"
                                                              : "not-comparable";
    out += "<tr class=\"c-" + cls + "\"><td><a href=\"#" + escape_html(e.id) + "\">" + escape_html(label(e)) +
           "</a></td><td>" + escape_html(e.title) + "</td><td>" + escape_html(e.thesis) + "</td><td>" +
           escape_html(runs_text(e)) + "</td><td>" + escape_html(held_text(c)) + "</td><td>" +
           escape_html(one_line_outcome(e)) + "</td></tr>\n";
  }
  return out;
}

std::string html_table(const std::string& caption, const std::string& rows) {
  if (rows.empty()) return "";
  return "<table class=\"overview\"><caption>" + escape_html(caption) +
         "</caption>\n<thead><tr><th>exp.</th><th>title</th><th>thesis</th><th>runs</th><th>claims held / "
         "total</th><th>outcome</th></tr></thead>\n<tbody>\n" +
         rows + "</tbody></table>\n";
}

/// "3 claims: 1 hold, 1 do not hold, 1 inconclusive" (`noun` "claim" or "check").
std::string verdict_counts_text(const VerdictCounts& counts, const std::string& noun) {
  const std::size_t n = total(counts);
  std::string text = std::to_string(n) + " " + noun + (n == 1 ? ": " : "s: ");
  for (std::size_t v = 0; v < 4; ++v) {
    if (counts[v] == 0 && v > 0) continue;
    text += (v == 0 ? "" : ", ") + std::to_string(counts[v]) + " " + kVerdictCountNames[v];
  }
  return text;
}

}  // namespace

std::string headline_text(const std::vector<OverviewEntry>& entries) {
  std::vector<Claim> campus, real, extensions;
  for (const OverviewEntry& e : entries) {
    std::vector<Claim>& group = !is_thesis_experiment(e) ? extensions : e.real_data ? real : campus;
    group.insert(group.end(), e.claims.begin(), e.claims.end());
  }
  const Counts t = count(campus), r = count(real), x = count(extensions);
  std::string text = "The thesis (E1–E19): " + verdict_counts_text(t.thesis, "claim") + ".";
  if (r.thesis_total() > 0)
    text = "The thesis (E1–E19) on the campus: " + verdict_counts_text(t.thesis, "claim") +
           "; on real data: " + verdict_counts_text(r.thesis, "claim") + ".";
  if (x.thesis_total() > 0)
    text += " Extensions beyond the thesis: " + verdict_counts_text(x.thesis, "claim") + ".";
  std::vector<Claim> all;
  for (const OverviewEntry& e : entries) all.insert(all.end(), e.claims.begin(), e.claims.end());
  const VerdictCounts sanity = count(all).sanity;
  if (total(sanity) > 0)
    text += " Sanity checks of the experiments themselves: " + verdict_counts_text(sanity, "check") + ".";
  return text;
}

int experiment_number(const std::string& id) {
  if (id.size() < 3 || id[0] != 'e' || !std::isdigit(static_cast<unsigned char>(id[1]))) return 0;
  int n = 0;
  std::size_t k = 1;
  for (; k < id.size() && std::isdigit(static_cast<unsigned char>(id[k])); ++k) n = 10 * n + (id[k] - '0');
  return k < id.size() && id[k] != '_' ? 0 : n;
}

std::string one_line_outcome(const OverviewEntry& entry) {
  if (!entry.failure.empty()) return "report failed: " + entry.failure;
  if (entry.runs_found == 0)
    return entry.runs_failed > 0 ? "every run failed (see its section)" : "no runs found";
  const Counts c = count(entry.claims);
  if (c.thesis_total() == 0) return "no thesis claims to check";
  std::string text = std::to_string(c.thesis[0]) + " of " + std::to_string(c.thesis_total()) + " claims hold";
  for (std::size_t v = 1; v < 4; ++v)
    if (c.thesis[v] > 0) text += "; " + std::to_string(c.thesis[v]) + " " + kVerdictCountNames[v];
  // Name the first claim that does not hold (or, failing that, the first inconclusive one).
  for (Verdict wanted : {Verdict::does_not_hold, Verdict::inconclusive}) {
    for (const Claim& claim : entry.claims) {
      if (claim.kind == ClaimKind::thesis && claim.verdict == wanted)
        return text + " — " + (wanted == Verdict::does_not_hold ? "not: " : "open: ") + claim.statement;
    }
  }
  return text;
}

std::string overview_html(const std::vector<OverviewEntry>& entries) {
  const std::string causes = causes_sentence(entries);
  return "<p class=\"headline\">" + escape_html(headline_text(entries)) + "</p>\n" +
         (causes.empty() ? ""
                         : "<p>" + escape_html(causes) + " (<a href=\"causes.md\">causes.md</a>).</p>\n") +
         html_table("The thesis' experiments", html_rows(entries, false)) +
         html_table("Extensions beyond the thesis", html_rows(entries, true));
}

std::string overview_markdown(const std::vector<OverviewEntry>& entries) {
  const std::string causes = causes_sentence(entries);
  std::string md =
      headline_text(entries) + (causes.empty() ? "" : " " + causes + " ([causes.md](causes.md)).") +
      "\n\n| exp. | title | thesis | runs | claims held / total | outcome |\n|---|---|---|---|---|---|\n";
  for (const OverviewEntry& e : entries) {
    md += "| [" + label(e) + "](" + e.id + "/" + e.id + ".md) | " + e.title + " | " + e.thesis + " | " +
          runs_text(e) + " | " + held_text(count(e.claims)) + " | " + one_line_outcome(e) + " |\n";
  }
  return md;
}

}  // namespace sextant
