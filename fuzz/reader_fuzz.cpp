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
  limits.max_backward_jumps = 2'000;
  reader.set_limits(limits);
  cutcom::Block b;
  try {
    while (reader.next(b)) {
    }
  } catch (const cutcom::InputError&) {
  }
  return 0;
}
