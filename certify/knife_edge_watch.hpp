// Knife edges are watched (PROP-KNIFE-1): a campaign's knife edges per clause against a committed
// baseline of the same generators and seed. A bug that acts exactly at a threshold hides as knife
// edges of its clause; the rise gives it away.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "campaign.hpp"

namespace cutcom::props {

// {"seed": S, "cases": N, "knife_edges": {"TRC-CORNER-4": n, …}, "ending_differently": {…}}:
// what a later run is held to.
nlohmann::json knife_edge_baseline(const CampaignSummary& s);

// The clauses whose knife edges rose beyond noise: more than e + 3 √e + 3, where e is the
// baseline's count scaled to this campaign's cases (Poisson noise; the same seed and cases give
// the same count, so a rise within that allowance is a change of code, not chance); and the same
// for those of them after which the runs end differently, where the baseline has that count (a
// bug that raises an alarm at a tie hides among a clause's knife edges, not among these). Each
// entry names the clause, both counts and the allowance. Throws std::runtime_error for a malformed
// file.
std::vector<std::string> knife_edge_rises(const CampaignSummary& s, const nlohmann::json& baseline);

}  // namespace cutcom::props
