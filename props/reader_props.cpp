// Robustness of the shared reader and both engines on random and mutated programs
// (PROP-READ-1): every input either runs or is rejected with an InputError naming a line;
// never a crash, a hang, another exception, or a non-finite number in the output.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <sstream>

#include "generators.hpp"
#include "run_case.hpp"

namespace cutcom::props {
namespace {

struct Outcome {
  bool rejected = false;
  int unsupported = 0;  // line of a "not supported" rejection (TRC-UNSUP-1), reached by decisions
  int error_line = 0;
  std::string error;
  RunResult result;
};

Outcome run_text(const std::string& text, bool use_ref) {
  Outcome o;
  MachineData md;
  std::istringstream in(text);
  CollectingSink sink;
  try {
    ProgramReader reader(in, md.initial_state());
    reader.set_limits({10'000});  // random loops: stop early (NC-PARAM-FLOW-6)
    if (use_ref)
      ref::run(reader, md, sink);
    else
      fast::run(reader, md, sink);
    o.result = std::move(sink.result);
  } catch (const UnsupportedError& e) {
    o.unsupported = e.line();
    o.result = std::move(sink.result);
  } catch (const InputError& e) {
    o.rejected = true;
    o.error_line = e.line();
    o.error = e.what();
  }
  return o;
}

void check_robust(const std::string& text) {
  Outcome f = run_text(text, false);
  Outcome r = run_text(text, true);
  RC_TAG(f.rejected ? "rejected" : "accepted");
  RC_ASSERT(f.rejected == r.rejected);
  if (f.rejected) {
    RC_ASSERT(f.error_line >= 1);
    RC_ASSERT(f.error_line == r.error_line);
    return;
  }
  for (const PathElement& e : f.result.path)
    for (double v : {e.start.x, e.start.y, e.start.z, e.end.x, e.end.y, e.end.z}) RC_ASSERT(std::isfinite(v));
  // Accepted by both: they agree as PROP-DIFF-1 defines it.
  std::istringstream in(text);
  ProgramReader reader(in);
  reader.set_limits({10'000});
  std::vector<Block> blocks;
  Block b;
  try {
    while (reader.next(b)) blocks.push_back(b);
  } catch (const InputError&) {  // after a "not supported" block (TRC-UNSUP-1) that ended both runs
    RC_ASSERT(f.unsupported > 0 || r.unsupported > 0);
  }
  Verdict v = compare(r.result, f.result, Tolerance::for_program(conditioning_of(blocks)));
  if (v.kind == Verdict::Kind::kDiverge) RC_FAIL(v.explanation);
  // TRC-UNSUP-1: rejected as not supported by both at the same block, or by one after a knife edge.
  if (f.unsupported != r.unsupported && v.kind != Verdict::Kind::kKnifeEdge)
    RC_FAIL("not supported at line " + std::to_string(r.unsupported) + " (ref) / " + std::to_string(f.unsupported) +
            " (fast)");
}

rc::Gen<std::string> nc_like_text() {
  static const std::vector<std::string> tokens = {
      "N10 ", "G0 ", "G1 ", "G2 ", "G3 ", "G17 ", "G18 ", "G41 ", "G42 ", "G40 ", "G450 ", "G451 ", "G91 ", "X", "Y",
      "Z", "I", "J", "CR=", "=", "AC(", "IC(", ")", "-", ".", "0", "1", "5", "9", "12.5", "0.001", " ", "\n", "\n",
      "; c", "$TC_DP6[1,1]=", "$TC_DP15[1,1]=", "T1 ", "D1 ", "D0 ", "M30", "M8 ", "H2 ", "OFFN=", "NORM ", "KONT ",
      "F100 ", "DISR=", "DISCL=AC(", "FAD=PM(", "Q", "/", "\t", "(", "[", "]", ",", "G54", "999999999999999", "%",
      // the language of parametric programs (NC-PARAM-*)
      "R1=", "R1", "R[", "DEF REAL AA=", "DEF INT BB[3]", "AA", "BB[", "+", "*", "/", "SIN(", "SQRT(", " AND ", "<",
      "==", "\nIF ", "\nELSE\n", "\nENDIF\n", "\nWHILE ", "\nENDWHILE\n", "\nFOR R2=1 TO 3\n", "\nENDFOR\n", "\nLOOP\n",
      "\nENDLOOP\n", "\nREPEAT\n", "\nUNTIL ", " GOTOF LL", " GOTOB LL", "\nLL: ", "$P_TOOLR", "\""};
  return rc::gen::map(rc::gen::container<std::vector<std::string>>(rc::gen::elementOf(tokens)),
                      [](const std::vector<std::string>& parts) {
                        std::string s;
                        for (const auto& p : parts) s += p;
                        return s;
                      });
}

rc::Gen<std::string> mutated_program() {
  return rc::gen::exec([] {
    std::string text = to_program(*any_contour());
    if (*rc::gen::inRange(0, 3) == 0) text = to_parametric_program(text);  // NC-PARAM-*: mutated too
    int edits = *rc::gen::inRange(1, 6);
    for (int k = 0; k < edits && !text.empty(); ++k) {
      std::size_t at = static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, text.size()));
      char c = *rc::gen::elementOf(std::string("XYZGN0123456789.-=;() \n$[],ACQR*+/<:"));
      switch (*rc::gen::inRange(0, 3)) {
        case 0:
          text.erase(at, 1);
          break;
        case 1:
          text.insert(at, 1, c);
          break;
        default:
          text[at] = c;
          break;
      }
    }
    return text;
  });
}

// covers: PROP-READ-1 NC-ERR-1
RC_GTEST_PROP(Robustness, RandomTextIsRunOrRejectedWithALine, ()) { check_robust(*nc_like_text()); }

// covers: PROP-READ-1 NC-ERR-1
RC_GTEST_PROP(Robustness, MutatedProgramsAreRunOrRejectedWithALine, ()) { check_robust(*mutated_program()); }

}  // namespace
}  // namespace cutcom::props
