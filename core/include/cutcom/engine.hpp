// What both engines have in common: their entry point's shape and the errors they may throw.
#pragma once

#include <string>

#include "cutcom/programmed_decisions.hpp"
#include "cutcom/reader.hpp"

namespace cutcom {

// A program construct the engines do not implement yet: named with its line, never run wrongly.
class UnsupportedError : public InputError {
 public:
  UnsupportedError(int line, const std::string& what)
      : InputError(line, 1, what + " (not supported by this version of cutcom)") {}
};

// The effective radius and the edge it came from; a change while active is a D change (decision 30).
struct ActiveEdge {
  std::int64_t tool = 0, edge = 0, sum_offset = 0;  // (a DL acts on the path as a D does: TOOL-SUM-1)
  Decimal radius, wear, offn;
  std::int8_t position = 0;  // a turning tool's cutting edge position (TOOL-TURN-1)
  static ActiveEdge of(const ModalState& s) {
    return {s.tool, s.edge, s.sum_offset, s.edge_radius, s.edge_wear, s.offn, s.edge_position};
  }
  friend bool operator==(const ActiveEdge&, const ActiveEdge&) = default;
  // Whether these are the edge data in force in `s` (asked for every block while compensation is
  // active; inline, the compiler compares the fields without building the copy).
  bool in_force(const ModalState& s) const { return *this == of(s); }
};

// TRC-UNSUP-1: KONTC/KONTT need polynomial output; the block is rejected, naming it.
inline void reject_kontc_kontt(const Block& b, bool retraction) {
  if (b.state.approach == ApproachMode::kKontC || b.state.approach == ApproachMode::kKontT)
    throw UnsupportedError(b.words.line, retraction ? "KONTC/KONTT retraction (needs polynomial output)"
                                                    : "KONTC/KONTT approach (needs polynomial output)");
}

// TRC-SIDE-1, TRC-SIDE-2: while compensation is active with `side` since the G41/G42 word counted
// `selection`, a block selects anew when it is on the other side or programs G41/G42 again.
inline bool selects_anew(const ModalState& s, Side side, std::uint32_t selection) {
  return s.side != Side::kOff && (s.side != side || s.selection != selection);
}

// radius_changes' checks of a change (the edge data differ from `active`), out of line: the rare case.
[[gnu::noinline]] inline bool edge_data_change(const Block& b, const ActiveEdge& active, int active_side) {
  const ModalState& s = b.state;
  ActiveEdge now = ActiveEdge::of(s);
  if (s.edge == 0 || !s.edge_defined)
    throw UnsupportedError(b.words.line, "a change to D0 or to an undefined edge while compensation is active");
  // NC-WORD-13: under a transformation the control changes tools only with G40 (JOB06 §7.10).
  if (s.tool != active.tool && s.transformation != Transformation::kOff)
    throw InputError(b.words.line, 1,
                     "a tool change with tool radius compensation G41/G42 in force under a transformation "
                     "(TRANSMIT, TRAORI): the control changes tools there only after G40");
  // The tip of a turning tool lies off its edge centre by the edge's radius (TOOL-TURN-1): a new
  // tip would shift the contour by another vector at each end of the blend.
  if ((active.position != 0 || now.position != 0) &&
      (active.position != now.position || active.radius + active.wear != now.radius + now.wear))
    throw UnsupportedError(b.words.line,
                           "a change of a turning tool's tip (its cutting edge position, radius or wear) while "
                           "compensation is active");
  CompensationSide cs = compensation_side(s);
  if (cs.s != active_side || cs.r.sign() <= 0)
    throw UnsupportedError(b.words.line,
                           "a D, DL or OFFN change that swaps the side or makes the radius 0 while compensation is "
                           "active (select anew with G41/G42)");
  return true;
}

// TRC-UNSUP-1: what a block on the active side may not do while compensation is selected
// (decision 30): change the tool edge, or ask for KONTC/KONTT.
// TRC-RADIUS-3: the edge data in force changed while compensation is active, without a new
// selection: a T, D, DL or OFFN change (or the edge's data), to an edge that is
// defined, on the same side with a radius above 0, is blended over the next block that moves in
// the plane (each engine, at that block); anything else is not supported (TRC-UNSUP-1).
inline bool radius_changes(const Block& b, const ActiveEdge& active, int active_side) {
  return !active.in_force(b.state) && edge_data_change(b, active, active_side);
}

// True when the block changes the radius (a blend follows, TRC-RADIUS-3).
inline bool reject_change_while_active(const Block& b, const ActiveEdge& active, int active_side) {
  bool changes = radius_changes(b, active, active_side);
  reject_kontc_kontt(b, false);
  return changes;
}

}  // namespace cutcom
