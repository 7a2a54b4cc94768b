#include "cutcom/read_ahead.hpp"

#include <pthread.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "cutcom/thread_time.hpp"

namespace cutcom {

ReadAhead::ReadAhead(ProgramReader& reader) : reader_(reader) {}

ReadAhead::~ReadAhead() { stop(); }

void ReadAhead::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    changed_.notify_all();
  }
  if (thread_.joinable()) thread_.join();
}

double ReadAhead::reader_cpu_seconds() {
  stop();
  return reader_seconds_;  // written by the thread before it ended (join orders it)
}

// Reads up to a batch of blocks; stops after a SAR block, at the end and at the reader's error.
void ReadAhead::fill(Batch& batch) {
  batch.count = 0, batch.stops = false, batch.last = false, batch.error = nullptr;
  batch.names.clear();
  std::uint32_t highest = 0;
  try {
    while (batch.count < kBatch) {
      Block& b = batch.blocks[batch.count];
      if (!reader_.next(b)) {
        batch.last = true;
        break;
      }
      ++batch.count;
      highest = std::max(highest, b.words.source);
      if (b.is_sar_block()) {  // SAR-END-3 may answer with a position: wait for it
        batch.stops = true;
        break;
      }
    }
  } catch (...) {
    batch.error = std::current_exception();
    batch.last = true;
  }
  for (; names_copied_ <= highest; ++names_copied_) batch.names.push_back(reader_.source_text(names_copied_));
}

void ReadAhead::read() {
  for (;;) {
    Batch batch;
    {
      std::unique_lock lock(mutex_);
      if (!empty_.empty()) batch = std::move(empty_.front()), empty_.pop_front();
    }
    if (batch.blocks.empty()) batch.blocks.resize(kBatch);  // the first few batches only
    fill(batch);
    bool stops = batch.stops, last = batch.last;
    std::unique_lock lock(mutex_);
    // Full: the reader sleeps until the engine has taken half of the queue, not one batch; each
    // wake-up costs the engine a system call and the reader a latency (on a virtual machine up to
    // hundreds of microseconds), and a reader that wakes late leaves the engine waiting.
    if (full_.size() >= kQueued) changed_.wait(lock, [this] { return full_.size() <= kLowWater || stopping_; });
    if (stopping_) return;
    full_.push_back(std::move(batch));
    changed_.notify_all();
    if (last) return;
    if (stops) {
      changed_.wait(lock, [this] { return resume_ || stopping_; });
      if (stopping_) return;
      resume_ = false;
      if (position_) reader_.set_position(*std::exchange(position_, std::nullopt));
    }
  }
}

const Block* ReadAhead::next_block() {
  if (!started_) {
    started_ = true;
    thread_ = std::thread([this] {
      pthread_setname_np(pthread_self(), "cutcom-reader");  // profiles tell the threads apart
      read();
      reader_seconds_ = thread_cpu_seconds();
    });
  }
  if (at_ < current_.count) return &current_.blocks[at_++];
  if (current_.last) {
    if (current_.error) std::rethrow_exception(current_.error);
    return nullptr;
  }
  std::unique_lock lock(mutex_);
  if (current_.stops) {  // the engine has taken the SAR block: the reader goes on
    resume_ = true;
    current_.stops = false;
    changed_.notify_all();
  }
  if (!current_.blocks.empty()) empty_.push_back(std::move(current_));  // its blocks are reused
  changed_.wait(lock, [this] { return !full_.empty(); });
  current_ = std::move(full_.front());
  full_.pop_front();
  if (full_.size() == kLowWater) changed_.notify_all();  // a reader waiting for room goes on
  lock.unlock();
  for (std::string& name : current_.names) names_.push_back(std::move(name));
  at_ = 0;
  return next_block();
}

void ReadAhead::set_position(const Point3& p) {
  // The reader waits after a SAR block only: after any other block it has read on already.
  if (!(current_.stops && at_ == current_.count))
    throw std::logic_error("SAR-END-3: a new position after a block that is not a SAR block");
  std::lock_guard lock(mutex_);
  position_ = p;
}

}  // namespace cutcom
