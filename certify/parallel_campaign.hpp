// `cutcom certify --jobs N`: one campaign's shards run in parallel processes on this machine and
// are merged into one summary (the cases and their numbers are those of the same campaign run in
// one process: case k is the same program in any sharding).
#pragma once

#include "campaign.hpp"

namespace cutcom::props {

struct ParallelRun {
  CampaignSummary summary;
  double wall_seconds = 0;
  int jobs = 1;
};

// Runs `options` (itself possibly one shard I/N of a larger campaign) as `jobs` shards
// I + N*j of N*jobs, splitting its case count; each writes its results (JSON lines) to a file of
// its own, appended to options.results in shard order at the end. jobs <= 1: in this process.
// Throws std::runtime_error if a shard's process fails.
ParallelRun run_campaign_jobs(const CampaignOptions& options, int jobs);

}  // namespace cutcom::props
