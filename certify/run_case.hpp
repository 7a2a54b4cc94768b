// Running a generated case through both engines.
#pragma once

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
};

inline MachineData machine_data_of(const ContourCase& c) {
  MachineData md;
  md.set("MD20210", std::to_string(c.md20210));
  md.set("MD20230", std::to_string(c.md20230));
  md.set("MD20240", std::to_string(c.md20240));
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

// Both engines on one program text, and the tolerance read off it.
inline CaseRuns run_program(const std::string& text, const MachineData& md, bool exact_checks = false,
                            const std::string& folder = {}, const ReaderSetup& setup = {}) {
  CaseRuns out;
  {
    std::istringstream in(text);
    ProgramReader reader(in, md.initial_state());
    look_for_subprograms(reader, folder, setup);
    CollectingSink sink;
    try {
      ref::run(reader, md, sink, exact_checks ? &out.exact : nullptr);
    } catch (const UnsupportedError& e) {
      out.ref_unsupported = e.line();
    }
    out.ref = std::move(sink.result);
  }
  {
    std::istringstream in(text);
    ProgramReader reader(in, md.initial_state());
    look_for_subprograms(reader, folder, setup);
    CollectingSink sink;
    try {
      fast::run(reader, md, sink);
    } catch (const UnsupportedError& e) {
      out.fast_unsupported = e.line();
    }
    out.fast = std::move(sink.result);
  }
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
