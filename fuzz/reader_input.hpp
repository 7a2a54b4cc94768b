// What the reader target does with one input, shared with the test that replays fuzz/corpus under
// the sanitizers (tests/fuzz_corpus_test.cpp): the reader must read the bytes or reject them with
// an InputError naming the line (spec NC-ERR-*); any other exception, a crash or a sanitizer
// report is a finding.
#pragma once

#include <sstream>
#include <string>
#include <string_view>

#include "cutcom/reader.hpp"

namespace cutcom::fuzz {

inline void read_input(std::string_view bytes) {
  std::istringstream in{std::string(bytes)};
  ProgramReader reader(in);
  reader.no_subprogram_files();  // the same bytes read alike whatever folder the fuzzer runs in
  // NC-PARAM-FLOW-6's check is the same at any limit: a lower one keeps an endless loop from
  // taking the fuzzer's time. Loops grown by the fuzzer took 72 % of its time at 1,000 jumps
  // and 1,000 blocks (a tenth of the units); 100 and 250 still pass every path of a loop many
  // times and triple the executions per second under the sanitizers.
  InterpreterLimits limits;
  limits.max_backward_jumps = 100;
  reader.set_limits(limits);
  // The reader keeps no state that grows with the block count beyond what 250 blocks reach, and a
  // subprogram repeated P2000 times would otherwise take a second per execution (the limit above
  // counts jumps, not repetitions): the first 250 blocks are read, the rest not.
  constexpr int kBlocksRead = 250;
  Block b;
  try {
    for (int n = 0; n < kBlocksRead && reader.next(b); ++n) {
    }
  } catch (const InputError&) {
  }
}

}  // namespace cutcom::fuzz
