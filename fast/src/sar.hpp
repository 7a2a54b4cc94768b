// Stage 1, the SAR expansion (spec sar.md; as ref/src/sar.hpp, no code is shared): programmed
// blocks in, blocks out to the compensation. A SAR block and the blocks up to P4 are gathered
// (core: SarSequence) and leave as sub-blocks that run through the compensation as if programmed
// (SAR-TRC-1); their in-plane points at P3 are doubles handed on beside the block
// (PlaneOverride). Every other block passes unchanged. ref decides the same clauses exactly.
#pragma once

#include <optional>
#include <span>

#include "block_copy.hpp"
#include "compensation.hpp"
#include "cutcom/decision_trace.hpp"
#include "cutcom/programmed_decisions.hpp"
#include "cutcom/sar_layout.hpp"
#include "cutcom/sar_sequence.hpp"
#include "sar_shape.hpp"

namespace cutcom::fast {

class SarExpansion {
 public:
  SarExpansion(const MachineData& md, PathSink& sink, Trace& trace, Compensation& next)
      : md_(md), sink_(sink), trace_(trace), next_(next), sequence_(md) {}

  // A programmed block: through the SAR sequence (SAR-P4-1 ...), then on to the compensation.
  void take(const Block& b);
  // The program's end: a SAR block still waiting for its P4 (SAR-TANGENT-1).
  void finish();
  // SAR-END-1/3: where the reader's next block starts after a retraction (once), if not where
  // the reader thinks.
  std::optional<Point3> take_reposition() { return std::exchange(reposition_, std::nullopt); }

 private:
  // Hands a block on; keeps the last programmed block moving in the plane (SAR-TANGENT-1).
  void forward(const Block& b, const PlaneOverride* o = nullptr) { forward(b, o, b.moves_in_plane()); }
  void forward(const Block& b, const PlaneOverride* o, bool moves);  // moves: b.moves_in_plane()
  void approach(std::span<const Block> gathered, int p4_index);
  void retraction(const Block& block);
  // The compensation in force at a SAR block, side and radius as decided in core (empty: none).
  using SarTrc = std::optional<CompensationSide>;
  static SarTrc sar_trc(const ModalState& st);
  // SAR-SIDE-1/2/3: the side of a circle; 0 after an alarm.
  int sar_side(const Block& b, const SarTrc& trc, Vec2 t, Vec2 p4, const std::optional<Vec2>& p0);
  // SAR-DISR-1/2: L or R; false after an alarm.
  bool sar_size(const Block& b, const SarTrc& trc, int sd, double& size);
  // SAR-DISCL-1..3, SAR-DISRP-1/2, SAR-SEG-1/2: the levels; false after an alarm.
  bool sar_levels(const Block& b, SarLevels& h, SarEndCase end_case, const Decimal& h4);
  // Hands on the sub-blocks with their points.
  void push_sub_blocks(const SarShape& shape, const std::optional<Vec2>& tool_centre);

  const MachineData& md_;
  PathSink& sink_;
  Trace& trace_;
  Compensation& next_;
  SarSequence sequence_;
  SarSubBlocks subs_;  // reused: nothing allocated per SAR block
  // The last programmed block moving in the plane, as run (SAR-TANGENT-1 at a retraction): only
  // what element_in reads of its BlockCopy, its geometry, since a whole Block (its words, actions
  // and modal state) or a BlockCopy per block would cost more than the reader (converted only at
  // a retraction).
  Block last_contour_;
  void keep_last_contour(const Block& b);
  PlaneOverride last_contour_over_;
  PlaneOverride end_over_;  // SAR-END-3's points for the block being taken (built only after such a retraction)
  bool last_contour_overridden_ = false;
  bool has_last_contour_ = false;
  bool at_sar_end_ = false;  // SAR-END-3: the tool stands at sar_end_ (in the plane)
  Vec2 sar_end_;
  Plane sar_end_plane_ = Plane::kG17;
  std::optional<Point3> reposition_;  // for the reader (SAR-END-1/3)
};

}  // namespace cutcom::fast
