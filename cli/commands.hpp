// The subcommands of `cutcom`: run, certify, md, alarms.
#pragma once

#include <string>
#include <vector>

#include "campaign.hpp"
#include "control_data.hpp"

namespace cutcom::cli {

int run_command(const RunOptions& o);
int list_machine_data(const RunOptions& o);  // --md-file, --md, --channel as for run
int list_alarms();

struct CertifyOptions {
  cutcom::props::CampaignOptions campaign = [] {
    cutcom::props::CampaignOptions c;
    c.budget = 60;  // a campaign of millions of cases must not hang on one
    return c;
  }();
  std::string shard = "0/1";
  int jobs = 0;  // parallel shards on this machine (0: one per core)
  std::string summary, report, histogram, spec = "spec";
  std::string knife_baseline, write_knife_baseline;  // PROP-KNIFE-1
  std::vector<std::string> merge, replay, from;
  long neighbours = 200;  // --from: generated neighbours of each program
  long show = -1;
  RunOptions control;  // --replay/--from: the control's data the programs need (tools, offsets, GUD)
};

int certify_command(CertifyOptions& o);

}  // namespace cutcom::cli
