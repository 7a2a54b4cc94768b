#include "campaign.hpp"

#include <fmt/format.h>
#include <poll.h>
#include <rapidcheck.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <stdexcept>

#include "cutcom/output.hpp"
#include "generators.hpp"
#include "run_case.hpp"

namespace cutcom::props {

namespace {

// Every capability built so far: the mixed contour generator (lines, circles, near-tangent and
// near-reversal corners, notches, tiny blocks, the ends, bottlenecks), circles near the tool
// radius, and SAR at either end. Case k takes source k mod 6.
struct Source {
  const char* name;
  rc::Gen<ContourCase> (*make)();
};
constexpr Source kSources[] = {{"any", any_contour}, {"sar", sar_contour}, {"any", any_contour},
                               {"sar", sar_contour}, {"any", any_contour}, {"near-radius", circles_near_radius}};

struct Outcome {
  std::string verdict;  // agree, knife-edge, knife-edge-ends-differ, not-supported, diverge
  std::string clause;   // knife edge: the parting clause
  std::string explanation;
  double error = 0, ratio = 0;
  bool compared_after = false;  // a knife edge compared on after it (PROP-DIFF-2)
  CaseRuns runs;
};

// PROP-DIFF-1, as the differential properties decide it (differential_props.cpp).
Outcome judge(CaseRuns runs) {
  Outcome o;
  o.runs = std::move(runs);
  const CaseRuns& r = o.runs;
  Verdict v = compare(r.ref, r.fast, r.tolerance);
  o.explanation = v.explanation;
  o.compared_after = v.compared_after;
  if (r.untraced) return o.explanation = *r.untraced, o.verdict = "diverge", o;  // PROP-TRACE-1
  if (r.ref_unsupported || r.fast_unsupported) {
    if (r.ref_unsupported == r.fast_unsupported) return o.verdict = "not-supported", o;
    if (v.kind != Verdict::Kind::kKnifeEdge) return o.verdict = "diverge", o;
  }
  if (v.kind == Verdict::Kind::kDiverge) return o.verdict = "diverge", o;
  if (v.kind == Verdict::Kind::kKnifeEdge) {
    // A knife edge after which the runs end differently (one clean, one with an alarm or a
    // rejection, or other alarms) is a verdict of its own: legitimate, but the user sees it.
    bool same_end = r.ref_unsupported == r.fast_unsupported && r.ref.alarms.size() == r.fast.alarms.size();
    for (std::size_t i = 0; same_end && i < r.ref.alarms.size(); ++i)
      same_end = r.ref.alarms[i].number == r.fast.alarms[i].number;
    o.verdict = same_end ? "knife-edge" : "knife-edge-ends-differ";
    o.clause = v.clause;
    return o;
  }
  o.verdict = "agree";
  o.error = v.max_coordinate_error;
  o.ratio = r.tolerance.coordinate > 0 ? o.error / r.tolerance.coordinate : 0;
  return o;
}

Outcome evaluate(const ContourCase& c) { return judge(run_case(c, false)); }

int bin_of(double value) {
  if (!(value > 0)) return 0;
  int b = static_cast<int>(std::floor((std::log10(value) + 20) * 10)) + 1;
  return std::clamp(b, 1, 160);
}

// RapidCheck's own shrinks, greedily: the first smaller case that still diverges, until none does.
ContourCase shrink(rc::Shrinkable<ContourCase> s, int budget) {
  ContourCase best = s.value();
  for (bool progress = true; progress && budget > 0;) {
    progress = false;
    for (auto seq = s.shrinks(); auto next = seq.next();) {
      if (--budget <= 0) break;
      ContourCase candidate = next->value();
      try {
        if (evaluate(candidate).verdict != "diverge") continue;
      } catch (const std::exception&) {
        continue;
      }
      s = *next, best = candidate, progress = true;
      break;
    }
  }
  return best;
}

std::string machine_data_text(const ContourCase& c) {
  return fmt::format("MD20210={}\nMD20230={}\nMD20240={}\n{}", c.md20210, c.md20230, c.md20240,
                     c.md20250 == ContourCase::kMd20250 ? "" : fmt::format("MD20250={}\n", c.md20250));
}

// tests/corpus/<name>.mpf, .md (machine data) and .ref.json (ref's output, the expected result).
std::string write_corpus(const std::string& dir, const std::string& name, const ContourCase& c,
                         const std::string& why) {
  std::filesystem::create_directories(dir);
  std::string base = dir + "/" + name;
  // ref reads the file as written, comment included: its line numbers are the file's.
  std::string program = "; found by cutcom certify: " + why + "\n" + to_program(c);
  std::ofstream(base + ".mpf") << program;
  std::ofstream(base + ".md") << machine_data_text(c);
  MachineData md = machine_data_of(c);
  std::istringstream in(program);
  ProgramReader reader(in, md.initial_state());
  std::ofstream out(base + ".ref.json");
  JsonWriter writer(out, "ref", false);
  try {
    ref::run(reader, md, writer);
  } catch (const UnsupportedError&) {
  }
  writer.finish();
  return base + ".mpf";
}

}  // namespace

std::uint64_t case_seed(std::uint64_t seed, long k) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (static_cast<std::uint64_t>(k) + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

namespace {
rc::Shrinkable<ContourCase> generate(std::uint64_t seed, long k) {
  rc::Gen<ContourCase> gen = kSources[k % 6].make();
  // One case in twelve of the mixed generator is a variant for the rules around selection, one in
  // twelve of the SAR generator a variant of its approach (kVariantNames).
  int v = 0;
  if (k % 12 == 4) v = 1 + static_cast<int>((case_seed(seed, k) >> 8) % (kSarVariants - 1));
  if (k % 12 == 3) v = kSarVariants + static_cast<int>((case_seed(seed, k) >> 8) % (kVariants - kSarVariants));
  if (v) {
    gen = rc::gen::map(gen, [v](ContourCase c) {
      c.variant = v;
      return c;
    });
  }
  return gen(rc::Random(case_seed(seed, k)), static_cast<int>(k % 101));
}
}  // namespace

ReplayVerdict replay(const std::string& program, const MachineData& md, const std::string& folder,
                     const std::function<void(ProgramReader&)>& setup) {
  Outcome o = judge(run_program(program, md, false, folder, setup));
  return {o.verdict, o.clause, o.explanation, o.error, o.ratio};
}

std::pair<std::string, std::string> campaign_case(std::uint64_t seed, long k) {
  ContourCase c = generate(seed, k).value();
  return {to_program(c), machine_data_text(c)};
}

std::string write_corpus_case(const std::string& dir, const std::string& name, std::uint64_t seed, long k,
                              const std::string& why) {
  return write_corpus(dir, name, generate(seed, k).value(), why);
}

namespace {

long case_of(const CampaignOptions& o, long i) { return o.shard + i * o.shards; }  // the campaign's case number

// A helix: no axis on which centre, start and end coincide (a circle keeps its applicate).
bool is_helix(const PathElement& e) {
  auto same = [](double c, double a, double b) { return c == a && a == b; };
  return e.type == ElementType::kArc && !same(e.center.x, e.start.x, e.end.x) &&
         !same(e.center.y, e.start.y, e.end.y) && !same(e.center.z, e.start.z, e.end.z);
}

std::set<std::string> evidence_of(const RunResult& ref) {
  std::set<std::string> out;
  for (const Alarm& a : ref.alarms) out.insert("alarm:" + std::string(a.clause));
  for (const Notice& n : ref.notices) out.insert("notice:" + std::string(n.clause));
  for (const PathElement& e : ref.path) {
    out.insert("element:" + std::string(origin_kind_name(e.origin.kind)));
    if (e.origin.sar != SarMove::kNone) out.insert("sar:" + std::string(sar_move_name(e.origin.sar)));
    if (is_helix(e)) out.insert("helix");
  }
  if (!ref.actions.empty()) out.insert("actions");
  if (!ref.variables.empty()) out.insert("variables");
  return out;
}

CaseRecord run_one(const CampaignOptions& o, long k) {
  CaseRecord r;
  r.k = k;
  r.source = kSources[k % 6].name;
  auto t0 = std::chrono::steady_clock::now();
  try {
    ContourCase c = generate(o.seed, k).value();
    r.style = c.style;
    Outcome out = evaluate(c);
    r.verdict = out.verdict, r.clause = out.clause;
    if (out.verdict == "diverge") r.explanation = out.explanation;
    const RunResult& ref = out.runs.ref;
    r.alarm = ref.alarms.empty() ? "none" : std::to_string(ref.alarms[0].number);
    for (const Decision& d : ref.decisions) {
      std::pair<long, long>& b = r.decisions[std::string(d.clause)][std::string(d.branch)];
      ++b.first;
      double band = out.runs.tolerance.band(d.clause);
      if (d.has_margin && band > 0 && std::fabs(margin_value(d)) <= band) ++b.second;
    }
    if (out.verdict == "agree") r.error = out.error, r.ratio = out.ratio;
    r.evidence = evidence_of(ref);
    if (c.variant) r.evidence.insert(std::string("variant:") + kVariantNames[c.variant]);
    if (out.compared_after && out.verdict != "diverge") r.evidence.insert("knife-edge-compared-after");
  } catch (const std::exception& e) {  // an engine must alarm or reject, never throw anything else
    r.verdict = "crash", r.explanation = std::string("exception: ") + e.what();
  }
  r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

bool stops(const CaseRecord& r) { return r.verdict == "diverge" || r.verdict == "crash"; }

void write_all(int fd, const std::string& text) {
  for (std::size_t done = 0; done < text.size();) {
    ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) ::_exit(3);  // the parent is gone
    done += static_cast<std::size_t>(n);
  }
}

// The child of a budgeted shard: cases from index i on, one JSON line each on `fd`.
[[noreturn]] void worker(const CampaignOptions& o, long i, int fd) {
  for (; o.cases == 0 || i < o.cases; ++i) {
    CaseRecord r = run_one(o, case_of(o, i));
    write_all(fd, r.to_json().dump() + "\n");
    if (stops(r)) break;
  }
  ::close(fd);
  ::_exit(0);  // no atexit handlers of the parent's libraries in the child
}

// Runs the shard's cases in child processes, restarting after a case over budget. `take`
// counts a record and says whether the shard stops.
template <class Take, class Elapsed>
void run_budgeted(const CampaignOptions& o, Take take, Elapsed elapsed) {
  long i = 0;
  bool stop = false;
  while (!stop && (o.cases == 0 || i < o.cases)) {
    if (o.seconds > 0 && elapsed() >= o.seconds) break;
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error("certify: cannot create a pipe");
    std::cout.flush(), std::cerr.flush();
    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("certify: cannot fork");
    if (pid == 0) ::close(fds[0]), worker(o, i, fds[1]);
    ::close(fds[1]);
    std::string pending;
    auto last = std::chrono::steady_clock::now();
    for (;;) {
      double wait = o.budget - std::chrono::duration<double>(std::chrono::steady_clock::now() - last).count();
      if (o.seconds > 0) wait = std::min(wait, o.seconds - elapsed());
      pollfd p{fds[0], POLLIN, 0};
      int ready = ::poll(&p, 1, static_cast<int>(std::ceil(std::max(wait, 0.0) * 1000)));
      if (ready < 0 && errno == EINTR) continue;
      if (ready == 0) {  // the time limit, or the case's budget
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
        if (o.seconds > 0 && elapsed() >= o.seconds) {
          stop = true;  // the case under way is not counted
          break;
        }
        CaseRecord r;
        r.k = case_of(o, i), r.source = kSources[r.k % 6].name, r.verdict = "over-budget", r.ms = o.budget * 1000;
        ++i;
        stop = take(r);
        break;
      }
      char chunk[1 << 16];
      ssize_t got = ::read(fds[0], chunk, sizeof chunk);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {  // the child ended
        int status = 0;
        ::waitpid(pid, &status, 0);
        if (!stop && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) {
          CaseRecord r;
          r.k = case_of(o, i), r.source = kSources[r.k % 6].name, r.verdict = "crash";
          r.explanation = WIFSIGNALED(status) ? fmt::format("killed by signal {}", WTERMSIG(status))
                                              : fmt::format("exit status {}", WEXITSTATUS(status));
          ++i;
          stop = take(r);
        }
        if (o.cases != 0 && i < o.cases && !stop) stop = true;  // ended early without a reason: do not loop
        break;
      }
      pending.append(chunk, static_cast<std::size_t>(got));
      for (std::size_t nl; !stop && (nl = pending.find('\n')) != std::string::npos;) {
        CaseRecord r = CaseRecord::from_json(nlohmann::json::parse(pending.substr(0, nl)));
        pending.erase(0, nl + 1);
        ++i;
        last = std::chrono::steady_clock::now();
        stop = take(r);
      }
      // Every case of the shard is in: the worker has only its exit left, and no case is under
      // way that its budget could count twice (a poll timing out before that exit counted the
      // case after the shard's last one over budget: 13 cases of 12).
      if (stop || (o.cases != 0 && i >= o.cases)) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
        break;
      }
    }
    ::close(fds[0]);
  }
}

}  // namespace

CampaignSummary run_campaign(const CampaignOptions& o) {
  CampaignSummary s;
  s.seed = o.seed;
  s.shards.push_back(fmt::format("{}/{}", o.shard, o.shards));
  std::ofstream results;
  if (!o.results.empty()) results.open(o.results);
  auto started = std::chrono::steady_clock::now();
  auto last_print = started;
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  long done_cases = 0;
  auto take = [&](const CaseRecord& r) {
    s.add(r);
    ++done_cases;
    if (o.live) {
      ++o.live->cases;
      if (r.verdict == "knife-edge" || r.verdict == "knife-edge-ends-differ") ++o.live->knife_edges;
      if (r.verdict == "over-budget") ++o.live->over_budget;
    }
    if (results.is_open())
      results << nlohmann::json{{"case", r.k},        {"source", r.source},
                                {"style", r.style},   {"verdict", r.verdict},
                                {"clause", r.clause}, {"error", r.error},
                                {"ratio", r.ratio},   {"ms", std::round(r.ms * 1000) / 1000}}
                     .dump()
              << "\n";
    if (stops(r)) {
      std::string what = fmt::format("case {}/{}: {}", o.seed, r.k, r.explanation);
      if (r.verdict == "diverge" && !o.corpus.empty()) {
        rc::Shrinkable<ContourCase> shrinkable = generate(o.seed, r.k);
        ContourCase minimal = shrink(shrinkable, 2000);
        std::string file =
            write_corpus(o.corpus, fmt::format("case-{}-{}", o.seed, r.k), minimal, evaluate(minimal).explanation);
        what += " -> " + file;
      }
      s.divergences.push_back(what);
      if (o.live) ++o.live->divergences, o.live->stop = true;  // the parallel shards stop too
      if (o.progress) std::cerr << "\nunexplained divergence: " << what << "\n";
      return true;
    }
    if (o.live && o.live->stop) return true;
    if (o.progress && std::chrono::steady_clock::now() - last_print > std::chrono::milliseconds(500)) {
      last_print = std::chrono::steady_clock::now();
      double done = o.cases ? static_cast<double>(done_cases) / static_cast<double>(o.cases)
                            : (o.seconds > 0 ? elapsed() / o.seconds : 0);
      int filled = static_cast<int>(std::clamp(done, 0.0, 1.0) * 30);
      std::cerr << fmt::format("\r[{:<30}] {} cases  {:.0f}/s  knife edges {}  over budget {}  divergences {}",
                               std::string(static_cast<std::size_t>(filled), '#'), s.cases,
                               static_cast<double>(s.cases) / std::max(elapsed(), 1e-9),
                               s.verdicts["knife-edge"] + s.verdicts["knife-edge-ends-differ"], s.over_budget.size(),
                               s.divergences.size())
                << std::flush;
    }
    return false;
  };
  if (o.budget > 0) {
    run_budgeted(o, take, elapsed);
  } else {
    for (long i = 0; o.cases == 0 || i < o.cases; ++i) {
      if (o.seconds > 0 && elapsed() >= o.seconds) break;
      if (take(run_one(o, case_of(o, i)))) break;
    }
  }
  s.seconds = elapsed();
  if (o.progress) std::cerr << "\n";
  return s;
}

nlohmann::json CaseRecord::to_json() const {
  nlohmann::json d = nlohmann::json::object();
  for (const auto& [id, branches] : decisions)
    for (const auto& [branch, n] : branches) d[id][branch] = {n.first, n.second};
  return {{"k", k},           {"source", source},   {"style", style}, {"verdict", verdict},
          {"clause", clause}, {"why", explanation}, {"alarm", alarm}, {"error", error},
          {"ratio", ratio},   {"ms", ms},           {"decisions", d}, {"evidence", evidence}};
}

CaseRecord CaseRecord::from_json(const nlohmann::json& j) {
  CaseRecord r;
  r.k = j.at("k").get<long>();
  r.source = j.at("source").get<std::string>(), r.style = j.at("style").get<std::string>();
  r.verdict = j.at("verdict").get<std::string>(), r.clause = j.at("clause").get<std::string>();
  r.explanation = j.at("why").get<std::string>(), r.alarm = j.at("alarm").get<std::string>();
  r.error = j.at("error").get<double>(), r.ratio = j.at("ratio").get<double>(), r.ms = j.at("ms").get<double>();
  for (const auto& [clause, branches] : j.at("decisions").items())
    for (const auto& [branch, n] : branches.items()) r.decisions[clause][branch] = {n[0].get<long>(), n[1].get<long>()};
  r.evidence = j.at("evidence").get<std::set<std::string>>();
  return r;
}

void CampaignSummary::add(const CaseRecord& r) {
  ++cases;
  ++verdicts[r.verdict];
  if (!r.style.empty()) ++styles[r.style];
  if (r.verdict == "over-budget") over_budget.push_back(fmt::format("{}/{}", seed, r.k));
  if (r.verdict == "over-budget" || r.verdict == "crash") return;
  ++alarms[r.alarm];
  for (const std::string& e : r.evidence) ++evidence[e];
  if (r.verdict == "knife-edge" || r.verdict == "knife-edge-ends-differ") ++knife_edges[r.clause];
  if (r.verdict == "knife-edge-ends-differ") ++knife_edges_ending_differently[r.clause];
  for (const auto& [clause, branches] : r.decisions)
    for (const auto& [branch, n] : branches) {
      BranchCount& b = coverage[clause][branch];
      b.taken += n.first, b.knife += n.second;
    }
  if (r.verdict == "agree") {
    ++error_bins[static_cast<std::size_t>(bin_of(r.error))];
    ++ratio_bins[static_cast<std::size_t>(bin_of(r.ratio))];
    if (r.error > max_error) max_error = r.error, max_error_case = fmt::format("{}/{}", seed, r.k);
    if (r.ratio > max_ratio) max_ratio = r.ratio, max_ratio_case = fmt::format("{}/{}", seed, r.k);
  }
}

nlohmann::json CampaignSummary::to_json() const {
  nlohmann::json cov = nlohmann::json::object();
  for (const auto& [clause, branches] : coverage)
    for (const auto& [branch, n] : branches) cov[clause][branch] = {n.taken, n.knife};
  return {{"format", "cutcom-certify/1"},
          {"seed", seed},
          {"shards", shards},
          {"cases", cases},
          {"seconds", seconds},
          {"verdicts", verdicts},
          {"knife_edges", knife_edges},
          {"knife_edges_ending_differently", knife_edges_ending_differently},
          {"styles", styles},
          {"alarms", alarms},
          {"coverage", cov},
          {"error_bins", error_bins},
          {"ratio_bins", ratio_bins},
          {"max_error", max_error},
          {"max_ratio", max_ratio},
          {"max_error_case", max_error_case},
          {"max_ratio_case", max_ratio_case},
          {"divergences", divergences},
          {"over_budget", over_budget},
          {"evidence", evidence}};
}

CampaignSummary CampaignSummary::from_json(const nlohmann::json& j) {
  CampaignSummary s;
  s.seed = j.at("seed").get<std::uint64_t>();
  s.shards = j.at("shards").get<std::vector<std::string>>();
  s.cases = j.at("cases").get<long>();
  s.seconds = j.at("seconds").get<double>();
  s.verdicts = j.at("verdicts").get<std::map<std::string, long>>();
  s.knife_edges = j.at("knife_edges").get<std::map<std::string, long>>();
  if (j.contains("knife_edges_ending_differently"))  // older summaries
    s.knife_edges_ending_differently = j.at("knife_edges_ending_differently").get<std::map<std::string, long>>();
  s.styles = j.at("styles").get<std::map<std::string, long>>();
  s.alarms = j.at("alarms").get<std::map<std::string, long>>();
  for (const auto& [clause, branches] : j.at("coverage").items())
    for (const auto& [branch, n] : branches.items()) s.coverage[clause][branch] = {n[0].get<long>(), n[1].get<long>()};
  s.error_bins = j.at("error_bins").get<std::vector<long>>();
  s.ratio_bins = j.at("ratio_bins").get<std::vector<long>>();
  s.max_error = j.at("max_error").get<double>();
  s.max_ratio = j.at("max_ratio").get<double>();
  s.max_error_case = j.at("max_error_case").get<std::string>();
  if (j.contains("max_ratio_case")) s.max_ratio_case = j.at("max_ratio_case").get<std::string>();  // older summaries
  s.divergences = j.at("divergences").get<std::vector<std::string>>();
  if (j.contains("over_budget")) s.over_budget = j.at("over_budget").get<std::vector<std::string>>();
  if (j.contains("evidence")) s.evidence = j.at("evidence").get<std::map<std::string, long>>();
  return s;
}

void CampaignSummary::merge(const CampaignSummary& o) {
  if (shards.empty()) seed = o.seed;
  shards.insert(shards.end(), o.shards.begin(), o.shards.end());
  cases += o.cases, seconds += o.seconds;
  for (const auto& [k, v] : o.verdicts) verdicts[k] += v;
  for (const auto& [k, v] : o.knife_edges) knife_edges[k] += v;
  for (const auto& [k, v] : o.knife_edges_ending_differently) knife_edges_ending_differently[k] += v;
  for (const auto& [k, v] : o.styles) styles[k] += v;
  for (const auto& [k, v] : o.alarms) alarms[k] += v;
  for (const auto& [clause, branches] : o.coverage)
    for (const auto& [branch, n] : branches) {
      BranchCount& b = coverage[clause][branch];
      b.taken += n.taken, b.knife += n.knife;
    }
  for (std::size_t i = 0; i < error_bins.size(); ++i)
    error_bins[i] += o.error_bins[i], ratio_bins[i] += o.ratio_bins[i];
  if (o.max_error > max_error) max_error = o.max_error, max_error_case = o.max_error_case;
  if (o.max_ratio > max_ratio) max_ratio = o.max_ratio, max_ratio_case = o.max_ratio_case;
  divergences.insert(divergences.end(), o.divergences.begin(), o.divergences.end());
  over_budget.insert(over_budget.end(), o.over_budget.begin(), o.over_budget.end());
  for (const auto& [k, v] : o.evidence) evidence[k] += v;
}

double CampaignSummary::error_percentile(double p, bool ratio) const {
  const std::vector<long>& bins = ratio ? ratio_bins : error_bins;
  long total = 0;
  for (long n : bins) total += n;
  if (total == 0) return 0;
  long target = static_cast<long>(std::ceil(p * static_cast<double>(total))), seen = 0;
  for (std::size_t i = 0; i < bins.size(); ++i) {
    seen += bins[i];
    if (seen >= target) return i == 0 ? 0.0 : std::pow(10.0, static_cast<double>(i) / 10.0 - 20);
  }
  return std::pow(10.0, -4.0);
}

}  // namespace cutcom::props
