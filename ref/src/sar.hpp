// Stage 1, the SAR expansion (spec sar.md; as fast/src/sar.hpp, no code is shared): programmed
// blocks in, blocks out to the compensation. A SAR block and the blocks up to P4 are gathered
// (core: SarSequence) and leave as sub-blocks that run through the compensation as if programmed
// (SAR-TRC-1); their points are exact and handed on beside the block (PlaneOverride): P3 has one
// square root (the unit tangent), the applicates are decimals. Every other block passes unchanged.
#pragma once

#include <optional>
#include <span>

#include "compensation.hpp"
#include "cutcom/decision_trace.hpp"
#include "cutcom/programmed_decisions.hpp"
#include "cutcom/sar_layout.hpp"
#include "cutcom/sar_sequence.hpp"
#include "plane_override.hpp"

namespace cutcom::ref::detail {

class SarExpansion {
 public:
  SarExpansion(const MachineData& md, PathSink& sink, Trace& trace, const ExactPath& path, Compensation& next)
      : md_(md), sink_(sink), trace_(trace), path_(path), next_(next), sequence_(md) {}

  // A programmed block: through the SAR sequence (SAR-P4-1 ...), then on to the compensation.
  void take(const Block& b);
  // The program's end: a SAR block still waiting for its P4 (SAR-TANGENT-1).
  void finish();
  // SAR-END-1/3: where the reader's next block starts after a retraction (once), if not where
  // the reader thinks.
  std::optional<Point3> take_reposition() { return std::exchange(reposition_, std::nullopt); }

 private:
  // Hands a block on; keeps the last programmed block moving in the plane (SAR-TANGENT-1).
  void forward(const Block& b, const std::optional<PlaneOverride>& over = std::nullopt);
  // SAR-POINTS-1, SAR-SIDE-*, SAR-DISR-*, SAR-DISCL-*, SAR-SUB-1 ...: expands an approach.
  void approach(std::span<const Block> gathered, int p4_index);
  // SAR-POINTS-2, SAR-END-*: expands a retraction after the contour's last block.
  void retraction(const Block& r);
  // The compensation in force at a SAR block, side and radius as decided in core (empty: none).
  using SarTrc = std::optional<CompensationSide>;
  static SarTrc sar_trc(const ModalState& state);
  // SAR-SIDE-1/2/3: the side of a circle; 0 after an alarm.
  int sar_side(const Block& b, const SarTrc& trc, const Vector& t, const Point& p4, const std::optional<Point>& p0);
  // SAR-DISR-1/2: L or R in units; empty after an alarm.
  std::optional<FT> sar_size(const Block& b, const SarTrc& trc, int s);
  // SAR-DISCL-1..3, SAR-DISRP-1/2, SAR-SEG-1/2: the levels; false after an alarm.
  bool sar_levels(const Block& b, SarLevels& h, SarEndCase end_case, const Decimal& h4);
  // Hands on the sub-blocks with their exact points.
  void push_sub_blocks(const SarSubBlocks& subs, const SarShape& shape, const std::optional<Point>& tool_centre);
  // SAR-END-3: a programmed block after a retraction that ended without end point starts there.
  std::optional<PlaneOverride> after_sar_end(const Block& b);

  const MachineData& md_;
  PathSink& sink_;
  Trace& trace_;
  const ExactPath& path_;  // rounds $P_APR/$P_AEP as the output does
  Compensation& next_;
  SarSequence sequence_;
  // The last programmed block moving in the plane and its points, as run (SAR-TANGENT-1).
  std::optional<Block> last_contour_;
  std::optional<PlaneOverride> last_contour_over_;
  struct SarEnd {
    Point at;
    Plane plane;
  };
  std::optional<SarEnd> sar_end_;     // SAR-END-3
  std::optional<Point3> reposition_;  // for the reader (SAR-END-1/3)
};

}  // namespace cutcom::ref::detail
