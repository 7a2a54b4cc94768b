// ref's pipeline (docs/architecture.md): the stages in the order a block passes them, each
// owning its state; the trace is their shared channel for decisions and alarms.
//   reader → SAR expansion (sar.cpp) → compensation (compensation.cpp, ends.cpp, collision.cpp)
//          → collision window (collision_window.hpp) → sink and the exact path
#include "cutcom/ref/engine.hpp"

#include "collision_window.hpp"
#include "compensation.hpp"
#include "cutcom/decision_trace.hpp"
#include "sar.hpp"

namespace cutcom::ref {

namespace {

class Pipeline {
 public:
  Pipeline(const MachineData& md, PathSink& sink, ExactPath& path)
      : sink_(sink),
        trace_(sink, Trace::Margins::kExact),
        window_(sink, path, md),
        compensation_(md, sink, trace_, window_, path),
        sar_(md, sink, trace_, path, compensation_) {
    // ALARM-1: before an alarm, the approach decided so far and everything held back go out.
    trace_.set_before_alarm([this] {
      compensation_.flush_approach();
      window_.release_all();
    });
  }

  // Blocks are read one by one, as a control reads them.
  bool run(BlockSource& blocks) {
    while (!trace_.stopped()) {
      const Block* read = blocks.next_block();
      if (!read) break;
      const Block& b = *read;
      if (!b.notice.empty()) sink_.notice({b.words.line, b.notice_clause, b.notice, b.words.source});  // the reader's
      sar_.take(b);
      if (auto p = sar_.take_reposition()) blocks.set_position(*p);  // SAR-END-1/3
    }
    // NC-ERR-2: a reading error anywhere rejects the program, even after an alarm.
    while (trace_.stopped() && blocks.next_block()) {
    }
    sar_.finish();
    if (!trace_.stopped()) compensation_.end_of_program();
    window_.release_all();
    return !trace_.stopped();
  }

 private:
  PathSink& sink_;
  Trace trace_;
  CollisionWindow window_;
  detail::Compensation compensation_;
  detail::SarExpansion sar_;
};

}  // namespace

bool run_exact(BlockSource& blocks, const MachineData& md, PathSink& sink, ExactPath& path) {
  return Pipeline(md, sink, path).run(blocks);
}

bool run(BlockSource& blocks, const MachineData& md, PathSink& sink, ExactCheckReport* checks) {
  ExactPath path;
  path.keep_elements(checks != nullptr);
  bool ok = Pipeline(md, sink, path).run(blocks);
  if (checks) path.check(*checks);
  return ok;
}

}  // namespace cutcom::ref
