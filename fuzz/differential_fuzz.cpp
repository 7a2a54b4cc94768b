// libFuzzer target: bytes -> program -> both engines -> the documented comparison (PROP-DIFF-1).
// An odd first byte reads the rest as NC text; an even one seeds the campaign's generators with
// the next eight bytes (so the fuzzer also explores generated contours). An unexplained
// divergence prints the program and traps; so does any exception other than the documented
// rejections, a crash or a sanitizer report.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "campaign.hpp"
#include "compare.hpp"
#include "cutcom/fast/engine.hpp"
#include "cutcom/ref/engine.hpp"

namespace {

bool run(bool use_ref, const std::string& text, const cutcom::MachineData& md, cutcom::CollectingSink& sink) {
  std::istringstream in(text);
  cutcom::ProgramReader reader(in, md.initial_state());
  return use_ref ? cutcom::ref::run(reader, md, sink) : cutcom::fast::run(reader, md, sink);
}

}  // namespace

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
  cutcom::CollectingSink r, f;
  int ref_rejected = 0, fast_rejected = 0;
  try {
    run(true, text, md, r);
  } catch (const cutcom::InputError& e) {
    ref_rejected = e.line();
  }
  try {
    run(false, text, md, f);
  } catch (const cutcom::InputError& e) {
    fast_rejected = e.line();
  }
  if (ref_rejected || fast_rejected) {
    if (ref_rejected != fast_rejected) {
      std::fprintf(stderr, "rejected at line %d (ref) / %d (fast):\n%s\n", ref_rejected, fast_rejected, text.c_str());
      __builtin_trap();
    }
    return 0;
  }
  std::istringstream in(text);
  cutcom::ProgramReader reader(in, md.initial_state());
  std::vector<cutcom::Block> blocks;
  cutcom::Block b;
  while (reader.next(b)) blocks.push_back(b);
  auto tol = cutcom::props::Tolerance::for_program(cutcom::props::conditioning_of(blocks, md.cutcom_maxnum_check_blocks));
  cutcom::props::Verdict v = cutcom::props::compare(r.result, f.result, tol);
  if (v.kind == cutcom::props::Verdict::Kind::kDiverge) {
    std::fprintf(stderr, "unexplained divergence: %s\n%s\n", v.explanation.c_str(), text.c_str());
    __builtin_trap();
  }
  return 0;
}
