// The sub-blocks of a smooth approach or retraction (spec SAR-SUB-1, SAR-FEED-1/2, SAR-ACTION-1,
// SAR-TRC-1, SAR-END-1/2), in the block model's terms. No geometry: each engine decides the
// points (exactly or in double) and passes the outcome here; the in-plane position of P3 enters
// only as a rounded picture, which the engines replace by their own value (Block::sar).
#pragma once

#include <array>

#include "cutcom/block.hpp"

namespace cutcom {

// SAR-END-1: what a retraction block programs decides where the retraction ends.
enum class SarEndCase : std::uint8_t {
  kApproach,
  kNoAxis,         // case 1: ends at P2 (P1 if they coincide)
  kApplicateOnly,  // case 2: ends at P1
  kPlaneAxis,      // case 3: ends at the programmed P0
};
SarEndCase sar_end_case(const Block& sar);

// The applicates (heights above the plane along the applicate axis) of P0 ... P4.
struct SarLevels {
  Decimal h0, h1, h2, h3, h4;
};

// SAR-DISCL-1/2, SAR-DISRP-1, SAR-END-1: the levels as programmed (decimal arithmetic, exact),
// before the direction-reversal check of SAR-DISCL-3, which each engine decides; h3 is set by
// set_p3_level once h2 is final. Throws UnsupportedError for DISRP on a retraction that ends at
// P1 or P2.
SarLevels sar_levels(const Block& sar, SarEndCase end_case, const Decimal& h4);
// SAR-SEG-1 / SAR-SEG-2: P3 at the level of P2 (G340) or of P4 (G341).
inline void set_p3_level(const Block& sar, SarLevels& h) {
  h.h3 = sar.state.sar_segmentation == SarSegmentation::kG340 ? h.h2 : h.h4;
}

// SAR-END-3: a block after a retraction that ended without end point (the tool off the decimal
// grid). True: it keeps the position in the plane; false: it leaves it (both plane axes
// absolute, straight). Throws UnsupportedError for anything else.
bool keeps_sar_end(const Block& b, Plane plane);

struct SarPlan {
  bool approach = true;
  SarEndCase end_case = SarEndCase::kApproach;
  SarLevels h;
  Point3 p0, p4;            // approach: P0 = the SAR block's start; retraction (case 3): its end
  Decimal p3_a, p3_b;       // rounded picture of P3 in the plane (abscissa, ordinate)
  Decimal tc_a, tc_b;       // SAR-END-2: rounded picture of the tool centre at P1
  bool lead_moves = false;  // P0 and P1 differ in the plane (decided by the engine)
  int sense = 0;            // the element: 0 straight, +1 counter-clockwise, -1 clockwise
};

struct SarSubBlocks {
  static constexpr int kMax = 5;
  std::array<Block, kMax> blocks{};
  int count = 0;
  bool element_in_p4_block = false;  // approach: the element is `p4_element`, run in that block
  Block p4_element;
};

// Builds the sub-blocks of `sar` (the SAR block) for `plan`; `p4_block` is the approach block
// that supplies P4 (the SAR block itself, or a later block, SAR-P4-2).
void sar_sub_blocks(const Block& sar, const Block& p4_block, const SarPlan& plan, SarSubBlocks& out);

// The picture of an exact in-plane position: nearest units of 10^-9 mm.
Decimal nearest_decimal(double units);

}  // namespace cutcom
