// `cutcom certify`: a campaign on generated programs (sharded, in parallel, merged, reported),
// the replay of given programs, and a user's programs with their neighbours (--from).
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "commands.hpp"
#include "knife_edge_watch.hpp"
#include "neighbours.hpp"
#include "parallel_campaign.hpp"

namespace cutcom::cli {

namespace {

// A program and its machine data (FILE.md beside it, as in tests/corpus), for --replay and --from.
struct ProgramWithData {
  std::string text, md_text;
  cutcom::MachineData md;
};
ProgramWithData read_program_with_data(const std::string& f) {
  if (std::filesystem::is_directory(f)) throw FileError(fmt::format("'{}' is a directory, not an NC program", f));
  std::ifstream in(f);
  if (!in) throw FileError(fmt::format("cannot open program '{}': {}", f, std::strerror(errno)));
  ProgramWithData p;
  p.text = read_all(in);
  std::filesystem::path md_file = std::filesystem::path(f).replace_extension(".md");
  if (std::filesystem::exists(md_file)) {
    std::ifstream m(md_file);
    p.md_text = read_all(m);
    std::istringstream again(p.md_text);
    p.md.load(again, md_file.string());
  }
  return p;
}

// Where a program's subprograms are looked for: its own folder.
std::string program_folder(const std::string& file) {
  std::string folder = std::filesystem::path(file).parent_path().string();
  return folder.empty() ? "." : folder;
}

// The control's data for one program of --replay/--from (its folder first for subprograms), as
// `cutcom run` sets it up.
std::function<void(cutcom::ProgramReader&)> reader_setup(const RunOptions& control, const std::string& file) {
  RunOptions o = control;
  o.program = file;
  ControlData data = control_data(o);
  return [data](cutcom::ProgramReader& reader) { data.into(reader); };
}

// A program of --replay/--from that the reader rejects: the error names the file.
template <class F>
auto naming_the_file(const std::string& file, F f) {
  try {
    return f();
  } catch (const cutcom::InputError& e) {
    throw FileError(fmt::format("{}: {}", file, e.what()));
  }
}

// `certify --replay`: each program (with its FILE.md machine data beside it, as in tests/corpus)
// through both engines, judged as a campaign case; exit 1 on an unexplained divergence.
int replay_programs(const std::vector<std::string>& files, const RunOptions& control) {
  bool diverged = false;
  for (const auto& f : files) {
    ProgramWithData p = read_program_with_data(f);
    auto setup = reader_setup(control, f);
    cutcom::props::ReplayVerdict v =
        naming_the_file(f, [&] { return cutcom::props::replay(p.text, p.md, program_folder(f), setup); });
    diverged = diverged || v.verdict == "diverge";
    std::cout << fmt::format("{}: {}", f, v.verdict);
    if (!v.clause.empty()) std::cout << " (" << v.clause << ")";
    if (v.verdict == "agree")
      std::cout << fmt::format(", largest coordinate error {:.3g} mm ({:.3g} of the tolerance)", v.error, v.ratio);
    if (!v.explanation.empty() && v.verdict != "agree") std::cout << ": " << v.explanation;
    std::cout << "\n";
  }
  return diverged ? kAlarm : kDone;
}

// `certify --from`: each program and `count` neighbours of it (values moved by small steps and
// onto exact ties, machine data near theirs), judged as campaign cases. A neighbour that
// diverges is written beside the program (NAME.neighbour-K.mpf and .md) to replay; exit 1.
int certify_from(const std::vector<std::string>& files, long count, std::uint64_t seed, const RunOptions& control) {
  bool diverged = false;
  for (const auto& f : files) {
    ProgramWithData p = read_program_with_data(f);
    auto setup = reader_setup(control, f);
    std::map<std::string, long> verdicts, knife_edges;
    long rejected = 0;
    double worst = 0;
    for (long k = 0; k <= count; ++k) {
      cutcom::props::Neighbour n{p.text, p.md, "the program itself"};
      if (k > 0) n = cutcom::props::neighbour_of(p.text, p.md, seed, k);
      cutcom::props::ReplayVerdict v;
      try {
        v = cutcom::props::replay(n.text, n.md, program_folder(f), setup);
      } catch (const cutcom::InputError& e) {  // a neighbour the reader rejects (an unreachable CR=, say)
        if (k == 0) throw FileError(fmt::format("{}: {}", f, e.what()));
        ++rejected;
        continue;
      } catch (const std::exception& e) {
        if (k == 0) throw;
        ++rejected;
        continue;
      }
      ++verdicts[v.verdict];
      if (v.verdict.rfind("knife-edge", 0) == 0) ++knife_edges[v.clause];
      if (v.verdict == "agree") worst = std::max(worst, v.ratio);
      if (v.verdict != "diverge") continue;
      diverged = true;
      std::filesystem::path base = std::filesystem::path(f).replace_extension("");
      std::string out = fmt::format("{}.neighbour-{}", base.string(), k);
      std::ofstream(out + ".mpf") << n.text;
      std::ofstream(out + ".md") << p.md_text << "MD20210=" << machine_datum_value(n.md, "MD20210")
                                 << "\nMD20230=" << machine_datum_value(n.md, "MD20230")
                                 << "\nMD20240=" << machine_datum_value(n.md, "MD20240") << "\n";
      std::cout << fmt::format("{}: neighbour {} ({}) diverges: {}\n  written to {}.mpf\n", f, k, n.change,
                               v.explanation, out);
    }
    auto count_of = [&](const char* v) { return verdicts.count(v) ? verdicts.at(v) : 0L; };
    std::cout << fmt::format(
        "{}: the program and {} neighbours: {} agree, {} knife edges ({} ending differently), {} not supported, {} "
        "rejected by the reader, {} unexplained divergences; largest coordinate error {:.3g} of the tolerance\n",
        f, count, count_of("agree"), count_of("knife-edge") + count_of("knife-edge-ends-differ"),
        count_of("knife-edge-ends-differ"), count_of("not-supported"), rejected, count_of("diverge"), worst);
    for (const auto& [clause, n] : knife_edges) std::cout << fmt::format("  knife edges {}: {}\n", clause, n);
  }
  return diverged ? kAlarm : kDone;
}

}  // namespace

int certify_command(CertifyOptions& o) {
  using cutcom::props::CampaignSummary;
  if (!o.replay.empty()) return replay_programs(o.replay, o.control);
  if (!o.from.empty()) return certify_from(o.from, o.neighbours, o.campaign.seed, o.control);
  if (o.show >= 0) {  // one case, to replay it with `cutcom run`
    auto [program, md] = cutcom::props::campaign_case(o.campaign.seed, o.show);
    std::string words = md.substr(0, md.size() - 1);
    std::replace(words.begin(), words.end(), '\n', ' ');
    std::cout << "; campaign " << o.campaign.seed << " case " << o.show << ", machine data: " << words << "\n"
              << program;
    return kDone;
  }
  if (o.merge.empty() && o.campaign.cases == 0 && o.campaign.seconds == 0) {  // it would never stop
    std::cerr << "cutcom: --cases 0 runs until --time: give --time SECONDS, or a number of cases\n";
    return kBadInput;
  }
  // The report's coverage table lists the spec's clauses: the folder must be there (run from the
  // repository, or name it), checked before a campaign runs.
  if (!o.report.empty() && !std::filesystem::is_directory(o.spec)) {
    std::cerr << fmt::format(
        "cutcom: --report needs the spec folder for its clause list: '{}' is not a folder (give --spec DIR)\n", o.spec);
    return kBadInput;
  }
  CampaignSummary s;
  double wall = 0;
  int used_jobs = 1;
  if (!o.merge.empty()) {
    for (const auto& f : o.merge) {
      std::ifstream in(f);
      if (!in) throw cutcom::MachineDataError(fmt::format("cannot open summary '{}'", f));
      s.merge(CampaignSummary::from_json(nlohmann::json::parse(in)));
    }
  } else {
    int i = 0, n = 0;
    char slash = 0;
    std::istringstream sh(o.shard);
    if (!(sh >> i >> slash >> n) || slash != '/' || n < 1 || i < 0 || i >= n)
      throw cutcom::MachineDataError(fmt::format("--shard wants I/N with 0 <= I < N, not '{}'", o.shard));
    o.campaign.shard = i, o.campaign.shards = n;
    int jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    cutcom::props::ParallelRun run = cutcom::props::run_campaign_jobs(o.campaign, jobs);
    s = std::move(run.summary);
    wall = run.wall_seconds, used_jobs = run.jobs;
  }
  if (!o.summary.empty()) std::ofstream(o.summary) << s.to_json().dump(1) << "\n";
  if (!o.write_knife_baseline.empty())
    std::ofstream(o.write_knife_baseline) << cutcom::props::knife_edge_baseline(s).dump(1) << "\n";
  std::vector<std::string> rises;
  if (!o.knife_baseline.empty()) {  // PROP-KNIFE-1
    std::ifstream in(o.knife_baseline);
    if (!in) throw cutcom::MachineDataError(fmt::format("cannot open knife-edge baseline '{}'", o.knife_baseline));
    nlohmann::json baseline = nlohmann::json::parse(in, nullptr, false);
    if (baseline.is_discarded())
      throw cutcom::MachineDataError(fmt::format("knife-edge baseline '{}' is not JSON", o.knife_baseline));
    try {
      rises = cutcom::props::knife_edge_rises(s, baseline);
    } catch (const std::runtime_error& e) {
      throw cutcom::MachineDataError(fmt::format("'{}': {}", o.knife_baseline, e.what()));
    }
  }
  if (!o.report.empty()) {
    std::string svg = o.histogram.empty()
                          ? (std::filesystem::path(o.report).parent_path() / "certification-errors.svg").string()
                          : o.histogram;
    cutcom::props::write_report(s, o.report, svg, o.spec);
  }
  long agree = s.verdicts.count("agree") ? s.verdicts.at("agree") : 0;
  long knife = s.verdicts.count("knife-edge") ? s.verdicts.at("knife-edge") : 0;
  long ends_differ = s.verdicts.count("knife-edge-ends-differ") ? s.verdicts.at("knife-edge-ends-differ") : 0;
  long unsupported = s.verdicts.count("not-supported") ? s.verdicts.at("not-supported") : 0;
  // s.seconds sums the shards' times: cases per second per core.
  std::string time =
      used_jobs > 1 ? fmt::format("{:.1f} s on {} jobs", wall, used_jobs) : fmt::format("{:.1f} s", s.seconds);
  std::cout << fmt::format(
      "{} cases in {} ({:.0f}/s per core): {} agree, {} knife edges (after {} of them the runs end differently), {} "
      "not "
      "supported, {} over budget, {} unexplained divergences; largest coordinate error {:.3g} mm (case {}), nearest "
      "its tolerance {:.3g} of it (case {})\n",
      s.cases, time, s.seconds > 0 ? static_cast<double>(s.cases) / s.seconds : 0.0, agree, knife + ends_differ,
      ends_differ, unsupported, s.over_budget.size(), s.divergences.size(), s.max_error, s.max_error_case, s.max_ratio,
      s.max_ratio_case);
  for (const auto& c : s.over_budget) std::cout << "over budget: case " << c << "\n";
  for (const auto& d : s.divergences) std::cout << "unexplained divergence: " << d << "\n";
  for (const auto& r : rises) std::cout << "knife edges rose beyond noise: " << r << "\n";
  if (!o.knife_baseline.empty() && rises.empty())
    std::cout << "knife edges per clause within noise of the baseline " << o.knife_baseline << "\n";
  return s.divergences.empty() && rises.empty() ? kDone : kAlarm;
}

}  // namespace cutcom::cli
