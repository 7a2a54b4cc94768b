// `cutcom run`: one engine over one program, written as text, JSON or an SVG picture; and the
// catalogues `cutcom md` and `cutcom alarms`.
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <utility>

#include "commands.hpp"
#include "cutcom/background_sink.hpp"
#include "cutcom/fast/engine.hpp"
#include "cutcom/output.hpp"
#include "cutcom/ref/engine.hpp"
#include "cutcom/thread_time.hpp"

namespace cutcom::cli {

namespace {

// Passes everything on and keeps the numbers of the alarms raised, for a hint after the run. For
// text and JSON it sits behind the BackgroundSink, on the writer's thread: the engine's thread
// then makes one call per element, not two (the engine's thread is the run's slowest).
class AlarmWatch : public cutcom::PathSink {
 public:
  explicit AlarmWatch(cutcom::PathSink& to) : to_(to) {}
  void element(const cutcom::PathElement& e) override { to_.element(e); }
  void action(const cutcom::ActionEvent& a) override { to_.action(a); }
  void decision(const cutcom::Decision& d) override { to_.decision(d); }
  bool keeps_decisions() const override { return to_.keeps_decisions(); }
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

// --stage-times: the processor time of each thread (negative: not measured).
struct StageTimes {
  double engine = -1, writer = -1;
};

// The reader and the engine share this thread: the reader hands the engine each block where it
// wrote it. (A reader on a thread of its own ran slower: every block, 2.7 KB, crossed from one
// core to the other, and that cost more than the reading it moved off this thread; issue
// "Performance".)
bool run_engine(const std::string& engine, cutcom::ProgramReader& reader, const cutcom::MachineData& md,
                cutcom::PathSink& out, StageTimes& times) {
  double started = cutcom::thread_cpu_seconds();
  bool ok = engine == "ref" ? cutcom::ref::run(reader, md, out) : cutcom::fast::run(reader, md, out);
  times.engine = cutcom::thread_cpu_seconds() - started;
  return ok;
}

void print_stage_times(const StageTimes& t, double elapsed) {
  std::string line = "cutcom: processor time by thread:";
  for (auto [name, seconds] : {std::pair{"reader+engine", t.engine}, {"writer", t.writer}})
    if (seconds >= 0) line += fmt::format(" {} {:.3f} s,", name, seconds);
  std::cerr << line << fmt::format(" elapsed {:.3f} s\n", elapsed);
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

// The text and JSON writers: formatted on a second thread while the reader and the engine run.
template <class Writer>
bool run_writing(Writer& writer, cutcom::ProgramReader& reader, const cutcom::MachineData& md, const RunOptions& o,
                 std::ostream& out, StageTimes& times) {
  AlarmWatch watch(writer);
  cutcom::BackgroundSink background(watch, o.trace);
  background.set_upstream_sources([&reader](std::uint32_t id) -> const std::string& { return reader.source_text(id); });
  writer.set_sources(background.sources());
  bool ok = run_to_the_end(
      writer, background, [&] { return run_engine(o.engine, reader, md, background, times); }, o, out);
  times.writer = background.writer_cpu_seconds();
  hint_after(watch.numbers, o);  // the writer's thread has ended: its numbers are all there
  return ok;
}

}  // namespace

int run_command(const RunOptions& o) {
  auto started = std::chrono::steady_clock::now();
  StageTimes times;
  cutcom::MachineData md = machine_data(o);
  ControlData control = control_data(o);

  // Standard input is kept in a temporary file: a program's backward jumps and loops, the units
  // of a job archive (NC-PARAM-SUB-8) and the picture's second reading read it again.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> spool(nullptr, std::fclose);
  std::string path = o.program;
  if (o.program == "-") {
    spool.reset(std::tmpfile());
    if (!spool) throw std::runtime_error("cannot create a temporary file for standard input");
    std::string chunk(1 << 16, '\0');
    while (std::cin.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || std::cin.gcount() > 0)
      if (std::fwrite(chunk.data(), 1, static_cast<std::size_t>(std::cin.gcount()), spool.get()) !=
          static_cast<std::size_t>(std::cin.gcount()))
        throw std::runtime_error("cannot keep standard input in a temporary file (disk full?)");
    if (std::fflush(spool.get()) != 0) throw std::runtime_error("cannot keep standard input in a temporary file");
    path = fmt::format("/proc/self/fd/{}", fileno(spool.get()));
  } else if (std::filesystem::is_directory(o.program)) {
    std::cerr << fmt::format("cutcom: '{}' is a directory, not an NC program\n", o.program);
    return kBadInput;
  }
  std::ifstream file(path);
  if (!file) {
    std::cerr << fmt::format("cutcom: cannot open program '{}': {}\n", o.program, std::strerror(errno));
    return kBadInput;
  }
  std::istream* in = &file;
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
    // (standard input was kept in a temporary file), the picture in bounded memory.
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
    AlarmWatch watch(picture);
    ok = run_engine(o.engine, reader, md, watch, times);
    hint_after(watch.numbers, o);
    std::string title = fmt::format("cutcom — {} — engine {}", o.program == "-" ? "stdin" : o.program, o.engine);
    picture.write(*out, title);
    for (const auto& a : picture.alarms()) std::cerr << fmt::format("ALARM {} {}\n", a.number, a.text);
  } else if (o.format == "json") {
    cutcom::JsonWriter writer(*out, o.engine, o.trace);
    cutcom::ProgramReader reader(*in, md.initial_state());
    control.into(reader);
    ok = run_writing(writer, reader, md, o, *out, times);
  } else {
    cutcom::TextWriter writer(*out, o.engine, o.trace);
    cutcom::ProgramReader reader(*in, md.initial_state());
    control.into(reader);
    ok = run_writing(writer, reader, md, o, *out, times);
  }
  out->flush();
  if (in->bad()) throw std::runtime_error("read error on the program");
  if (out_file) out_file->commit();
  if (o.stage_times)
    print_stage_times(times, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  return ok ? kDone : kAlarm;
}

int list_machine_data(const RunOptions& o) {
  const cutcom::MachineData md = machine_data(o);
  for (const auto& d : cutcom::machine_data_catalogue())
    std::cout << fmt::format("{:<12} {:<32} = {:<6} {:<8} range {:<30} {} [{}]\n", d.id, d.name,
                             cutcom::machine_datum_value(md, d.id), d.unit, d.range, d.meaning, d.clause);
  return kDone;
}

int list_alarms() {
  for (const cutcom::AlarmInfo& info : cutcom::alarm_catalogue()) {
    const cutcom::AlarmInfo* a = &info;
    std::cout << fmt::format("{}  {:<96} [{}]{}\n", a->number, a->text, a->clause,
                             a->number_confirmed ? "" : " (number not confirmed by the manual pages)");
  }
  return kDone;
}

}  // namespace cutcom::cli
