// ARC-CENTRE-2 (the end point may miss the circle about the programmed centre by at most
// max(MD21000, MD21010 * radius)) and ARC-CR-1 (a CR= circle must reach its end point): decisions
// on programmed decimals, taken exactly in core and traced here by ref with their exact margin.
// Used by the SAR expansion (the block that defines the direction at P4) and the compensation.
#pragma once

#include "cutcom/decision_trace.hpp"
#include "cutcom/programmed_decisions.hpp"

namespace cutcom::ref::detail {

// False: alarm 14040 stopped the program.
inline bool arc_is_consistent(const Block& b, const MachineData& md, Trace& trace) {
  MarginText margin = trace.keeps_decisions() ? MarginText::kExact : MarginText::kNone;
  if (!b.centre) {  // ARC-CR-1
    ProgrammedDecision reach = cr_circle_reach(b, margin);
    trace.decide(reach, b.words.line);
    if (reach.branch != "circle") trace.raise(14040, b, "ARC-CR-1");
    return reach.branch == "circle";
  }
  ProgrammedDecision t = circle_end_point(b, md, margin);  // ARC-CENTRE-2
  trace.decide(t, b.words.line);
  if (t.branch != "within") trace.raise(14040, b);
  return t.branch == "within";
}

}  // namespace cutcom::ref::detail
