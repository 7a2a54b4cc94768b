// libFuzzer target: any bytes as NC text. The reader must read them or reject them with an
// InputError naming the line (spec NC-ERR-*): any other exception, a crash or a sanitizer report
// is a finding.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "cutcom/reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  cutcom::ProgramReader reader(in);
  reader.no_subprogram_files();  // the same bytes read alike whatever folder the fuzzer runs in
  // NC-PARAM-FLOW-6's check is the same at any limit: a lower one keeps an endless loop from
  // taking the fuzzer's time.
  cutcom::InterpreterLimits limits;
  limits.max_backward_jumps = 1'000;
  reader.set_limits(limits);
  // The reader keeps no state that grows with the block count beyond what 1,000 blocks reach, and a
  // subprogram repeated P2000 times would otherwise take a second per execution (the limit above
  // counts jumps, not repetitions): the first 1,000 blocks are read, the rest not.
  constexpr int kBlocksRead = 1'000;
  cutcom::Block b;
  try {
    for (int n = 0; n < kBlocksRead && reader.next(b); ++n) {
    }
  } catch (const cutcom::InputError&) {
  }
  return 0;
}
