// TRC-CD-1: output held back over the MD20240 window (as ref/src/held_output.hpp; no code is
// shared). Elements and actions wait here, in path order, tagged with the traversing block they
// belong to, until the window has passed them; a bottleneck cut removes what comes after the cut
// point. Reserved once from MD20240 and MD20250: nothing is allocated per block.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

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
};

class HeldOutput {
 public:
  // What the window can hold: MD20240 + 2 traversing blocks, each with up to MD20250 blocks
  // without plane motion, each block at most three elements and its actions.
  HeldOutput(PathSink& sink, const MachineData& md) : sink_(sink) {
    std::size_t capacity = static_cast<std::size_t>(md.cutcom_maxnum_check_blocks + 2) *
                           static_cast<std::size_t>(md.cutcom_maxnum_dummy_blocks + 1) * (3 + BlockWords::kMaxAux);
    records_.reserve(capacity);
    scratch_.reserve(capacity);
  }

  void hold(const HeldRecord& r) { records_.push_back(r); }
  // Releases the records of traversing blocks before `seq`, in path order.
  void release_before(int seq) {
    std::size_t n = 0;
    for (; n < records_.size() && records_[n].seq < seq; ++n) {
      if (records_[n].is_element)
        sink_.element(records_[n].element);
      else
        sink_.action(records_[n].action);
    }
    records_.erase(records_.begin(), records_.begin() + static_cast<std::ptrdiff_t>(n));
  }
  void release_all() { release_before(std::numeric_limits<int>::max()); }

  bool empty() const { return records_.empty(); }
  std::size_t size() const { return records_.size(); }
  HeldRecord& operator[](std::size_t i) { return records_[i]; }
  const HeldRecord& operator[](std::size_t i) const { return records_[i]; }
  // The records, for a bottleneck cut (TRC-CD-4), and a reserved scratch list for the records
  // after the cut point while the cut blocks run again.
  std::vector<HeldRecord>& records() { return records_; }
  std::vector<HeldRecord>& scratch() { return scratch_; }

 private:
  PathSink& sink_;
  std::vector<HeldRecord> records_, scratch_;
};

}  // namespace cutcom::fast
