// fast's pipeline (docs/architecture.md): the stages in the order a block passes them, each
// owning its state; the trace is their shared channel for decisions and alarms.
//   reader → SAR expansion (sar.cpp) → compensation (compensation.cpp, ends.cpp, collision.cpp)
//          → collision window (collision_window.hpp) → sink
#include "cutcom/fast/engine.hpp"

#include "collision_window.hpp"
#include "compensation.hpp"
#include "cutcom/decision_trace.hpp"
#include "sar.hpp"

namespace cutcom::fast {

struct Engine::State {
  State(const MachineData& md, PathSink& out)
      : sink(out),
        trace(out, Trace::Margins::kDouble),
        window(out, md),
        compensation(md, out, trace, window),
        sar(md, out, trace, compensation) {
    // ALARM-1: before an alarm, the approach decided so far and everything held back go out.
    trace.set_before_alarm([this] {
      compensation.flush_approach();
      window.release_all();
    });
  }
  PathSink& sink;
  Trace trace;
  CollisionWindow window;
  Compensation compensation;
  SarExpansion sar;
};

Engine::Engine(const MachineData& md, PathSink& sink) : state_(std::make_unique<State>(md, sink)) {}
Engine::~Engine() = default;

bool Engine::stopped() const { return state_->trace.stopped(); }

void Engine::push(const Block& b) {
  if (stopped()) return;
  if (!b.notice.empty())
    state_->sink.notice({b.words.line, b.notice_clause, b.notice, b.words.source});  // the reader's
  state_->sar.take(b);
}

void Engine::finish() {
  State& st = *state_;
  st.sar.finish();
  if (!st.trace.stopped()) st.compensation.end_of_program();
  st.window.release_all();
}

std::optional<Point3> Engine::take_reposition() { return state_->sar.take_reposition(); }

bool run(BlockSource& blocks, const MachineData& md, PathSink& sink) {
  Engine engine(md, sink);
  while (!engine.stopped()) {
    const Block* b = blocks.next_block();
    if (!b) break;
    engine.push(*b);
    if (auto p = engine.take_reposition()) blocks.set_position(*p);  // SAR-END-3
  }
  // NC-ERR-2: a reading error anywhere rejects the program, even after an alarm.
  while (engine.stopped() && blocks.next_block()) {
  }
  engine.finish();
  return !engine.stopped();
}

}  // namespace cutcom::fast
