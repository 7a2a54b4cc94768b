#include "cutcom/background_sink.hpp"

#include <pthread.h>

#include <type_traits>
#include <utility>

#include "cutcom/thread_time.hpp"

namespace cutcom {

BackgroundSink::BackgroundSink(PathSink& target, bool decisions) : target_(target), decisions_(decisions) {
  filling_.reserve(kBatch);
  writer_ = std::thread([this] {
    pthread_setname_np(pthread_self(), "cutcom-writer");  // profiles tell the threads apart
    write();
    writer_seconds_ = thread_cpu_seconds();
  });
}

BackgroundSink::~BackgroundSink() {
  try {
    finish();
  } catch (...) {  // a destructor must not throw
  }
}

template <class T>
void BackgroundSink::push(T&& e) {
  filling_.emplace_back(std::in_place_type<std::decay_t<T>>, std::forward<T>(e));  // built in place: one copy
  if (filling_.size() >= kBatch) hand_over();
}

void BackgroundSink::element(const PathElement& e) {
  copy_sources(e.origin.source);
  push(e);
}
void BackgroundSink::action(const ActionEvent& a) { push(a); }
void BackgroundSink::decision(const Decision& d) {
  if (decisions_) push(OwnedDecision{d, std::string(d.clause), std::string(d.branch)});
}
void BackgroundSink::alarm(const Alarm& a) {
  copy_sources(a.source);
  push(a);
}
void BackgroundSink::notice(const Notice& n) {
  copy_sources(n.source);
  push(n);
}
void BackgroundSink::sar_variables(const SarVariables& v) { push(v); }

void BackgroundSink::copy_sources(std::uint32_t up_to) {
  if (up_to < copied_ || !upstream_) return;
  std::lock_guard lock(names_mutex_);
  for (; copied_ <= up_to; ++copied_) names_.push_back(upstream_(copied_));
}

SourceNames BackgroundSink::sources() {
  return [this](std::uint32_t id) -> const std::string& {
    std::lock_guard lock(names_mutex_);
    return names_[id < names_.size() ? id : 0];
  };
}

void BackgroundSink::hand_over() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return full_.size() < kQueued || failed_; });
  if (failed_) {  // the target failed: what follows is dropped, finish() reports the error
    filling_.clear();
    return;
  }
  full_.push_back(std::move(filling_));
  if (empty_.empty()) {
    filling_ = Batch();
    filling_.reserve(kBatch);
  } else {
    filling_ = std::move(empty_.front());
    empty_.pop_front();
  }
  changed_.notify_all();
}

void BackgroundSink::write() {
  for (;;) {
    Batch batch;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return !full_.empty() || closing_; });
      if (full_.empty()) return;
      batch = std::move(full_.front());
      full_.pop_front();
    }
    try {
      for (const Event& e : batch)
        std::visit(
            [this](const auto& v) {
              using T = std::decay_t<decltype(v)>;
              if constexpr (std::is_same_v<T, PathElement>) target_.element(v);
              if constexpr (std::is_same_v<T, ActionEvent>) target_.action(v);
              if constexpr (std::is_same_v<T, OwnedDecision>) {
                Decision d = v.decision;
                d.clause = v.clause, d.branch = v.branch;
                target_.decision(d);
              }
              if constexpr (std::is_same_v<T, Alarm>) target_.alarm(v);
              if constexpr (std::is_same_v<T, Notice>) target_.notice(v);
              if constexpr (std::is_same_v<T, SarVariables>) target_.sar_variables(v);
            },
            e);
    } catch (...) {
      std::lock_guard lock(mutex_);
      error_ = std::current_exception();
      failed_ = true;
      full_.clear();
      changed_.notify_all();
      return;
    }
    batch.clear();
    std::lock_guard lock(mutex_);
    empty_.push_back(std::move(batch));
    changed_.notify_all();
  }
}

void BackgroundSink::finish() {
  if (writer_.joinable()) {
    if (!filling_.empty()) hand_over();
    {
      std::lock_guard lock(mutex_);
      closing_ = true;
      changed_.notify_all();
    }
    writer_.join();
  }
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

}  // namespace cutcom
