#include "report_causes.hpp"

namespace sextant {
namespace {

/// A table cell: no line breaks or column bars of its own.
std::string cell(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '|') c = c == '|' ? '/' : ' ';
  return text;
}

std::string experiment_label(const OverviewEntry& e) {
  const int n = experiment_number(e.id);
  return (n > 0 ? "E" + std::to_string(n) : e.id) + (e.real_data ? " (real)" : "");
}

}  // namespace

std::string causes_sentence(const std::vector<OverviewEntry>& entries) {
  std::size_t failing = 0, caused = 0;
  for (const OverviewEntry& e : entries)
    for (const Claim& c : e.claims)
      if (c.verdict == Verdict::does_not_hold) {
        ++failing;
        caused += c.cause.empty() ? 0 : 1;
      }
  if (failing == 0) return "";
  return "Of the " + std::to_string(failing) + " claims and checks that do not hold, " +
         std::to_string(caused) + (caused == 1 ? " carries" : " carry") + " a measured cause";
}

std::string causes_markdown(const std::vector<OverviewEntry>& entries) {
  std::string rows;
  for (const OverviewEntry& e : entries)
    for (const Claim& c : e.claims)
      if (c.verdict == Verdict::does_not_hold)
        rows += "| [" + experiment_label(e) + "](" + e.id + "/" + e.id + ".md) | " +
                (c.kind == ClaimKind::thesis ? "claim" : "sanity check") + " | " + cell(c.statement) + " | " +
                (c.cause.empty() ? "none measured yet" : cell(c.cause)) + " |\n";
  const std::string sentence = causes_sentence(entries);
  if (rows.empty()) return "Every claim and check holds, or is inconclusive or not comparable.\n";
  return sentence + ".\n\n| exp. | kind | does not hold | cause |\n|---|---|---|---|\n" + rows;
}

}  // namespace sextant
