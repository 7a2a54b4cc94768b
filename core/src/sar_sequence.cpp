// SAR-P4-1, SAR-STOP-1, SAR-AGAIN-1, SAR-TANGENT-1: gathering the blocks of a SAR sequence.
#include "cutcom/sar_sequence.hpp"

#include "cutcom/engine.hpp"

namespace cutcom {

SarSequence::Step SarSequence::fail(int number, const Block& at) {
  alarm_ = number;
  alarm_copy_ = at;
  alarm_block_ = &alarm_copy_;
  count_ = 0;
  return Step::kAlarm;
}

SarSequence::Step SarSequence::take(const Block& b, bool moves) {
  if (count_ == 0) {
    if (!b.is_sar_block()) {
      if (moves) has_traversing_ = true, traversing_plane_ = b.state.plane;
      return Step::kPass;
    }
    if (!is_approach(b)) {
      // SAR-TANGENT-1: the retraction leaves the end tangent of the last traversing block.
      if (!has_traversing_) return fail(10744, b);
      if (traversing_plane_ != b.state.plane)
        throw UnsupportedError(b.words.line, "plane change between the contour and its SAR retraction");
      has_traversing_ = false;  // a second retraction has no contour to leave
      return Step::kRetraction;
    }
    held_[0] = b;
    count_ = 1;
    dummies_ = 0;
    // SAR-P4-1: a plane axis in the SAR block gives P4; otherwise the next traversing block does.
    p4_index_ = b.programs_plane_axis() ? 0 : -1;
    return Step::kHold;
  }
  // An approach is waiting for its direction block.
  if (b.is_sar_block()) return fail(10743, b);  // SAR-AGAIN-1
  if (b.words.stopre) return fail(10746, b);    // SAR-STOP-1
  if (p4_index_ < 0 && !moves && b.words.programs_any_axis())
    throw UnsupportedError(b.words.line, "axis motion between a SAR block and the block that gives P4");
  held_[static_cast<std::size_t>(count_++)] = b;
  if (!moves) {
    if (++dummies_ > md_.wab_maxnum_dummy_blocks) return fail(10740, b);  // SAR-P4-1
    return Step::kHold;
  }
  has_traversing_ = true, traversing_plane_ = b.state.plane;
  if (p4_index_ < 0) {
    p4_index_ = count_ - 1;
    return Step::kHold;
  }
  if (b.state.plane != held_[0].state.plane)
    throw UnsupportedError(b.words.line, "plane change between a SAR block and its direction block");
  return Step::kApproach;  // SAR-TANGENT-1: the first block moving in the plane after P4
}

SarSequence::Step SarSequence::finish() {
  if (count_ == 0) return Step::kPass;
  return fail(10744, held_[0]);  // SAR-TANGENT-1: no block defines the direction
}

}  // namespace cutcom
