// Test helpers: a program text read into blocks, or run through both engines.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "cutcom/fast/engine.hpp"
#include "cutcom/machine_data.hpp"
#include "cutcom/reader.hpp"
#include "cutcom/ref/engine.hpp"
#include "cutcom/sink.hpp"

namespace cutcom::testing {

inline std::vector<Block> read_blocks(const std::string& text, ModalState initial = {},
                                      const OffsetTable* offsets = nullptr) {
  std::istringstream in(text);
  ProgramReader r(in, initial);
  if (offsets) r.offsets() = *offsets;
  std::vector<Block> out;
  Block b;
  while (r.next(b)) out.push_back(b);
  return out;
}

struct Both {
  RunResult fast, ref;
};
inline Both run_both(const std::string& text, const MachineData& md = {}) {
  Both r;
  for (int e = 0; e < 2; ++e) {
    std::istringstream in(text);
    ProgramReader reader(in, md.initial_state());
    CollectingSink sink;
    if (e == 0)
      fast::run(reader, md, sink);
    else
      ref::run(reader, md, sink);
    (e == 0 ? r.fast : r.ref) = sink.result;
  }
  return r;
}

}  // namespace cutcom::testing
