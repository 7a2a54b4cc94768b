// The knife-edge watch (PROP-KNIFE-1) on hand-made summaries: what counts as a rise.
#include "knife_edge_watch.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace cutcom::props {
namespace {

CampaignSummary summary(long cases, std::map<std::string, long> knife_edges) {
  CampaignSummary s;
  s.seed = 20261201, s.cases = cases, s.knife_edges = std::move(knife_edges);
  return s;
}

// covers: PROP-KNIFE-1
TEST(KnifeEdgeWatch, ARiseBeyondNoiseNamesTheClause) {
  nlohmann::json base = knife_edge_baseline(summary(20000, {{"TRC-CORNER-4", 20}, {"TRC-CD-3", 300}}));
  EXPECT_EQ(base["cases"], 20000);
  EXPECT_EQ(base["knife_edges"]["TRC-CORNER-4"], 20);
  // 20 + 3 sqrt(20) + 3 = 36.4: 36 passes, 37 is a rise; the other clause unchanged.
  EXPECT_TRUE(knife_edge_rises(summary(20000, {{"TRC-CORNER-4", 36}, {"TRC-CD-3", 300}}), base).empty());
  std::vector<std::string> r = knife_edge_rises(summary(20000, {{"TRC-CORNER-4", 37}, {"TRC-CD-3", 290}}), base);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0], "TRC-CORNER-4: 37 knife edges in 20000 cases, baseline 20 in 20000 (at most 36 allowed)");
  // Scaled to the cases run: half the cases, half the expectation (10 + 3 sqrt(10) + 3 = 22.5).
  EXPECT_EQ(knife_edge_rises(summary(10000, {{"TRC-CORNER-4", 23}}), base).size(), 1u);
  EXPECT_TRUE(knife_edge_rises(summary(10000, {{"TRC-CORNER-4", 22}}), base).empty());
  // A clause without knife edges in the baseline: more than 3 is a rise.
  EXPECT_EQ(knife_edge_rises(summary(20000, {{"TRC-KONT-1", 4}}), base).size(), 1u);
  EXPECT_TRUE(knife_edge_rises(summary(20000, {{"TRC-KONT-1", 3}}), base).empty());
  // A file that is not a baseline is an error, not a pass.
  EXPECT_THROW(knife_edge_rises(summary(1, {}), nlohmann::json::object()), std::runtime_error);
  EXPECT_THROW(knife_edge_rises(summary(1, {{"X", 1}}), {{"cases", 5}, {"knife_edges", {{"X", "many"}}}}),
               std::runtime_error);
}

// covers: PROP-KNIFE-1
TEST(KnifeEdgeWatch, KnifeEdgesEndingDifferentlyAreWatchedOnTheirOwn) {
  // A clause's knife edges within noise, but more of them now end with an alarm in one engine: a
  // bug that raises an alarm at a tie (mutant 68: 11 against 3 in all, 7 against 0 ending so).
  CampaignSummary before = summary(20000, {{"TRC-ARC-CORNER-1", 3}});
  nlohmann::json base = knife_edge_baseline(before);
  EXPECT_TRUE(base["ending_differently"].is_object());
  CampaignSummary now = summary(20000, {{"TRC-ARC-CORNER-1", 11}});
  now.knife_edges_ending_differently = {{"TRC-ARC-CORNER-1", 7}};
  std::vector<std::string> r = knife_edge_rises(now, base);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0],
            "TRC-ARC-CORNER-1: 7 knife edges ending differently in 20000 cases, baseline 0 in 20000 (at most 3 "
            "allowed)");
  now.knife_edges_ending_differently = {{"TRC-ARC-CORNER-1", 3}};
  EXPECT_TRUE(knife_edge_rises(now, base).empty());
  // A baseline written before this count had it is held to the knife edges alone.
  base.erase("ending_differently");
  now.knife_edges_ending_differently = {{"TRC-ARC-CORNER-1", 7}};
  EXPECT_TRUE(knife_edge_rises(now, base).empty());
  // A summary keeps the count through JSON and a merge.
  CampaignSummary back = CampaignSummary::from_json(now.to_json());
  back.merge(back);
  EXPECT_EQ(back.knife_edges_ending_differently["TRC-ARC-CORNER-1"], 14);
}

}  // namespace
}  // namespace cutcom::props
