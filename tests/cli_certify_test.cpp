// The certification campaign from the command line: shards and their merge, parallel jobs, Slurm
// job arrays, the per-case budget, replays of given programs and their neighbours.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_shell.hpp"

using namespace cutcom::cli_test;

namespace {
// covers: CLI-2
TEST(Cli, CertifyShardsMergeIntoTheReport) {
  const std::string dir = CUTCOM_BINARY_DIR;
  for (const char* shard : {"0/2", "1/2"}) {
    Result r = sh(kCli + " certify --cases 15 --seed 3 --no-progress --shard " + shard + " --summary " + dir +
                  "/shard" + shard[0] + ".json --results " + dir + "/results" + shard[0] + ".jsonl");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("15 cases"), std::string::npos) << r.out;
  }
  std::ifstream lines(dir + "/results1.jsonl");
  std::string first;
  std::getline(lines, first);
  EXPECT_EQ(nlohmann::json::parse(first)["case"], 1);  // shard 1/2 runs cases 1, 3, 5, ...
  Result m = sh(kCli + " certify --merge " + dir + "/shard0.json " + dir + "/shard1.json --report " + dir +
                "/certification.md --spec " CUTCOM_SOURCE_DIR "/spec");
  ASSERT_EQ(m.status, 0);
  EXPECT_NE(m.out.find("30 cases"), std::string::npos) << m.out;
  std::ifstream report(dir + "/certification.md");
  std::string text((std::istreambuf_iterator<char>(report)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("# Certification of fast against ref"), std::string::npos);
  EXPECT_NE(text.find("| TRC-CORNER-1 |"), std::string::npos);
  EXPECT_TRUE(std::ifstream(dir + "/certification-errors.svg").good());
  // Case k is the same program whatever the sharding.
  EXPECT_EQ(sh(kCli + " certify --seed 3 --show 7").out, sh(kCli + " certify --seed 3 --show 7").out);
}

nlohmann::json summary_of(const std::string& file) {
  std::ifstream in(file);
  nlohmann::json j = nlohmann::json::parse(in);
  j.erase("seconds");
  return j;
}

// covers: CLI-2
TEST(Cli, CertifyJobsRunTheSameCasesInParallelProcesses) {
  const std::string dir = CUTCOM_BINARY_DIR;
  Result one = sh(kCli + " certify --cases 31 --seed 9 --no-progress --jobs 1 --summary " + dir +
                  "/jobs1.json --results " + dir + "/jobs1.jsonl");
  Result three = sh(kCli + " certify --cases 31 --seed 9 --no-progress --jobs 3 --summary " + dir +
                    "/jobs3.json --results " + dir + "/jobs3.jsonl");
  ASSERT_EQ(one.status, 0) << one.out;
  ASSERT_EQ(three.status, 0) << three.out;
  EXPECT_NE(three.out.find("31 cases in "), std::string::npos) << three.out;
  EXPECT_NE(three.out.find(" on 3 jobs ("), std::string::npos) << three.out;
  EXPECT_NE(three.out.find("/s per core)"), std::string::npos) << three.out;
  nlohmann::json a = summary_of(dir + "/jobs1.json"), b = summary_of(dir + "/jobs3.json");
  EXPECT_EQ(a["shards"], nlohmann::json::array({"0/1"}));
  EXPECT_EQ(b["shards"], nlohmann::json::array({"0/3", "1/3", "2/3"}));
  a.erase("shards"), b.erase("shards");
  EXPECT_EQ(a, b);  // the same 31 cases, counted alike
  // The case nearest its tolerance is named: the agreeing case of the largest error / tolerance.
  {
    std::ifstream in(dir + "/jobs1.jsonl");
    double most = -1;
    long nearest = -1;
    for (std::string line; std::getline(in, line);) {
      nlohmann::json r = nlohmann::json::parse(line);
      if (r["verdict"] == "agree" && r["ratio"].get<double>() > most) most = r["ratio"], nearest = r["case"];
    }
    ASSERT_GE(nearest, 0);
    if (most > 0) EXPECT_EQ(a["max_ratio_case"], "9/" + std::to_string(nearest));
    EXPECT_EQ(a["max_ratio"].get<double>(), most);
  }
  // Every case once in the results, whatever process ran it.
  auto cases_in = [](const std::string& file) {
    std::ifstream in(file);
    std::vector<long> k;
    for (std::string line; std::getline(in, line);) k.push_back(nlohmann::json::parse(line)["case"].get<long>());
    std::sort(k.begin(), k.end());
    return k;
  };
  std::vector<long> all(31);
  for (long k = 0; k < 31; ++k) all[static_cast<std::size_t>(k)] = k;
  EXPECT_EQ(cases_in(dir + "/jobs1.jsonl"), all);
  EXPECT_EQ(cases_in(dir + "/jobs3.jsonl"), all);
}

// covers: CLI-2
TEST(Cli, CertifyRunsAsASlurmJobArray) {
  // Where a Slurm cluster answers (e.g. scripts/slurm-one-node.sh): the campaign as an array of
  // three tasks, merged by its own job, counts the cases of one process.
  if (sh("timeout 5 sinfo -h -N -o %T 2>/dev/null | grep -Eq 'idle|mixed'").status != 0)
    GTEST_SKIP() << "no Slurm cluster answers here";
  const std::string dir = std::string(CUTCOM_BINARY_DIR) + "/slurm-campaign";
  std::filesystem::remove_all(dir);
  Result array = sh("bash " CUTCOM_SOURCE_DIR "/scripts/slurm-campaign.sh --seed 9 --cases 31 --tasks 3 --out " + dir +
                    " --cutcom " + kCli + " --spec " CUTCOM_SOURCE_DIR "/spec --wait");
  ASSERT_EQ(array.status, 0) << array.out;
  EXPECT_NE(array.out.find("33 cases in 3 array tasks of 11"), std::string::npos) << array.out;
  Result one = sh(kCli + " certify --cases 33 --seed 9 --no-progress --jobs 1 --summary " + dir + "/one.json");
  ASSERT_EQ(one.status, 0) << one.out;
  nlohmann::json a = summary_of(dir + "/one.json"), b = summary_of(dir + "/merged.json");
  EXPECT_EQ(b["shards"], nlohmann::json::array({"0/3", "1/3", "2/3"}));
  a.erase("shards"), b.erase("shards");
  EXPECT_EQ(a, b);
  EXPECT_TRUE(std::filesystem::exists(dir + "/certification.md"));
}

// covers: CLI-2
TEST(Cli, CertifyWithABudgetRunsTheCasesInAChildAndCountsTheSame) {
  const std::string dir = CUTCOM_BINARY_DIR;
  Result child = sh(kCli + " certify --cases 40 --seed 5 --no-progress --summary " + dir + "/budget60.json");
  Result here = sh(kCli + " certify --cases 40 --seed 5 --no-progress --budget 0 --summary " + dir + "/budget0.json");
  ASSERT_EQ(child.status, 0) << child.out;
  ASSERT_EQ(here.status, 0) << here.out;
  EXPECT_EQ(summary_of(dir + "/budget60.json"), summary_of(dir + "/budget0.json"));
  // A budget of a microsecond: cases are killed (over budget, not a divergence) and the shard
  // goes on; every case is counted once, and each one over budget is named.
  // Several times: a worker that has written its shard's last case and not yet ended was once
  // counted over budget for the case after it (13 of 12, case 5/12, in about one run of 30).
  for (int run = 0; run < 10; ++run) {
    SCOPED_TRACE(run);
    Result tight = sh(kCli + " certify --cases 12 --seed 5 --no-progress --budget 0.000001 --summary " + dir +
                      "/budget-tight.json");
    ASSERT_EQ(tight.status, 0) << tight.out;
    nlohmann::json t = summary_of(dir + "/budget-tight.json");
    EXPECT_EQ(t["cases"], 12);
    long counted = 0;
    for (const auto& [verdict, n] : t["verdicts"].items()) counted += n.get<long>();
    EXPECT_EQ(counted, 12);
    long over = t["verdicts"].contains("over-budget") ? t["verdicts"]["over-budget"].get<long>() : 0;
    EXPECT_EQ(static_cast<long>(t["over_budget"].size()), over);
    EXPECT_NE(tight.out.find(std::to_string(over) + " over budget"), std::string::npos) << tight.out;
    for (const auto& name : t["over_budget"]) {  // cases 5/0 … 5/11 only
      std::string k = name.get<std::string>().substr(2);
      EXPECT_LT(std::stol(k), 12) << name;
    }
  }
}

// covers: CLI-2 PROP-CORPUS-1 PROP-FROM-1
// A campaign that would never stop, or a negative count, is a usage error before anything runs.
// covers: CLI-2
TEST(Cli, CertifyRefusesCountsThatMakeNoCampaign) {
  Result forever = sh("{ " + kCli + " certify --cases 0 --no-progress 2>&1; }");
  EXPECT_EQ(forever.status, 2);
  EXPECT_NE(forever.out.find("--cases 0 runs until --time"), std::string::npos) << forever.out;
  for (const char* option : {"--cases -5", "--time -1", "--show -3", "--budget -2"}) {
    Result r = sh("{ " + kCli + " certify " + option + " --no-progress 2>&1; }");
    EXPECT_EQ(r.status, 2) << option;
    EXPECT_NE(r.out.find("is not a number of 0 or more"), std::string::npos) << option << ": " << r.out;
  }
}

TEST(Cli, CertifyReplayJudgesProgramsWithTheirMachineData) {
  const std::string src = CUTCOM_SOURCE_DIR, dir = CUTCOM_BINARY_DIR;
  // A corpus case: a knife edge of TRC-CD-3 (its MD20240 = 2 read from the .md beside it) after
  // which ref cuts the bottleneck and fast raises an alarm: a verdict of its own.
  Result knife = sh(kCli + " certify --replay " + src + "/tests/corpus/cdon-entry-on-sar-element.mpf");
  ASSERT_EQ(knife.status, 0) << knife.out;
  EXPECT_NE(knife.out.find("knife-edge-ends-differ (TRC-CD-3)"), std::string::npos) << knife.out;
  // The machine data beside the program are read: a bad datum names its file and line.
  {
    std::ifstream in(src + "/tests/corpus/cdon-entry-on-sar-element.mpf");
    std::ofstream(dir + "/replay-bad.mpf") << in.rdbuf();
    std::ofstream(dir + "/replay-bad.md") << "MD20240=abc\n";
  }
  Result bad = sh("{ " + kCli + " certify --replay " + dir + "/replay-bad.mpf 2>&1; }");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("replay-bad.md:1: MD20240"), std::string::npos) << bad.out;
  // A user's program and its neighbours (PROP-FROM-1).
  Result from = sh(kCli + " certify --from " + src + "/examples/contour.mpf --neighbours 40");
  EXPECT_EQ(from.status, 0) << from.out;
  EXPECT_NE(from.out.find("contour.mpf: the program and 40 neighbours: "), std::string::npos) << from.out;
  EXPECT_NE(from.out.find(" 0 unexplained divergences"), std::string::npos) << from.out;
  Result missing = sh("{ " + kCli + " certify --replay " + dir + "/no-such-program.mpf 2>&1; }");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.out.find("cannot open program"), std::string::npos) << missing.out;
  EXPECT_EQ(missing.out.find("machine data"), std::string::npos) << missing.out;  // a program, not a datum
  Result folder = sh("{ " + kCli + " certify --replay " + dir + " 2>&1; }");
  EXPECT_EQ(folder.status, 2);
  EXPECT_NE(folder.out.find("is a directory, not an NC program"), std::string::npos) << folder.out;
  // A program whose tool lives in the control's table: certified with the table given as for run;
  // without it the error names the program.
  std::string named = dir + "/certify-named-tool.mpf";
  std::ofstream(named) << "T=\"FLAT 10\" D1\nG0 X-10 Y-10\nG1 G41 X0 Y0 F500\nX40\nY30\nX0\nG40 X-10 Y40\nM30\n";
  Result tool = sh(kCli + " certify --from " + named + " --neighbours 10 --tool '\"FLAT 10\"=5'");
  EXPECT_EQ(tool.status, 0) << tool.out;
  EXPECT_NE(tool.out.find("the program and 10 neighbours: "), std::string::npos) << tool.out;
  Result no_tool = sh("{ " + kCli + " certify --from " + named + " --neighbours 10 2>&1; }");
  EXPECT_EQ(no_tool.status, 2);
  EXPECT_NE(no_tool.out.find("certify-named-tool.mpf: line 1, column 1: tool \"FLAT 10\""), std::string::npos)
      << no_tool.out;
}
}  // namespace
