// fast: the optimized double-precision TRC engine. Streaming: blocks are pushed one by one and
// the path leaves through the sink as soon as it is fixed; the look-ahead buffer has a fixed
// capacity (MachineData limits), so memory is bounded whatever the program length.
#pragma once

#include <memory>
#include <optional>

#include "cutcom/block_source.hpp"
#include "cutcom/engine.hpp"
#include "cutcom/machine_data.hpp"
#include "cutcom/sink.hpp"

namespace cutcom::fast {

class Engine {
 public:
  Engine(const MachineData& md, PathSink& sink);
  ~Engine();
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  // Feeds the next block; throws UnsupportedError for constructs not implemented yet.
  void push(const Block& block);
  // Ends the program: flushes what is still pending.
  void finish();
  // An alarm stopped the program; further blocks are ignored.
  bool stopped() const;
  // SAR-END-3: after a SAR retraction without end point, where blocks read next start (the
  // caller's BlockSource::set_position); empty otherwise.
  std::optional<Point3> take_reposition();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Reads the whole program from `blocks` (the reader) through the engine. Returns false if an alarm stopped it.
bool run(BlockSource& blocks, const MachineData& md, PathSink& sink);

}  // namespace cutcom::fast
