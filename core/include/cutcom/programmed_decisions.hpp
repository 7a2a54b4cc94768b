// Decisions whose deciding quantity is a function of programmed decimals only (the effective
// radius, DISR, DISCL/DISRP levels, CR= and I/J/K circles): taken once, here, exactly. Both
// engines trace the branch and the margin given and keep only the geometry they must compute
// themselves, so such a decision can never part them (no knife edge of fast's own).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "cutcom/block.hpp"
#include "cutcom/machine_data.hpp"
#include "cutcom/sar_layout.hpp"

namespace cutcom {

// The outcome of one decision: its clause, its branch and its margin (the deciding quantity minus
// its threshold, in mm) as a double (`approx`) and, where asked for, written with an exact sign
// (`exact`; "0" for an exact tie).
struct ProgrammedDecision {
  std::string_view clause;
  std::string_view branch;
  bool has_margin = false;
  std::string exact;
  double approx = 0;
};

// Whether a decision's margin is also written exactly (ref's trace) or only as a double (fast's:
// the circle checks of every arc are then decided in double under a proven error bound, exactly
// only near their threshold, so that fast allocates nothing per block). kNone: decided exactly
// with no margin at all, where no trace keeps it (ref's run without --trace).
enum class MarginText { kExact, kDouble, kNone };

// TRC-RADIUS-2: the side the tool runs on from G41/G42 and the sign of the effective radius
// (TRC-RADIUS-1); a negative radius swaps the side, its magnitude is the radius compensated.
struct CompensationSide {
  int s = 1;          // +1 left of the direction of travel, -1 right
  Decimal effective;  // $TC_DP6 + $TC_DP15 + OFFN
  Decimal r;          // |effective|
  ProgrammedDecision decision;
};
CompensationSide compensation_side(const ModalState& state);  // state.side must be G41 or G42

// SAR-DISR-1/2: the length of a SAR line (DISR + r) or the radius of a SAR circle's tool-centre
// path (DISR ± r), from DISR and the compensation in force (`trc`: none without it) on the SAR
// side `sar_side`. Empty `size`: alarm 10742 under `decision.clause`.
struct SarSize {
  std::optional<Decimal> size;
  ProgrammedDecision decision;
};
SarSize sar_size(const Block& sar, const std::optional<CompensationSide>& trc, int sar_side);

// SAR-DISRP-2 and SAR-DISCL-3 on the levels of P1, P2, P4: the retraction plane on the side of P2
// (else alarm 10748), then the direction-reversal check with MD20204 (P2 clamped within it, else
// alarm 10741). `h.h2` is clamped in place; `alarm` is 0 when the sequence may run.
struct SarLevelCheck {
  std::optional<ProgrammedDecision> retraction_plane;  // SAR-DISRP-2, when DISRP and DISCL are programmed
  std::optional<ProgrammedDecision> reversal;          // SAR-DISCL-3, unless SAR-DISRP-2 raised
  int alarm = 0;
};
SarLevelCheck check_sar_levels(const Block& sar, SarLevels& h, const MachineData& md);

// ARC-CR-1: a CR= circle reaches its end point when 0 < chord <= 2|CR|; margin 2|CR| - chord.
ProgrammedDecision cr_circle_reach(const Block& b, MarginText text);
// ARC-CENTRE-2: start and end lie on one circle about the programmed centre within
// max(MD21000, MD21010 x start radius); margin |end radius - start radius| - tolerance.
ProgrammedDecision circle_end_point(const Block& b, const MachineData& md, MarginText text);
// TRC-ARC-EQ-1 on programmed decimals: the sign of rho - r, rho the radius of the circle block `b`
// as the engines take it (|CR|, or the distance of the start from the centre corrected onto the
// chord's bisector by ARC-CENTRE-1), r >= 0. Empty when b has neither centre nor CR.
std::optional<int> circle_radius_sign(const Block& b, const Decimal& r);
// The same from the circle's plane components in units of 10^-9 mm: the chord e - s and the
// programmed centre less s (by_centre), or CR.
struct ProgrammedCircle {
  std::array<Int128, 2> chord{}, to_centre{};
  bool by_centre = true;
  Int128 cr = 0;
};
int circle_radius_sign(const ProgrammedCircle& c, Int128 r_units);

}  // namespace cutcom
