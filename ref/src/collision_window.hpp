// Stage 3, the collision window (TRC-CD-1; as fast/src/collision_window.hpp, no code is shared).
// The compensation's elements and actions wait here, in path order, tagged with the traversing
// block they belong to, until the window has passed them; a bottleneck cut (TRC-CD-4, the
// compensation's collision check) removes what comes after the cut point. What leaves goes to
// the sink, rounded, and to the exact path (exact_path.hpp), for the exact checks.
#pragma once

#include <climits>
#include <deque>
#include <iterator>
#include <optional>

#include "cutcom/machine_data.hpp"
#include "cutcom/sink.hpp"
#include "exact_path.hpp"

namespace cutcom::ref {

struct HeldRecord {
  const Block* owner = nullptr;
  int seq = 0;                         // ordinal of the owner's traversing block
  std::optional<PathElement> element;  // empty: an action
  ActionEvent action;
  ExactPath::Element exact;  // the element, exact
  bool candidate() const {   // an equidistant or transition circle (TRC-CD-1 compares them)
    return element &&
           (element->origin.kind == OriginKind::kOffset || element->origin.kind == OriginKind::kTransitionCircle);
  }
};

class CollisionWindow {
 public:
  CollisionWindow(PathSink& sink, ExactPath& path, const MachineData& md) : sink_(sink), path_(path), md_(md) {}

  // A block enters the compensation: it counts if it moves in the plane (TRC-CD-1 counts
  // traversing blocks).
  void begin_block(const Block& b) {
    if (b.moves_in_plane()) ++traversing_;
  }
  // The ordinal of the last traversing block so far: the seq of what the block puts out.
  int seq() const { return traversing_; }
  // A block is done: with the window in force (CDON, compensation active) the output of the last
  // MD20240 traversing blocks waits; otherwise everything goes out.
  void end_block(bool window_in_force) {
    release_before(window_in_force ? traversing_ + 1 - md_.cutcom_maxnum_check_blocks : INT_MAX);
  }
  void release_all() { release_before(INT_MAX); }

  void hold(HeldRecord r) { records_.push_back(std::move(r)); }
  // Releases the records of traversing blocks before `seq` (all records: seq = INT_MAX).
  void release_before(int seq) {
    while (!records_.empty() && records_.front().seq < seq) {
      HeldRecord& r = records_.front();
      if (r.element) {
        sink_.element(*r.element);
        path_.add(r.exact);
      } else {
        sink_.action(r.action);
      }
      records_.pop_front();
    }
  }
  const std::deque<HeldRecord>& records() const { return records_; }

  // TRC-CD-4: the path is cut on `record`, which now ends at `end` (and is gone if nothing is
  // left of it); the records after it leave the window and are returned in path order, for the
  // cut blocks to run again.
  std::deque<HeldRecord> cut(std::size_t record, const ExactPoint& end) {
    HeldRecord& r = records_[record];
    r.exact.end = end, r.element->end = path_.output(end);
    auto after = records_.begin() + static_cast<std::ptrdiff_t>(record) + 1;
    std::deque<HeldRecord> dropped(std::make_move_iterator(after), std::make_move_iterator(records_.end()));
    records_.erase(after, records_.end());
    if (path_.same(r.exact.start, r.exact.end)) records_.erase(records_.begin() + static_cast<std::ptrdiff_t>(record));
    return dropped;
  }

 private:
  PathSink& sink_;
  ExactPath& path_;
  const MachineData& md_;
  std::deque<HeldRecord> records_;
  int traversing_ = 0;
};

}  // namespace cutcom::ref
