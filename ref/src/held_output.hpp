// TRC-CD-1: output held back over the MD20240 window. Elements and actions wait here, in path
// order, tagged with the traversing block they belong to, until the window has passed them; a
// bottleneck cut removes what comes after the cut point.
#pragma once

#include <deque>
#include <optional>

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

class HeldOutput {
 public:
  HeldOutput(PathSink& sink, ExactPath& path) : sink_(sink), path_(path) {}
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
  std::deque<HeldRecord>& records() { return records_; }

 private:
  PathSink& sink_;
  ExactPath& path_;
  std::deque<HeldRecord> records_;
};

}  // namespace cutcom::ref
