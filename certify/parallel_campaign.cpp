// Parallel shards of one campaign (parallel_campaign.hpp): fork() per shard (the campaign is
// single-threaded, so a child starts from a consistent copy), summaries handed back through
// files, progress and the stop at a divergence through counters in shared memory.
#include "parallel_campaign.hpp"

#include <fmt/format.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace cutcom::props {

namespace {

struct SharedCounts {  // LiveCounts in memory the children share with the parent
  LiveCounts* counts = nullptr;
  SharedCounts() {
    void* m = mmap(nullptr, sizeof(LiveCounts), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (m == MAP_FAILED) throw std::runtime_error("cannot map memory for the parallel shards");
    counts = new (m) LiveCounts();
  }
  ~SharedCounts() {
    counts->~LiveCounts();
    munmap(counts, sizeof(LiveCounts));
  }
  SharedCounts(const SharedCounts&) = delete;
  SharedCounts& operator=(const SharedCounts&) = delete;
};

struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "cutcom-certify-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a directory for the parallel shards");
    path = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

}  // namespace

ParallelRun run_campaign_jobs(const CampaignOptions& o, int jobs) {
  ParallelRun run;
  auto started = std::chrono::steady_clock::now();
  auto wall = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  if (o.cases > 0 && jobs > o.cases) jobs = static_cast<int>(o.cases);
  if (jobs <= 1) {
    run.summary = run_campaign(o);
    run.wall_seconds = wall();
    return run;
  }
  run.jobs = jobs;
  TempDir dir;
  SharedCounts shared;
  struct Child {
    pid_t pid;
    std::filesystem::path summary, results;
  };
  std::vector<Child> children;
  std::cout.flush(), std::cerr.flush();
  for (int j = 0; j < jobs; ++j) {
    CampaignOptions c = o;
    c.shard = o.shard + o.shards * j, c.shards = o.shards * jobs;  // case k = shard + shards * i, as in one process
    if (o.cases > 0) c.cases = o.cases / jobs + (j < o.cases % jobs ? 1 : 0);
    c.progress = false;  // the parent shows the progress of all of them
    c.live = shared.counts;
    Child child{0, dir.path / fmt::format("shard{}.json", j), dir.path / fmt::format("shard{}.jsonl", j)};
    if (!o.results.empty()) c.results = child.results.string();
    child.pid = fork();
    if (child.pid < 0) {
      for (const Child& k : children) kill(k.pid, SIGTERM), waitpid(k.pid, nullptr, 0);
      throw std::runtime_error("cannot start a process for a parallel shard");
    }
    if (child.pid == 0) {
      int status = 0;
      try {
        CampaignSummary s = run_campaign(c);
        std::ofstream out(child.summary);
        out << s.to_json().dump() << "\n";
        status = out.good() ? 0 : 3;
      } catch (const std::exception& e) {
        std::cerr << fmt::format("cutcom: shard {}/{}: {}\n", c.shard, c.shards, e.what());
        status = 2;
      }
      std::cerr.flush();
      _exit(status);
    }
    children.push_back(child);
  }
  // Progress of the whole campaign while the shards run.
  std::size_t running = children.size();
  std::vector<int> statuses(children.size(), -1);
  auto last_print = std::chrono::steady_clock::now();
  while (running > 0) {
    for (std::size_t j = 0; j < children.size(); ++j) {
      if (statuses[j] != -1) continue;
      int st = 0;
      pid_t r = waitpid(children[j].pid, &st, WNOHANG);
      if (r == children[j].pid) statuses[j] = st, --running;
    }
    if (running == 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (o.progress && std::chrono::steady_clock::now() - last_print > std::chrono::milliseconds(500)) {
      last_print = std::chrono::steady_clock::now();
      const LiveCounts& n = *shared.counts;
      double done = o.cases ? static_cast<double>(n.cases) / static_cast<double>(o.cases)
                            : (o.seconds > 0 ? wall() / o.seconds : 0);
      int filled = static_cast<int>(std::clamp(done, 0.0, 1.0) * 30);
      std::cerr << fmt::format(
                       "\r[{:<30}] {} cases  {:.0f}/s on {} jobs  knife edges {}  over budget {}  divergences {}",
                       std::string(static_cast<std::size_t>(filled), '#'), n.cases.load(),
                       static_cast<double>(n.cases.load()) / std::max(wall(), 1e-9), jobs, n.knife_edges.load(),
                       n.over_budget.load(), n.divergences.load())
                << std::flush;
    }
  }
  if (o.progress) std::cerr << "\n";
  std::string failed;
  for (std::size_t j = 0; j < children.size(); ++j) {
    int st = statuses[j];
    if (WIFEXITED(st) && WEXITSTATUS(st) == 0) continue;
    failed += fmt::format("{}shard {}/{} {}", failed.empty() ? "" : "; ", o.shard + o.shards * static_cast<int>(j),
                          o.shards * jobs,
                          WIFSIGNALED(st) ? fmt::format("was killed by signal {}", WTERMSIG(st))
                                          : fmt::format("ended with status {}", WEXITSTATUS(st)));
  }
  if (!failed.empty()) throw std::runtime_error("a parallel shard failed: " + failed);
  std::ofstream results;
  if (!o.results.empty()) {
    results.open(o.results);
    if (!results) throw std::runtime_error(fmt::format("cannot write results '{}'", o.results));
  }
  for (const Child& c : children) {
    std::ifstream in(c.summary);
    nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded())
      throw std::runtime_error(fmt::format("a parallel shard left no summary ({})", c.summary.string()));
    run.summary.merge(CampaignSummary::from_json(j));
    std::ifstream lines(c.results);
    if (results.is_open() && lines.peek() != std::ifstream::traits_type::eof()) results << lines.rdbuf();
  }
  run.wall_seconds = wall();
  return run;
}

}  // namespace cutcom::props
