// Stage 3, the collision window (TRC-CD-1; as ref/src/collision_window.hpp, no code is shared).
// The compensation's elements and actions wait here, in path order, tagged with the traversing
// block they belong to, until the window has passed them; a bottleneck cut (TRC-CD-4, the
// compensation's collision check) removes what comes after the cut point. Under CDOF nothing is
// held: output goes straight to the sink. Reserved once from MD20240 and MD20250: nothing is
// allocated per block.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "bottleneck.hpp"
#include "cutcom/block.hpp"
#include "cutcom/machine_data.hpp"
#include "cutcom/sink.hpp"

namespace cutcom::fast {

struct HeldRecord {
  int seq = 0;  // the owner's traversing ordinal
  bool is_element = false;
  PathElement element;
  double radius = 0;  // arcs: radius in the plane
  ActionEvent action;
  int owner_line = 0;    // the block it belongs to, to run it again at a cut
  int owner_block = -1;  // that block's identity (BlockCopy::block)
  ContourInsert owner_insert;
  std::optional<std::int64_t> owner_number;
  PathPoint owner_start, owner_end;
  bool owner_rapid = false;
  Decimal owner_feed;
  FeedType owner_feed_type = FeedType::kG94;
  SarMove owner_sar = SarMove::kNone;
  // The collision check's box around the element in the plane of `box_axes`, kept once computed
  // (a held element meets the entries of MD20240 blocks); reset wherever the element changes.
  mutable PieceBox box;
  mutable bool boxed = false;
  mutable PlaneAxes box_axes{0, 1, 2};
};

class CollisionWindow {
 public:
  // What the window can hold: MD20240 + 2 traversing blocks, each with up to MD20250 blocks
  // without plane motion, each block at most three elements and its actions.
  CollisionWindow(PathSink& sink, const MachineData& md) : sink_(sink), md_(md) {
    std::size_t capacity = static_cast<std::size_t>(md.cutcom_maxnum_check_blocks + 2) *
                           static_cast<std::size_t>(md.cutcom_maxnum_dummy_blocks + 1) * (3 + BlockWords::kMaxAux);
    records_.reserve(capacity);
    scratch_.reserve(capacity);
  }

  // A block enters the compensation: it counts if it moves in the plane (TRC-CD-1 counts
  // traversing blocks); under CDON its output waits. `moves`: b.moves_in_plane().
  void begin_block(const Block& b, bool moves) {
    if (moves) ++traversing_;
    holding_ = b.state.collision == CollisionMode::kCdon;
  }
  // The ordinal of the last traversing block so far: the seq of what the block puts out.
  int seq() const { return traversing_; }
  // A block is done: with the window in force (CDON, compensation active) the output of the last
  // MD20240 traversing blocks waits; otherwise everything goes out.
  void end_block(bool window_in_force) {
    if (!window_in_force) return release_all();
    release_before(traversing_ + 1 - md_.cutcom_maxnum_check_blocks);
  }
  // Under CDOF with nothing held, output goes straight out (it would be released at the block's end).
  bool direct() const { return !holding_ && empty(); }

  void hold(const HeldRecord& r) {
    HeldRecord& k = hold_new();
    k = r, k.boxed = false;
  }
  // A new record at the end, to be filled in place (a record is a few hundred bytes). Records
  // past the end are kept to be filled again: a new one is not constructed per element; what a
  // filler may leave unset is reset here.
  HeldRecord& hold_new() {
    // Released records are dropped only when the reserve is full: one move of the few held then,
    // instead of one per released record.
    if (end_ == records_.capacity() && head_ > 0) {
      std::move(records_.begin() + static_cast<std::ptrdiff_t>(head_),
                records_.begin() + static_cast<std::ptrdiff_t>(end_), records_.begin());
      end_ -= head_, head_ = 0;
    }
    if (end_ == records_.size()) records_.emplace_back();
    HeldRecord& k = records_[end_++];
    k.is_element = false, k.radius = 0, k.boxed = false;
    return k;
  }
  // Releases the records of traversing blocks before `seq`, in path order.
  void release_before(int seq) {
    for (; head_ < end_ && records_[head_].seq < seq; ++head_) {
      if (records_[head_].is_element)
        sink_.element(records_[head_].element);
      else
        sink_.action(records_[head_].action);
    }
    if (head_ == end_) head_ = end_ = 0;
  }
  void release_all() { release_before(std::numeric_limits<int>::max()); }

  bool empty() const { return head_ == end_; }
  std::size_t size() const { return end_ - head_; }
  const HeldRecord& operator[](std::size_t i) const { return records_[head_ + i]; }

  // TRC-CD-4: the path is cut on `record`, which now ends at `end` (nothing is left of it when
  // `vanishes`); the records after it leave the window and are returned in path order, for the
  // cut blocks to run again (a reserved scratch list, valid until the next cut).
  const std::vector<HeldRecord>& cut(std::size_t record, const PathPoint& end, bool vanishes) {
    std::size_t at = head_ + record;
    records_[at].element.end = end, records_[at].boxed = false;
    scratch_.assign(records_.begin() + static_cast<std::ptrdiff_t>(at) + 1,
                    records_.begin() + static_cast<std::ptrdiff_t>(end_));
    end_ = vanishes ? at : at + 1;  // the cut record is the last one left, if anything is left of it
    if (head_ == end_) head_ = end_ = 0;
    return scratch_;
  }

 private:
  PathSink& sink_;
  const MachineData& md_;
  std::vector<HeldRecord> records_, scratch_;
  std::size_t head_ = 0;  // records_[0, head_) are released
  std::size_t end_ = 0;   // records_[head_, end_) are held; those after it wait to be filled again
  int traversing_ = 0;
  bool holding_ = false;  // CDON in force for the block being processed
};

}  // namespace cutcom::fast
