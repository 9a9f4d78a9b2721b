// The front page's headline counts the thesis' claims (E1–E19) apart from the extensions' claims
// and from the sanity checks; every claim and check that does not hold is listed beside its cause, or as
// having none measured yet.
#include <gtest/gtest.h>

#include "report_causes.hpp"
#include "report_overview.hpp"

namespace sextant {
namespace {

OverviewEntry entry(const std::string& id, std::vector<Claim> claims) {
  OverviewEntry e;
  e.id = id;
  e.claims = std::move(claims);
  return e;
}

TEST(ReportOverview, TheHeadlineCountsThesisClaimsApartFromExtensionsAndSanityChecks) {
  const std::vector<OverviewEntry> entries = {
      entry("e02_accuracy", {{"a", Verdict::holds, "", ClaimKind::thesis},
                             {"b", Verdict::does_not_hold, "", ClaimKind::thesis},
                             {"c", Verdict::holds, "", ClaimKind::sanity}}),
      entry("e19_unbiased", {{"d", Verdict::inconclusive, "", ClaimKind::thesis},
                             {"e", Verdict::does_not_hold, "", ClaimKind::sanity}}),
      entry("e20_pose_graph",
            {{"f", Verdict::holds, "", ClaimKind::thesis}, {"g", Verdict::holds, "", ClaimKind::sanity}}),
  };
  EXPECT_EQ(
      headline_text(entries),
      "The thesis (E1–E19): 3 claims: 1 hold, 1 do not hold, 1 inconclusive. Extensions beyond the thesis: "
      "1 claim: 1 hold. Sanity checks of the experiments themselves: 3 checks: 2 hold, 1 do not hold.");
  const std::string html = overview_html(entries);
  EXPECT_NE(html.find("<p class=\"headline\">The thesis (E1–E19): 3 claims"), std::string::npos);
  EXPECT_LT(html.find("headline"), html.find("The thesis' experiments"));
}

TEST(ReportOverview, RealDataClaimsAreCountedApartFromTheCampus) {
  std::vector<OverviewEntry> entries = {
      entry("e02_accuracy", {{"a", Verdict::holds, "", ClaimKind::thesis}}),
      entry("e02_accuracy_mulran", {{"a", Verdict::does_not_hold, "", ClaimKind::thesis},
                                    {"b", Verdict::holds, "", ClaimKind::thesis}})};
  entries[1].real_data = true;
  EXPECT_EQ(
      headline_text(entries),
      "The thesis (E1–E19) on the campus: 1 claim: 1 hold; on real data: 2 claims: 1 hold, 1 do not hold.");
}

TEST(ReportOverview, WithoutExtensionsOrSanityChecksTheHeadlineSaysOnlyTheThesis) {
  const std::vector<OverviewEntry> entries = {
      entry("e05_x", {{"a", Verdict::not_comparable, "", ClaimKind::thesis}})};
  EXPECT_EQ(headline_text(entries), "The thesis (E1–E19): 1 claim: 0 hold, 1 not comparable.");
}

TEST(ReportCauses, EveryClaimThatDoesNotHoldIsListedWithItsCauseOrNone) {
  std::vector<OverviewEntry> entries = {
      entry("e09_kf", {{"covers", Verdict::does_not_hold, "3 %", ClaimKind::sanity, "the thesis: a | b"},
                       {"rare", Verdict::holds, "", ClaimKind::thesis, "never shown"}}),
      entry("e06_sampling", {{"fast", Verdict::does_not_hold, "", ClaimKind::thesis},
                             {"open", Verdict::inconclusive, "", ClaimKind::thesis}})};
  entries[1].real_data = true;
  EXPECT_EQ(causes_sentence(entries),
            "Of the 2 claims and checks that do not hold, 1 carries a measured cause");
  const std::string md = causes_markdown(entries);
  EXPECT_NE(md.find("| [E9](e09_kf/e09_kf.md) | sanity check | covers | the thesis: a / b |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| [E6 (real)](e06_sampling/e06_sampling.md) | claim | fast | none measured yet |"),
            std::string::npos)
      << md;
  EXPECT_EQ(md.find("rare"), std::string::npos) << "a claim that holds is not listed";
  EXPECT_EQ(md.find("open"), std::string::npos) << "an inconclusive claim is not listed";
}

TEST(ReportCauses, WithNothingThatFailsThereIsNoSentence) {
  const std::vector<OverviewEntry> entries = {entry("e01_x", {{"a", Verdict::holds, "", ClaimKind::thesis}})};
  EXPECT_EQ(causes_sentence(entries), "");
  EXPECT_NE(causes_markdown(entries).find("Every claim and check holds"), std::string::npos);
}

}  // namespace
}  // namespace sextant
