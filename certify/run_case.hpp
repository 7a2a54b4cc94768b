// Running a generated case through both engines.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <sstream>

#include "compare.hpp"
#include "contour_case.hpp"
#include "cutcom/fast/engine.hpp"
#include "cutcom/ref/engine.hpp"

namespace cutcom::props {

struct CaseRuns {
  RunResult ref, fast;
  int ref_unsupported = 0, fast_unsupported = 0;  // line of a "not supported" rejection (TRC-UNSUP-1)
  ref::ExactCheckReport exact;
  Tolerance tolerance;
  std::optional<std::string> untraced;  // PROP-TRACE-1: how fast (or ref) without its trace differs
};

// A sink as `cutcom run` without --trace has: it keeps no decisions.
class UntracedSink : public CollectingSink {
 public:
  bool keeps_decisions() const override { return false; }
};

inline MachineData machine_data_of(const ContourCase& c) {
  MachineData md;
  md.set("MD20210", std::to_string(c.md20210));
  md.set("MD20230", std::to_string(c.md20230));
  md.set("MD20240", std::to_string(c.md20240));
  md.set("MD20250", std::to_string(c.md20250));
  return md;
}

// The control's data a user's program needs (tool table, offsets, GUD, subprogram folders): set
// on each reader after the default below. Empty for generated cases.
using ReaderSetup = std::function<void(ProgramReader&)>;

// Subprograms of a program given as text are looked for in `folder` only (none: no file is one).
inline void look_for_subprograms(ProgramReader& reader, const std::string& folder, const ReaderSetup& setup = {}) {
  if (folder.empty())
    reader.no_subprogram_files();
  else
    reader.set_search_path({folder});
  if (setup) setup(reader);
}

// One engine ("ref" or "fast") on one program, into `sink`; the line of a "not supported"
// rejection, or 0. `checks`: ref's exact checks, where asked for.
inline int run_engine(std::string_view engine, const std::string& text, const MachineData& md,
                      const std::string& folder, const ReaderSetup& setup, CollectingSink& sink,
                      ref::ExactCheckReport* checks = nullptr) {
  std::istringstream in(text);
  ProgramReader reader(in, md.initial_state());
  look_for_subprograms(reader, folder, setup);
  try {
    if (engine == "ref")
      ref::run(reader, md, sink, checks);
    else
      fast::run(reader, md, sink);
  } catch (const UnsupportedError& e) {
    return e.line();
  }
  return 0;
}

// PROP-TRACE-1: the engine run again without its trace, against its traced run.
inline std::optional<std::string> untraced_run_difference(std::string_view engine, const std::string& text,
                                                          const MachineData& md, const std::string& folder,
                                                          const ReaderSetup& setup, const RunResult& traced,
                                                          int traced_unsupported) {
  UntracedSink untraced;
  int unsupported = run_engine(engine, text, md, folder, setup, untraced);
  if (std::optional<std::string> d = untraced_difference(traced, untraced.result, engine)) return d;
  if (unsupported == traced_unsupported) return std::nullopt;
  return fmt::format("{} without its trace: not supported at line {}, with it at line {}", engine, unsupported,
                     traced_unsupported);
}

// Both engines on one program text, and the tolerance read off it.
inline CaseRuns run_program(const std::string& text, const MachineData& md, bool exact_checks = false,
                            const std::string& folder = {}, const ReaderSetup& setup = {}) {
  CaseRuns out;
  {
    CollectingSink sink;
    out.ref_unsupported = run_engine("ref", text, md, folder, setup, sink, exact_checks ? &out.exact : nullptr);
    out.ref = std::move(sink.result);
  }
  // PROP-TRACE-1 for ref: without margins its collision check passes over pieces whose certified
  // boxes are apart and locates crossings without their slack: only where it compared pieces,
  // which its trace shows as TRC-CD-3 or TRC-CD-5 decisions.
  bool compared_pieces = std::any_of(out.ref.decisions.begin(), out.ref.decisions.end(), [](const Decision& d) {
    return d.clause == "TRC-CD-3" || d.clause == "TRC-CD-5";
  });
  if (compared_pieces)
    out.untraced = untraced_run_difference("ref", text, md, folder, setup, out.ref, out.ref_unsupported);
  {
    CollectingSink sink;
    out.fast_unsupported = run_engine("fast", text, md, folder, setup, sink);
    out.fast = std::move(sink.result);
  }
  if (!out.untraced)
    out.untraced = untraced_run_difference("fast", text, md, folder, setup, out.fast, out.fast_unsupported);
  std::istringstream in(text);
  ProgramReader reader(in, md.initial_state());
  look_for_subprograms(reader, folder, setup);
  std::vector<Block> blocks;
  Block b;
  while (reader.next(b)) blocks.push_back(b);
  out.tolerance = Tolerance::for_program(conditioning_of(blocks, md.cutcom_maxnum_check_blocks, &out.ref));
  return out;
}

inline CaseRuns run_case(const ContourCase& c, bool exact_checks) {
  return run_program(to_program(c), machine_data_of(c), exact_checks);
}

}  // namespace cutcom::props
