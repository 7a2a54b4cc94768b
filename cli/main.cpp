// cutcom: what a SINUMERIK 840D would do with an NC program under 2D tool radius compensation.
// Exit status: 0 done without alarm, 1 an alarm stopped the program, 2 bad input or usage.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <thread>

#include "campaign.hpp"
#include "cutcom/background_sink.hpp"
#include "cutcom/fast/engine.hpp"
#include "cutcom/machine_data.hpp"
#include "cutcom/output.hpp"
#include "cutcom/reader.hpp"
#include "cutcom/ref/engine.hpp"
#include "knife_edge_watch.hpp"
#include "neighbours.hpp"
#include "parallel_campaign.hpp"

namespace {

constexpr int kDone = 0, kAlarm = 1, kBadInput = 2;

struct RunOptions {
  std::string program;
  std::string engine = "fast";
  std::string format = "text";
  std::string output;
  std::vector<std::string> md;
  std::vector<std::string> md_files;
  std::vector<std::string> system_values;  // NC-PARAM-SYS-4: --sysvar
  std::vector<std::string> tool_files;
  std::string offsets_file;
  bool trace = false;
  std::int64_t max_loops = cutcom::InterpreterLimits{}.max_backward_jumps;
  std::vector<std::string> search_path;
  std::vector<std::string> tool_edges;  // TOOL-FILE-2
  std::vector<std::string> definition_files;
  std::optional<std::string> arguments;
};

// A data file given on the command line is wrong: names the file and line (exit 2).
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// TOOL-FILE-1, NC-OFFSET-2: the control's tool table and settable offsets from files.
struct ControlData {
  cutcom::ToolTable tools;
  cutcom::OffsetTable offsets;
  cutcom::InterpreterLimits limits;
  std::vector<std::string> search_path;  // NC-PARAM-SUB-1: the program's folder, then --search-path
  std::vector<std::pair<std::string, std::string>> definitions;  // NC-PARAM-VAR-3: (file, text)
  std::optional<std::string> arguments;                          // NC-PARAM-SUB-5
  std::map<std::string, std::string> machine_values;             // NC-PARAM-SYS-4
  void into(cutcom::ProgramReader& reader) const {
    reader.set_machine_values(machine_values);
    reader.tools() = tools;
    reader.offsets() = offsets;
    reader.set_limits(limits);
    reader.set_search_path(search_path);
    for (const auto& [file, text] : definitions) {
      std::istringstream in(text);
      try {
        reader.load_definitions(in);
      } catch (const cutcom::InputError& e) {
        throw FileError(fmt::format("{}:{}:{}: {}", file, e.line(), e.column(), e.detail()));
      }
    }
    if (arguments) {
      try {
        reader.set_arguments(*arguments);
      } catch (const cutcom::InputError& e) {
        throw FileError(fmt::format("--args, column {}: {}", e.column(), e.detail()));
      }
    }
  }
};

template <class Table>
void load_file(Table& table, const std::string& file, const char* what) {
  if (std::filesystem::is_directory(file)) throw FileError(fmt::format("{} file '{}' is a directory", what, file));
  std::ifstream in(file);
  if (!in) throw FileError(fmt::format("cannot open {} file '{}'", what, file));
  try {
    table.load(in, file);
  } catch (const cutcom::InputError& e) {
    std::string_view detail = e.detail();  // (the table names the file too: once is enough)
    if (detail.starts_with(file + ": ")) detail.remove_prefix(file.size() + 2);
    throw FileError(fmt::format("{}:{}:{}: {}", file, e.line(), e.column(), detail));
  }
}

cutcom::MachineData machine_data(const RunOptions& o) {
  cutcom::MachineData md;
  for (const auto& f : o.md_files) {
    std::ifstream in(f);
    if (!in) throw cutcom::MachineDataError(fmt::format("cannot open machine data file '{}'", f));
    md.load(in, f);
  }
  for (const auto& a : o.md) md.set_assignment(a);
  return md;
}

ControlData control_data(const RunOptions& o) {
  ControlData c;
  for (const auto& f : o.tool_files) load_file(c.tools, f, "tool");
  for (const auto& t : o.tool_edges) {
    try {
      c.tools.define(t);  // TOOL-FILE-2: after the archives, so that it overrides them
    } catch (const cutcom::InputError& e) {
      throw FileError(fmt::format("--tool '{}', column {}: {}", t, e.column(), e.detail()));
    }
  }
  if (!o.offsets_file.empty()) load_file(c.offsets, o.offsets_file, "offsets");
  c.limits.max_backward_jumps = o.max_loops;
  for (const auto& f : o.definition_files) {
    if (std::filesystem::is_directory(f)) throw FileError(fmt::format("definitions file '{}' is a directory", f));
    std::ifstream in(f);
    if (!in) throw FileError(fmt::format("cannot open definitions file '{}'", f));
    std::ostringstream text;
    text << in.rdbuf();
    c.definitions.emplace_back(f, text.str());
  }
  c.arguments = o.arguments;
  c.machine_values = machine_data(o).program_values();
  for (const auto& a : o.system_values) {  // NC-PARAM-SYS-4: after the machine data, which they may not replace
    std::pair<std::string, std::string> given;
    try {
      given = cutcom::system_value_assignment(a);
    } catch (const cutcom::MachineDataError& e) {
      throw FileError(fmt::format("--sysvar '{}': {}", a, e.what()));
    }
    if (c.machine_values.count(given.first))
      throw FileError(fmt::format("--sysvar '{}': {} is machine data, given with --md", a, given.first));
    c.machine_values.insert(std::move(given));
  }
  std::filesystem::path folder =
      o.program == "-" ? std::filesystem::path(".") : std::filesystem::path(o.program).parent_path();
  c.search_path.push_back(folder.empty() ? "." : folder.string());
  for (const auto& d : o.search_path) c.search_path.push_back(d);
  return c;
}

// Passes everything on and keeps the numbers of the alarms raised, for a hint after the run.
class AlarmWatch : public cutcom::PathSink {
 public:
  explicit AlarmWatch(cutcom::PathSink& to) : to_(to) {}
  void element(const cutcom::PathElement& e) override { to_.element(e); }
  void action(const cutcom::ActionEvent& a) override { to_.action(a); }
  void decision(const cutcom::Decision& d) override { to_.decision(d); }
  void alarm(const cutcom::Alarm& a) override {
    numbers.push_back(a.number);
    to_.alarm(a);
  }
  void notice(const cutcom::Notice& n) override { to_.notice(n); }
  void sar_variables(const cutcom::SarVariables& v) override { to_.sar_variables(v); }
  std::vector<int> numbers;

 private:
  cutcom::PathSink& to_;
};

// TRC-SEL-7 without any tool data: most real programs keep it in the control's tool table.
void hint_after(const std::vector<int>& alarms, const RunOptions& o) {
  if (o.tool_files.empty() && o.tool_edges.empty() && std::find(alarms.begin(), alarms.end(), 17181) != alarms.end())
    std::cerr
        << "cutcom: alarm 17181: the active tool has no data for its edge. A control keeps tool data in its "
           "tool table: give it with --tool T=RADIUS (e.g. --tool 1=5 or --tool \"FLAT 10\"=5), with --tools FILE "
           "($TC_DPn[t,d]=... and $TC_TP2[t]=\"NAME\" lines, the TO_INI.INI convention) or assign $TC_DP1/$TC_DP6 in "
           "the program\n";
}

bool run_engine(const std::string& engine, cutcom::ProgramReader& reader, const cutcom::MachineData& md,
                cutcom::PathSink& out, const RunOptions& o) {
  AlarmWatch sink(out);
  bool ok = engine == "ref" ? cutcom::ref::run(reader, md, sink) : cutcom::fast::run(reader, md, sink);
  hint_after(sink.numbers, o);
  return ok;
}

std::string read_all(std::istream& in) {
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The output file is written beside its place and renamed when the run is done, so that a
// rejected program leaves no empty or partial file behind (NC-ERR-3, CLI-1). A path that is not a
// regular file (/dev/null, a pipe, a terminal) is written in place: renaming over it would replace
// the device with a file. A symbolic link is followed, so the file it names is replaced.
class OutputFile {
 public:
  explicit OutputFile(const std::string& path) : path_(path) {
    std::error_code ec;
    std::filesystem::path target = path_;
    for (int links = 0; links < 40 && std::filesystem::is_symlink(target, ec); ++links) {
      std::filesystem::path to = std::filesystem::read_symlink(target, ec);
      if (ec) break;
      target = to.is_absolute() ? to : target.parent_path() / to;
    }
    auto kind = std::filesystem::status(target, ec).type();
    in_place_ = !ec && kind != std::filesystem::file_type::regular && kind != std::filesystem::file_type::not_found;
    path_ = target.string();
    part_ = in_place_ ? path_ : path_ + ".part";
  }
  ~OutputFile() {
    if (!committed_ && file_.is_open()) {
      file_.close();
      std::error_code ec;
      if (!in_place_) std::filesystem::remove(part_, ec);
    }
  }
  bool open() {
    file_.open(part_);
    return static_cast<bool>(file_);
  }
  std::ostream& stream() { return file_; }
  void commit() {
    file_.close();
    if (!in_place_) std::filesystem::rename(part_, path_);
    committed_ = true;
  }

 private:
  std::string path_, part_;
  std::ofstream file_;
  bool in_place_ = false;  // not a regular file: written directly, never renamed over
  bool committed_ = false;
};

// CLI-1: the document is closed whatever happens: bad input found half-way ends it with the
// error (a JSON reader still parses it), then the error goes on to the caller (exit status 2).
// The writer runs on its own thread (BackgroundSink): all it was handed is written first.
template <class Writer, class Run>
bool run_to_the_end(Writer& writer, cutcom::BackgroundSink& background, Run run, const RunOptions& o,
                    std::ostream& out) {
  bool ok = false;
  try {
    ok = run();
  } catch (const cutcom::InputError& e) {
    background.finish();
    writer.error(o.program == "-" ? "stdin" : o.program, e.line(), e.column(), e.detail());
    writer.finish();
    out.flush();
    throw;
  }
  background.finish();
  writer.finish();
  return ok;
}

// The text and JSON writers: formatted on a second thread while the engine runs.
template <class Writer>
bool run_writing(Writer& writer, cutcom::ProgramReader& reader, const cutcom::MachineData& md, const RunOptions& o,
                 std::ostream& out) {
  cutcom::BackgroundSink background(writer, o.trace);
  background.set_upstream_sources([&reader](std::uint32_t id) -> const std::string& { return reader.source_text(id); });
  writer.set_sources(background.sources());
  return run_to_the_end(
      writer, background, [&] { return run_engine(o.engine, reader, md, background, o); }, o, out);
}

int run_command(const RunOptions& o) {
  cutcom::MachineData md = machine_data(o);
  ControlData control = control_data(o);

  std::ifstream file;
  std::istream* in = &std::cin;
  if (o.program != "-") {
    if (std::filesystem::is_directory(o.program)) {
      std::cerr << fmt::format("cutcom: '{}' is a directory, not an NC program\n", o.program);
      return kBadInput;
    }
    file.open(o.program);
    if (!file) {
      std::cerr << fmt::format("cutcom: cannot open program '{}': {}\n", o.program, std::strerror(errno));
      return kBadInput;
    }
    in = &file;
  }
  std::unique_ptr<OutputFile> out_file;
  std::ostream* out = &std::cout;
  if (!o.output.empty() && o.output != "-") {
    out_file = std::make_unique<OutputFile>(o.output);
    if (!out_file->open()) {
      std::cerr << fmt::format("cutcom: cannot write '{}'\n", o.output);
      return kBadInput;
    }
    out = &out_file->stream();
  }

  bool ok = true;
  if (o.format == "svg") {
    // The picture needs the programmed contour too: the program is read twice, from the file
    // (standard input is kept in a temporary file), the picture in bounded memory.
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> spool(nullptr, std::fclose);
    std::string path = o.program;
    if (o.program == "-") {
      spool.reset(std::tmpfile());
      if (!spool) throw std::runtime_error("cannot create a temporary file for standard input");
      std::string chunk(1 << 16, '\0');
      while (std::cin.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || std::cin.gcount() > 0)
        std::fwrite(chunk.data(), 1, static_cast<std::size_t>(std::cin.gcount()), spool.get());
      std::fflush(spool.get());
      path = fmt::format("/proc/self/fd/{}", fileno(spool.get()));
    }
    cutcom::SvgPicture picture;
    {
      std::ifstream first(path);
      cutcom::ProgramReader again(first, md.initial_state());
      control.into(again);
      cutcom::Block b;
      cutcom::Plane plane = cutcom::Plane::kG17;
      try {
        while (again.next(b)) {
          if (b.state.side != cutcom::Side::kOff) plane = b.state.plane;
          picture.programmed(b);
        }
      } catch (const cutcom::InputError&) {
        // the contour up to the error is drawn; the engine's run below reports the error
      }
      picture.set_plane(plane);
    }
    std::ifstream second(path);
    cutcom::ProgramReader reader(second, md.initial_state());
    control.into(reader);
    ok = run_engine(o.engine, reader, md, picture, o);
    std::string title = fmt::format("cutcom — {} — engine {}", o.program == "-" ? "stdin" : o.program, o.engine);
    picture.write(*out, title);
    for (const auto& a : picture.alarms()) std::cerr << fmt::format("ALARM {} {}\n", a.number, a.text);
  } else if (o.format == "json") {
    cutcom::JsonWriter writer(*out, o.engine, o.trace);
    cutcom::ProgramReader reader(*in, md.initial_state());
    control.into(reader);
    ok = run_writing(writer, reader, md, o, *out);
  } else {
    cutcom::TextWriter writer(*out, o.engine, o.trace);
    cutcom::ProgramReader reader(*in, md.initial_state());
    control.into(reader);
    ok = run_writing(writer, reader, md, o, *out);
  }
  out->flush();
  if (in->bad()) throw std::runtime_error("read error on the program");
  if (out_file) out_file->commit();
  return ok ? kDone : kAlarm;
}

int list_machine_data(const std::vector<std::string>& assignments) {
  cutcom::MachineData md;
  for (const auto& a : assignments) md.set_assignment(a);
  for (const auto& d : cutcom::machine_data_catalogue())
    std::cout << fmt::format("{:<12} {:<32} = {:<6} {:<8} range {:<30} {} [{}]\n", d.id, d.name,
                             cutcom::machine_datum_value(md, d.id), d.unit, d.range, d.meaning, d.clause);
  return kDone;
}

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

// A program and its machine data (FILE.md beside it, as in tests/corpus), for --replay and --from.
struct ProgramWithData {
  std::string text, md_text;
  cutcom::MachineData md;
};
ProgramWithData read_program_with_data(const std::string& f) {
  std::ifstream in(f);
  if (!in) throw cutcom::MachineDataError(fmt::format("cannot open program '{}'", f));
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
      "supported, {} over budget, {} unexplained divergences; largest coordinate error {:.3g} mm ({:.3g} of the "
      "tolerance)\n",
      s.cases, time, s.seconds > 0 ? static_cast<double>(s.cases) / s.seconds : 0.0, agree, knife + ends_differ,
      ends_differ, unsupported, s.over_budget.size(), s.divergences.size(), s.max_error, s.max_ratio);
  for (const auto& c : s.over_budget) std::cout << "over budget: case " << c << "\n";
  for (const auto& d : s.divergences) std::cout << "unexplained divergence: " << d << "\n";
  for (const auto& r : rises) std::cout << "knife edges rose beyond noise: " << r << "\n";
  if (!o.knife_baseline.empty() && rises.empty())
    std::cout << "knife edges per clause within noise of the baseline " << o.knife_baseline << "\n";
  return s.divergences.empty() && rises.empty() ? kDone : kAlarm;
}

int list_alarms() {
  for (const cutcom::AlarmInfo& info : cutcom::alarm_catalogue()) {
    const cutcom::AlarmInfo* a = &info;
    std::cout << fmt::format("{}  {:<96} [{}]{}\n", a->number, a->text, a->clause,
                             a->number_confirmed ? "" : " (number not confirmed by the manual pages)");
  }
  return kDone;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cutcom: SINUMERIK 840D 2D tool radius compensation, exact reference and fast engine"};
  app.require_subcommand(1);
  RunOptions o;
  auto* run = app.add_subcommand("run", "compute the tool-centre path of an NC program");
  run->add_option("PROGRAM", o.program, "NC program file, - for standard input")->required();
  run->add_option("--engine", o.engine, "ref (exact) or fast (double)")->check(CLI::IsMember({"ref", "fast"}));
  run->add_option("--format", o.format, "text, json or svg")->check(CLI::IsMember({"text", "json", "svg"}));
  run->add_option("-o,--output", o.output, "write to FILE instead of standard output");
  run->add_option("--md", o.md, "machine datum NAME=VALUE, e.g. --md MD20204=0.02 (repeatable)");
  run->add_option("--md-file", o.md_files, "file of NAME=VALUE lines (repeatable)");
  run->add_option("--sysvar", o.system_values,
                  "a system variable the program reads that cutcom does not model, $NAME[index]=VALUE (a number or "
                  "\"text\"), e.g. --sysvar '$A_IN[1]=1' (repeatable)");
  run->add_flag("--trace", o.trace, "include the decision trace (text and json)");
  run->add_option("--tools", o.tool_files,
                  "tool-offset archive ($TC_DPn[t,d]=..., $TC_TP2[t]=\"NAME\" lines, TO_INI.INI style; repeatable)");
  run->add_option("--tool", o.tool_edges,
                  "one tool edge TOOL[/EDGE]=RADIUS, TOOL a number or a name: --tool 1=5 --tool \"FLAT 10\"/2=4.98 "
                  "(an end mill; after --tools, repeatable)");
  run->add_option("--offsets", o.offsets_file, "settable work offsets ($P_UIFR[n]=CTRANS(X,..,Y,..) lines)");
  run->add_option("--max-loops", o.max_loops,
                  "loop passes and backward jumps before a program counts as running away (NC-PARAM-FLOW-6)")
      ->check(CLI::PositiveNumber);
  run->add_option("--definitions", o.definition_files,
                  "global user data: a file of DEF lines (GUD, DEF.DIR/*.DEF) every program level sees (repeatable)");
  run->add_option("--args", o.arguments,
                  "run PROGRAM, a subprogram, on its own with these arguments, e.g. --args \"40, 2.5, , 1\"");
  run->add_option("--search-path", o.search_path,
                  "folder where subprograms (NAME.SPF) are looked for after the program's own (repeatable)")
      ->check(CLI::ExistingDirectory);
  std::vector<std::string> md_assignments;
  auto* md = app.add_subcommand("md", "list the machine data, their values and ranges");
  md->add_option("--md", md_assignments, "override NAME=VALUE before listing");
  auto* alarms = app.add_subcommand("alarms", "list the alarm catalogue");
  CertifyOptions co;
  auto* certify =
      app.add_subcommand("certify", "certify fast against ref on generated programs (docs/certification.md)");
  certify->add_option("--cases", co.campaign.cases, "cases in this shard (0: until --time)");
  certify->add_option("--time", co.campaign.seconds, "stop after this many seconds");
  certify
      ->add_option("--budget", co.campaign.budget,
                   "seconds one case may take (default 60; 0: no limit, all in this process); a case over "
                   "budget is recorded as over-budget, not compared")
      ->check(CLI::NonNegativeNumber);
  certify->add_option("--seed", co.campaign.seed, "campaign seed (case k is the same program in any sharding)");
  certify->add_option("--shard", co.shard, "I/N: run cases k = I, I+N, I+2N, ... of the campaign");
  certify
      ->add_option("--jobs", co.jobs,
                   "run the cases in N processes on this machine and merge them (default: one per core)")
      ->check(CLI::Range(1, 1024));
  certify->add_option("--results", co.campaign.results, "JSON lines, one per case");
  certify->add_option("--corpus", co.campaign.corpus, "directory for an unexplained divergence (tests/corpus)");
  certify->add_option("--summary", co.summary, "write the shard's summary (JSON) for --merge");
  certify->add_option("--merge", co.merge, "merge shard summaries instead of running")->expected(1, -1);
  certify->add_option("--report", co.report, "write the report (docs/certification.md) and its error histogram");
  certify->add_option("--histogram", co.histogram, "the histogram's SVG file (next to the report by default)");
  certify->add_option("--spec", co.spec, "spec directory, for the clause list of the coverage table");
  certify->add_flag("!--no-progress", co.campaign.progress, "no progress bar");
  certify->add_option("--knife-baseline", co.knife_baseline,
                      "fail when a clause's knife edges rise beyond noise over this baseline (JSON)");
  certify->add_option("--write-knife-baseline", co.write_knife_baseline,
                      "write this campaign's knife edges per clause as a baseline (JSON)");
  certify->add_option("--replay", co.replay, "judge these programs (FILE.md beside each: machine data) and stop")
      ->expected(1, -1);
  certify
      ->add_option("--from", co.from,
                   "certify fast on these programs (FILE.md beside each: machine data) and their neighbours")
      ->expected(1, -1);
  certify->add_option("--neighbours", co.neighbours, "--from: neighbours of each program (default 200)")
      ->check(CLI::Range(0L, 10'000'000L));
  certify->add_option("--show", co.show, "print the program of campaign case K (with --seed) and stop");
  // TOOL-FILE-1/2, NC-OFFSET-2, NC-PARAM-VAR-3, NC-PARAM-SUB-1: a user's programs need the control's data.
  certify->add_option("--tools", co.control.tool_files, "--replay/--from: tool-offset archive (as for run)");
  certify->add_option("--tool", co.control.tool_edges,
                      "--replay/--from: one tool edge TOOL[/EDGE]=RADIUS (as for run)");
  certify->add_option("--offsets", co.control.offsets_file, "--replay/--from: settable work offsets (as for run)");
  certify->add_option("--definitions", co.control.definition_files, "--replay/--from: global user data (as for run)");
  certify
      ->add_option("--search-path", co.control.search_path,
                   "--replay/--from: folder where subprograms are looked for after the program's own")
      ->check(CLI::ExistingDirectory);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kBadInput;
  }
  try {
    if (*run) return run_command(o);
    if (*md) return list_machine_data(md_assignments);
    if (*alarms) return list_alarms();
    if (*certify) return certify_command(co);
  } catch (const cutcom::InputError& e) {
    std::cout.flush();
    std::cerr << fmt::format("cutcom: {}: {}\n", o.program, e.what());
    return kBadInput;
  } catch (const cutcom::MachineDataError& e) {
    std::cerr << fmt::format("cutcom: machine data: {}\n", e.what());
    return kBadInput;
  } catch (const FileError& e) {
    std::cerr << fmt::format("cutcom: {}\n", e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << fmt::format("cutcom: internal error: {}\n", e.what());
    return 3;
  }
  return kBadInput;
}
