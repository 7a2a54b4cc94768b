// libFuzzer target: bytes -> program -> both engines -> the documented comparison (PROP-DIFF-1).
// An odd first byte reads the rest as NC text; an even one seeds the campaign's generators with
// the next eight bytes (so the fuzzer also explores generated contours). An unexplained
// divergence, judged as the campaign judges a case, prints the program and traps; so does any
// exception other than the reader's rejections, a crash or a sanitizer report.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "campaign.hpp"
#include "cutcom/input_error.hpp"
#include "cutcom/reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0 || size > 4096) return 0;  // long texts only slow the exact engine down
  std::string text;
  cutcom::MachineData md;
  if (data[0] % 2 == 1) {
    text.assign(reinterpret_cast<const char*>(data + 1), size - 1);
  } else {
    std::uint64_t seed = 0;
    std::memcpy(&seed, data + 1, std::min<std::size_t>(8, size - 1));
    auto [program, md_text] = cutcom::props::campaign_case(seed, static_cast<long>(data[0] / 2));
    text = program;
    std::istringstream m(md_text);
    md.load(m, "generated");
  }
  // Judged as a campaign case (PROP-DIFF-1, PROP-BOUNDARY-1): a rejection "not supported" in one
  // engine after a knife edge is a knife edge, not a divergence.
  cutcom::props::ReplayVerdict v;
  try {
    // The comparison holds both whole paths: a loop run a million times (NC-PARAM-FLOW-6's default
    // limit) took 306 s and 2 GB; the runaway check is the same at a lower limit.
    v = cutcom::props::replay(text, md, {}, [](cutcom::ProgramReader& reader) {
      cutcom::InterpreterLimits limits;
      limits.max_backward_jumps = 2'000;
      reader.set_limits(limits);
    });
  } catch (const cutcom::InputError&) {
    return 0;  // the reader, which both engines share, rejects the text (PROP-READ-1)
  }
  if (v.verdict == "diverge") {
    std::fprintf(stderr, "unexplained divergence: %s\n%s\n", v.explanation.c_str(), text.c_str());
    __builtin_trap();
  }
  return 0;
}
