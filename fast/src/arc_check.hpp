// ARC-CENTRE-2 (the end point may miss the circle about the programmed centre by at most
// max(MD21000, MD21010 * radius)) and ARC-CR-1 (a CR= circle must reach its end point): decisions
// on programmed decimals, taken exactly in core and traced here by fast with their double margin.
// Used by the SAR expansion (the block that defines the direction at P4) and the compensation.
#pragma once

#include "cutcom/decision_trace.hpp"
#include "cutcom/programmed_decisions.hpp"

namespace cutcom::fast {

// False: alarm 14040 stopped the program.
inline bool arc_is_consistent(const Block& b, const MachineData& md, Trace& trace) {
  ProgrammedDecision d =
      b.centre ? circle_end_point(b, md, MarginText::kDouble) : cr_circle_reach(b, MarginText::kDouble);
  trace.decide(d, b.words.line);
  bool ok = d.branch == (b.centre ? "within" : "circle");
  if (!ok) trace.raise(14040, b.words, b.centre ? std::string_view{} : std::string_view{"ARC-CR-1"});
  return ok;
}

}  // namespace cutcom::fast
