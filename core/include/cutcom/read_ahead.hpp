// The reader on a thread of its own (issue "Performance": reading took about 40 % of the engine
// thread's time). It reads batches of blocks ahead of the engine, in order, in bounded memory, and
// hands on the reader's InputError where the reader would have thrown it.
//
// The one message back from an engine to the reader, SAR-END-3's new position after a SAR
// retraction without end point, must reach the reader before it reads the next block: the reader
// therefore stops after every SAR block (SAR-BLOCK-1) until the engine has taken it and asked for
// the next one, and a position given after any other block is a logic error.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cutcom/block_source.hpp"
#include "cutcom/reader.hpp"

namespace cutcom {

class ReadAhead final : public BlockSource {
 public:
  // `reader` is read on the second thread from the first next_block() on, and must not be used
  // otherwise until this object is gone.
  explicit ReadAhead(ProgramReader& reader);
  ~ReadAhead() override;  // stops the reader where it is
  ReadAhead(const ReadAhead&) = delete;
  ReadAhead& operator=(const ReadAhead&) = delete;

  const Block* next_block() override;
  void set_position(const Point3& p) override;
  // NC-PARAM-SUB-3: where a block handed out stands ("INNER.SPF line 4, …"): the reader's
  // names, copied with the blocks, read on the engine's thread.
  const std::string& source_text(std::uint32_t id) const { return names_[id < names_.size() ? id : 0]; }
  // The processor time the reader's thread used (cutcom run --stage-times); stops the reader
  // where it is, so only once the engine is done.
  double reader_cpu_seconds();

 private:
  static constexpr std::size_t kBatch = 256;             // blocks handed over at once
  static constexpr std::size_t kQueued = 4;              // batches read ahead at most: the memory bound (2.8 MB)
  static constexpr std::size_t kLowWater = kQueued / 2;  // a full queue wakes the reader again here
  struct Batch {
    std::vector<Block> blocks;  // kBatch of them once used; reused, so their text keeps its room
    std::size_t count = 0;
    bool stops = false;              // ends with a SAR block: the reader waits for the engine
    bool last = false;               // the program's end or the reader's error follows
    std::exception_ptr error;        // the reader's, to be thrown after the blocks before it
    std::vector<std::string> names;  // source names new with these blocks
  };

  void read();  // the second thread
  void fill(Batch& batch);
  void stop();  // the reader stops where it is; its thread has ended when this returns

  ProgramReader& reader_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Batch> full_, empty_;
  bool stopping_ = false, resume_ = false;
  double reader_seconds_ = 0;       // the reader thread's processor time, written as it ends
  std::optional<Point3> position_;  // SAR-END-3, for the reader when it resumes
  std::uint32_t names_copied_ = 1;  // on the reader's thread
  // The engine's side.
  Batch current_;
  std::size_t at_ = 0;
  bool started_ = false;
  std::deque<std::string> names_{""};
};

}  // namespace cutcom
