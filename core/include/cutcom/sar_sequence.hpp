// Which blocks take part in a smooth approach or retraction (spec SAR-P4-1, SAR-STOP-1,
// SAR-AGAIN-1, SAR-TANGENT-1). No geometry: both engines use it to gather the SAR block, the
// blocks after it up to the block that defines the approach direction, and on retraction the
// last traversing block before it. Memory is bounded: at most MD20202 + 2 blocks are held.
#pragma once

#include <array>
#include <optional>
#include <span>

#include "cutcom/block.hpp"
#include "cutcom/machine_data.hpp"

namespace cutcom {

class SarSequence {
 public:
  explicit SarSequence(const MachineData& md) : md_(md) {}

  enum class Step {
    kPass,        // run the block as usual
    kHold,        // kept: an approach waits for the block that defines its direction
    kApproach,    // gathered(): the SAR block, the blocks after it, last the direction block
    kRetraction,  // the block is a SAR retraction block (the engines know their contour's last block)
    kAlarm,       // alarm() at alarm_block()
  };

  // `moves` is b.moves_in_plane(), which the engines ask once a block for all their stages.
  Step take(const Block& b, bool moves);
  // The program ends (M30 or end of text): kAlarm 10744 if an approach still waits.
  Step finish();

  std::span<const Block> gathered() const { return {held_.data(), static_cast<std::size_t>(count_)}; }
  // Index in gathered() of the block whose end point is P4 (0: the SAR block itself).
  int p4_index() const { return p4_index_; }
  int alarm() const { return alarm_; }
  const Block& alarm_block() const { return *alarm_block_; }
  // Forget what was gathered once the engine ran it.
  void release() { count_ = 0, p4_index_ = -1; }

  static bool is_approach(const Block& b) {
    auto c = *b.words.sar_contour;
    return c == SarContour::kG147 || c == SarContour::kG247 || c == SarContour::kG347;
  }

 private:
  Step fail(int number, const Block& at);

  const MachineData& md_;
  std::array<Block, MachineData::kMaxDummyBlocks + 3> held_{};
  int count_ = 0;
  int p4_index_ = -1;  // -1: P4 not known yet
  int dummies_ = 0;
  bool has_traversing_ = false;  // a programmed block moved in the plane since the last retraction
  Plane traversing_plane_ = Plane::kG17;
  int alarm_ = 0;
  const Block* alarm_block_ = nullptr;
  Block alarm_copy_;
};

}  // namespace cutcom
