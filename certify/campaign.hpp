// The certification campaign (`cutcom certify`, docs/certification.md): the differential
// comparison of PROP-DIFF-1 over all generators at scale, in reproducible shards, with decision
// coverage per clause and branch and the measured distribution of fast's coordinate error.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cutcom/machine_data.hpp"
#include "cutcom/reader.hpp"

namespace cutcom::props {

// Counts a shard shares with the other shards of a campaign run in parallel (`--jobs`), in
// memory all of them see: progress for the parent, and a stop at the first divergence.
struct LiveCounts {
  std::atomic<long> cases{0}, knife_edges{0}, over_budget{0}, divergences{0};
  std::atomic<bool> stop{false};
};

struct CampaignOptions {
  long cases = 1000;       // cases to run in this shard (0: until `seconds`)
  double seconds = 0;      // stop after this long (0: no limit)
  std::uint64_t seed = 1;  // campaign seed: case k gets its own seed from (seed, k) whatever the sharding
  int shard = 0, shards = 1;
  std::string results;  // JSON lines, one per case (empty: none)
  std::string corpus;   // where an unexplained divergence is written (empty: not written)
  bool progress = true;
  // Seconds one case may take (0: no limit, cases run in this process). With a budget the cases
  // run in a child process; a case over budget is killed, recorded as "over-budget" (not
  // compared) and the shard goes on with the next one. A crash in a case stops the shard.
  double budget = 0;
  LiveCounts* live = nullptr;  // shared with parallel shards (nullptr: alone)
};

// One case's result, as the campaign counts it.
struct CaseRecord {
  long k = 0;
  std::string source, style;
  std::string verdict;  // agree, knife-edge, not-supported, diverge, over-budget, crash
  std::string clause;   // knife edge: the parting clause
  std::string explanation;
  std::string alarm = "none";  // ref's first alarm
  double error = 0, ratio = 0, ms = 0;
  std::map<std::string, std::map<std::string, std::pair<long, long>>> decisions;  // clause -> branch -> taken, knife
  // What ref's output shows besides decisions, once per case: "alarm:<clause>", "notice:<clause>",
  // "element:<origin kind>", "sar:<movement>", "helix", "actions" (evidence for clauses that are
  // constructions or alarms, not traced branches).
  std::set<std::string> evidence;

  nlohmann::json to_json() const;
  static CaseRecord from_json(const nlohmann::json& j);
};

// Counts of one decision branch: taken, and taken with ref's margin inside the clause's band.
struct BranchCount {
  long taken = 0, knife = 0;
};

struct CampaignSummary {
  std::uint64_t seed = 0;
  std::vector<std::string> shards;  // "I/N" of each shard merged in
  long cases = 0;
  double seconds = 0;                                                  // summed over shards (CPU-bound: one core each)
  std::map<std::string, long> verdicts;                                // agree, knife-edge, not-supported, diverge
  std::map<std::string, long> knife_edges;                             // by clause
  std::map<std::string, long> knife_edges_ending_differently;          // by clause, those of them
  std::map<std::string, long> styles;                                  // by generator
  std::map<std::string, long> alarms;                                  // by number ("none" without)
  std::map<std::string, std::map<std::string, BranchCount>> coverage;  // clause -> branch
  // Coordinate error of agreeing cases: log10 bins from 1e-20 mm (index 0: exactly 0), 10 per
  // decade; and the error relative to the documented tolerance.
  std::vector<long> error_bins = std::vector<long>(161, 0);
  std::vector<long> ratio_bins = std::vector<long>(161, 0);
  double max_error = 0, max_ratio = 0;
  std::string max_error_case;            // "seed/k" of the case with the largest error
  std::string max_ratio_case;            // "seed/k" of the case nearest its tolerance (often another)
  std::vector<std::string> divergences;  // unexplained: what, and the corpus file written
  std::vector<std::string> over_budget;  // "seed/k" of the cases killed at the time budget
  std::map<std::string, long> evidence;  // CaseRecord::evidence: cases showing each

  nlohmann::json to_json() const;
  static CampaignSummary from_json(const nlohmann::json& j);
  void merge(const CampaignSummary& other);
  void add(const CaseRecord& r);
  // Percentile p (0..1) of the error distribution (upper edge of the bin).
  double error_percentile(double p, bool ratio = false) const;
};

// Runs the shard; stops at the first unexplained divergence (after shrinking it and writing it
// to the corpus).
CampaignSummary run_campaign(const CampaignOptions& options);

// docs/certification.md and its error histogram (SVG), from a (merged) summary; `spec_dir` gives
// the clause list for the coverage table.
void write_report(const CampaignSummary& s, const std::string& markdown_path, const std::string& svg_path,
                  const std::string& spec_dir);

// One program through both engines, judged as a campaign case (PROP-DIFF-1): a corpus case, or
// a program of one's own.
struct ReplayVerdict {
  std::string verdict;  // agree, knife-edge, not-supported, diverge
  std::string clause;   // knife edge: the parting clause
  std::string explanation;
  double error = 0, ratio = 0;  // agree: largest coordinate error (mm) and its share of the tolerance
};
// `folder`: where the program's subprograms are (empty: it calls none; no file is looked at).
ReplayVerdict replay(const std::string& program, const MachineData& md, const std::string& folder = {},
                     const std::function<void(ProgramReader&)>& setup = {});

// Case k of a campaign: its program text and machine data (NAME=VALUE lines), to replay it.
std::pair<std::string, std::string> campaign_case(std::uint64_t seed, long k);
// Writes case k of campaign `seed` to `dir`/`name`.mpf with its .md and ref's output .ref.json
// (what a divergence leaves in tests/corpus); returns the .mpf's path.
std::string write_corpus_case(const std::string& dir, const std::string& name, std::uint64_t seed, long k,
                              const std::string& why);

// The seed of case k of a campaign (splitmix64 of seed and k): shards agree on it.
std::uint64_t case_seed(std::uint64_t seed, long k);

}  // namespace cutcom::props
